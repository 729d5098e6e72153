#include "sgtllc/sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/LU>

#include "sgtllc/sim/raycast.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

constexpr double kPeriod = 0.1;     // s (10 Hz)
constexpr int kMaxFrames = 1000000;
constexpr int kPlanAttempts = 4;    // each replans a route 1.5 times longer if driving it ran out of road

const SimConfig& validated(const SimConfig& config) {
  config.validate();
  return config;
}

TrajectoryConfig trajectoryConfig(const SimConfig& config) {
  const ScenePreset preset = scenePreset(config.scene);
  TrajectoryConfig drive;
  drive.frames = config.frames;
  drive.period = kPeriod;
  drive.sensor_height = config.sensor_height;
  drive.speed_min = preset.speed_min;
  drive.speed_max = preset.speed_max;
  drive.seed = config.seed;
  return drive;
}

/// Route length the frames need: turns slow the vehicle down, so expect ~85 % of the mean cruise speed.
double expectedLength(const SimConfig& config) {
  const ScenePreset preset = scenePreset(config.scene);
  return config.frames * kPeriod * 0.85 * 0.5 * (preset.speed_min + preset.speed_max);
}

}  // namespace

void SimConfig::validate() const {
  if (frames < 1 || frames > kMaxFrames) {
    throw Error("frames must be 1.." + std::to_string(kMaxFrames) + ", not " + std::to_string(frames));
  }
  if (accumulate < 0 || accumulate > 100) throw Error("accumulate must be 0..100, not " + std::to_string(accumulate));
  if (!(label_noise >= 0.0 && label_noise <= 1.0)) {
    throw Error("label noise must be between 0 and 1, not " + std::to_string(label_noise));
  }
  if (revisits < -1 || revisits > 10000) throw Error("revisits must be 0..10000, not " + std::to_string(revisits));
  if (!(sensor_height > 0.5 && sensor_height < 5.0)) {
    throw Error("sensor height must be 0.5..5 m, not " + std::to_string(sensor_height));
  }
  if (!(sensor.max_range > sensor.min_range && sensor.min_range >= 0.0)) throw Error("sensor range limits are invalid");
  if (!(sensor.range_noise >= 0.0) || !(sensor.dropout >= 0.0 && sensor.dropout < 1.0)) {
    throw Error("sensor noise settings are invalid");
  }
  if (follow && !world_of) throw Error("follow: only a second session (world_of) follows a first one's roads");
  if (world_of) {
    if (world_of->world_of) throw Error("the first session of a second session must not be a second session itself");
    if (world_of->scene != scene) {
      throw Error(std::string("a second session drives in its first session's scene (") + sceneName(world_of->scene) +
                  "), not " + sceneName(scene));
    }
    if (world_of->seed == seed) {
      throw Error("a second session needs a seed other than its first session's (" + std::to_string(seed) +
                  "): the seed draws the traffic, the route and the noise");
    }
    world_of->validate();
  }
}

int SimConfig::scansPerFrame() const {
  if (accumulate > 0) return accumulate;
  return sensor.kind == SensorKind::kMid70 ? 10 : 1;
}

int SimConfig::plannedRevisits() const {
  if (world_of) return 0;  // a second session's route plans none (planSecondRoute)
  return revisits >= 0 ? revisits : std::max(1, static_cast<int>(std::lround(frames / 500.0)));
}

Simulator::Simulator(const SimConfig& config) : config_(validated(config)), sensor_(config_.sensor) {
  if (config.world_of) {
    driveSecondSession();
    return;
  }
  const ScenePreset preset = scenePreset(config.scene);
  const TrajectoryConfig drive = trajectoryConfig(config);
  double length = expectedLength(config);
  for (int attempt = 0; attempt < kPlanAttempts; ++attempt, length *= 1.5) {
    WorldConfig wc;
    wc.preset = preset;
    wc.seed = config.seed;
    wc.blocks_x = wc.blocks_y = blocksForRoute(preset, length);
    wc.duration = config.frames * kPeriod;
    world_ = generateWorld(wc);
    route_ = planRoute(world_.roads, length, config.plannedRevisits(), config.seed);
    poses_ = driveRoute(world_, route_, drive);
    if (numFrames() == config.frames) {
      T_world_origin_ = poses_[0].T_world_lidar;
      return;
    }
  }
  throw Error("could not plan a route long enough for " + std::to_string(config.frames) + " frames");
}

void Simulator::driveSecondSession() {
  const Simulator first(*config_.world_of);
  WorldConfig wc = first.world().config;
  wc.traffic_seed = config_.seed;
  world_ = generateWorld(wc);
  T_world_origin_ = first.T_world_origin();
  // The day after: every change of the first session (parked cars gone, trees cut back) has happened.
  world_time_offset_ = first.numFrames() * kPeriod;
  for (const FramePose& p : first.poses()) first_poses_.push_back(p.T_world_lidar);
  PriorRoute prior;
  prior.legs = first.route();
  if (config_.follow) {
    // Only the roads the first session drove to their end: its route runs on past its last frame (planRoute leaves
    // spare road).
    double driven = 0.0;
    for (size_t i = 1; i < first_poses_.size(); ++i) {
      driven += (first_poses_[i].topRightCorner<3, 1>() - first_poses_[i - 1].topRightCorner<3, 1>()).norm();
    }
    double along = 0.0;
    size_t reached = 0;
    while (reached < prior.legs.size() && along + legLength(world_.roads, prior.legs[reached]) <= driven) {
      along += legLength(world_.roads, prior.legs[reached++]);  // legs driven to their end
    }
    // A first session shorter than its first road keeps that road.
    prior.legs.resize(std::min(prior.legs.size(), std::max<size_t>(reached, 1)));
  }
  prior.start = first.poses()[0].T_world_lidar.topRightCorner<2, 1>();
  const TrajectoryConfig drive = trajectoryConfig(config_);
  double length = expectedLength(config_);
  for (int attempt = 0; attempt < kPlanAttempts; ++attempt, length *= 1.5) {
    route_ = planSecondRoute(world_.roads, length, prior, config_.seed, config_.follow);
    poses_ = driveRoute(world_, route_, drive);
    if (numFrames() == config_.frames) return;
  }
  throw Error("could not plan a second session long enough for " + std::to_string(config_.frames) + " frames");
}

int Simulator::firstScan(int i) const { return std::max(0, i - config_.scansPerFrame() + 1); }

SimScan Simulator::scan(int j) const {
  if (j < 0 || j >= numFrames()) throw Error("scan " + std::to_string(j) + " is out of range");
  const FramePose& pose = poses_[j];
  RawScan raw = castScan(world_, sensor_, pose.T_world_lidar, pose.time + world_time_offset_, j, config_.seed);
  SimScan out;
  out.labels = predictLabels(raw, config_.label_noise, config_.seed, j);
  out.true_labels = trueLabels(raw);
  out.points = std::move(raw.points);
  out.intensity = std::move(raw.intensity);
  return out;
}

SimFrame Simulator::merge(int i, const std::vector<const SimScan*>& scans) const {
  if (i < 0 || i >= numFrames()) throw Error("frame " + std::to_string(i) + " is out of range");
  const int first = firstScan(i);
  if (static_cast<int>(scans.size()) != i - first + 1) throw Error("frame " + std::to_string(i) + ": wrong scans");
  SimFrame out;
  const Eigen::Matrix4d world_to_i = poses_[i].T_world_lidar.inverse();
  for (int j = first; j <= i; ++j) {
    const SimScan& s = *scans[static_cast<size_t>(j - first)];
    const Eigen::Matrix4d T = world_to_i * poses_[j].T_world_lidar;  // scan j into frame i
    const Eigen::Matrix3f R = T.topLeftCorner<3, 3>().cast<float>();
    const Eigen::Vector3f t = T.topRightCorner<3, 1>().cast<float>();
    for (const Eigen::Vector3f& p : s.points) out.points.push_back(j == i ? p : Eigen::Vector3f(R * p + t));
    out.intensity.insert(out.intensity.end(), s.intensity.begin(), s.intensity.end());
    out.labels.insert(out.labels.end(), s.labels.begin(), s.labels.end());
    out.true_labels.insert(out.true_labels.end(), s.true_labels.begin(), s.true_labels.end());
  }
  return out;
}

SimFrame Simulator::frame(int i) const {
  if (i < 0 || i >= numFrames()) throw Error("frame " + std::to_string(i) + " is out of range");
  std::vector<SimScan> scans;
  std::vector<const SimScan*> ptrs;
  for (int j = firstScan(i); j <= i; ++j) scans.push_back(scan(j));
  for (const SimScan& s : scans) ptrs.push_back(&s);
  return merge(i, ptrs);
}

}  // namespace sgtllc::sim
