#include "sgtllc/sim/sequence_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <numeric>
#include <utility>

#include <Eigen/LU>

#include "sgtllc/config.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "sgtllc/node_extraction.h"
#include "sgtllc/sim/cross_session.h"
#include "sgtllc/sim/manifest.h"
#include "sgtllc/sim/odometry.h"
#include "sgtllc/parallel.h"
#include "sgtllc/sim/preview.h"

namespace sgtllc::sim {
namespace {

namespace fs = std::filesystem;

std::string frameName(int i) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "%06d", i);
  return buf;
}

/// Per-frame results a worker hands back (filled in its own slot; merged in frame order).
struct FrameSlot {
  uint32_t points = 0;
  std::map<uint16_t, uint64_t> classes;
  bool sampled = false;
  std::array<int, kNumPaperClasses> nodes{}, true_nodes{};
  std::exception_ptr error;
};

std::array<int, kNumPaperClasses> nodesPerClass(const NodeExtractor& extractor, const SimFrame& f, bool truth) {
  LabeledCloud cloud;
  cloud.points = f.points;
  cloud.labels = truth ? f.true_labels : f.labels;
  std::array<int, kNumPaperClasses> count{};
  for (const Node& n : extractor.extract(cloud).nodes) ++count[n.label];
  return count;
}

/// Revisit figures from the poses (frame 0 frame) and the positive pairs.
void revisitStats(const Simulator& sim, const std::vector<Eigen::Matrix4d>& poses, const std::vector<LoopPair>& pairs,
                  int min_gap, SequenceStats& s) {
  int last_query = -1;
  bool last_opposite = false;
  for (const LoopPair& p : pairs) {
    if (!p.loop) continue;
    // Forward axes (first rotation column) of the two frames, compared in the ground plane.
    const Eigen::Vector2d fq = poses[p.query].block<2, 1>(0, 0).normalized();
    const Eigen::Vector2d fc = poses[p.candidate].block<2, 1>(0, 0).normalized();
    const bool opposite = fq.dot(fc) < std::cos(135.0 * M_PI / 180.0);
    if (p.query != last_query) {
      s.opposite_queries += last_opposite;
      ++s.query_frames;
      last_query = p.query;
      last_opposite = false;
    }
    last_opposite = last_opposite || opposite;
  }
  s.opposite_queries += last_opposite;
  for (int i = 0; i < sim.numFrames(); ++i) {
    const VisitKind kind = sim.poses()[i].kind;
    ++s.frames_by_kind[kind];
    if (kind != VisitKind::kLaneShift1 && kind != VisitKind::kLaneShift2) continue;
    double nearest = 1e300;
    for (int c = 0; c + min_gap <= i; ++c) {
      nearest = std::min(nearest, (poses[i].topRightCorner<3, 1>() - poses[c].topRightCorner<3, 1>()).norm());
    }
    if (nearest < 1e300) s.lane_shift_offsets.push_back(nearest);
  }
}

}  // namespace

void checkOutputDir(const std::string& dir, bool force) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) throw Error("cannot write to " + dir + ": it is a file, not a folder");
  if (!force && fs::directory_iterator(dir, ec) != fs::directory_iterator()) {
    throw Error(dir + " is not empty; choose an empty or new folder, or pass --force to overwrite the simulator's "
                      "files in it (nothing else is touched)");
  }
  if (ec) throw Error("cannot read folder " + dir + ": " + ec.message());
}

void prepareOutputDir(const std::string& dir, bool force) {
  checkOutputDir(dir, force);
  std::error_code ec;
  for (const fs::path& p : {fs::path(dir), fs::path(dir) / "velodyne", fs::path(dir) / "labels"}) {
    fs::create_directories(p, ec);
    if (ec || !fs::is_directory(p)) throw Error("cannot create folder " + p.string() + ": " + ec.message());
  }
}

std::vector<Eigen::Matrix4d> readBackLidarPoses(const std::string& dir) {
  return io::lidarPoses(io::readKittiPoses(dir + "/poses.txt"), io::readKittiCalibTr(dir + "/calib.txt"));
}

SequenceStats writeSequence(const Simulator& sim, const WriteOptions& options,
                            const std::function<void(int)>& progress) {
  prepareOutputDir(options.dir, options.force);
  const std::string& dir = options.dir;
  const int n = sim.numFrames();
  // Without --force the folder was empty a moment ago: refuse any file that has appeared in it since.
  const io::Overwrite overwrite = io::overwriteIf(options.force);

  // Poses in the KITTI convention: cam0 of frame i in cam0 of frame 0, P_i = Tr · T_lidar0_lidari · Tr⁻¹.
  const Eigen::Matrix4d Tr = io::kittiVelodyneToCam0();
  const Eigen::Matrix4d Tr_inv = Tr.inverse();
  const Eigen::Matrix4d world_to_0 = sim.T_world_origin().inverse();  // a second session: the first one's frame 0
  std::vector<Eigen::Matrix4d> lidar0(n), cam(n);
  std::vector<double> times(n);
  for (int i = 0; i < n; ++i) {
    lidar0[i] = world_to_0 * sim.poses()[i].T_world_lidar;
    cam[i] = Tr * lidar0[i] * Tr_inv;
    times[i] = sim.poses()[i].time;
  }
  SequenceStats stats;
  writeManifest(dir, sim.config(), overwrite);
  io::writeKittiCalib(dir + "/calib.txt", io::kittiProjections(), Tr, overwrite);
  io::writeKittiPoses(dir + "/poses.txt", cam, overwrite);
  // Odometry knows nothing of another session: a second session's starts at the identity, in its own frame 0, as a
  // real drive's would (poses.txt, the ground truth, stays in the first session's frame; docs/relocalization.md).
  std::vector<Eigen::Matrix4d> own = lidar0;
  if (sim.isSecondSession() && !own.empty()) {
    const Eigen::Matrix4d first_inv = lidar0.front().inverse();
    for (Eigen::Matrix4d& T : own) T = first_inv * T;
  }
  const std::vector<Eigen::Matrix4d> odometry = driftingOdometry(own, options.odometry, sim.config().seed);
  std::vector<Eigen::Matrix4d> odometry_cam(n);
  for (int i = 0; i < n; ++i) odometry_cam[i] = Tr * odometry[i] * Tr_inv;
  io::writeKittiPoses(dir + "/odometry.txt", odometry_cam, overwrite);
  io::writeKittiTimes(dir + "/times.txt", times, overwrite);
  LoopPairOptions pair_options;
  pair_options.seed = sim.config().seed;
  const std::vector<Eigen::Matrix4d> lidar = readBackLidarPoses(dir);
  const std::vector<LoopPair> pairs = loopPairs(lidar, pair_options);
  writeLoopPairs(dir + "/loop_pairs.txt", pairs, overwrite);
  if (sim.isSecondSession()) {
    std::vector<Eigen::Vector3d> first, second;
    for (const Eigen::Matrix4d& T : sim.firstSessionPoses()) first.push_back((world_to_0 * T).topRightCorner<3, 1>());
    for (const Eigen::Matrix4d& T : lidar0) second.push_back(T.topRightCorner<3, 1>());
    const std::vector<NearestFrame> nearest = nearestFrames(first, second);
    writeCrossSession(dir + "/" + kCrossSessionName, nearest, overwrite);
    for (const NearestFrame& f : nearest) {
      stats.cross_near += f.distance <= pair_options.positive_distance;
      stats.cross_far += f.distance > pair_options.negative_distance;
    }
  }

  stats.frames = n;
  for (int i = 1; i < n; ++i) {
    stats.path_length += (lidar0[i].topRightCorner<3, 1>() - lidar0[i - 1].topRightCorner<3, 1>()).norm();
  }
  stats.odometry_end_error = (odometry.back().topRightCorner<3, 1>() - own.back().topRightCorner<3, 1>()).norm();
  for (const LoopPair& p : pairs) ++(p.loop ? stats.positives : stats.negatives);
  revisitStats(sim, lidar, pairs, pair_options.min_gap, stats);

  const Config defaults;
  const NodeExtractor extractor(defaults.cluster, defaults.labels);
  const int threads = std::max(1, options.threads);
  const int batch = 4 * threads;
  std::vector<FrameSlot> slots;
  // Raw scans by index. An accumulating sensor merges each scan into several consecutive frames, so every scan is
  // cast once and kept until the last frame that needs it is written.
  std::map<int, SimScan> scans;
  for (int first = 0; first < n; first += batch) {
    const int count = std::min(batch, n - first);
    const int lo = sim.firstScan(first);
    scans.erase(scans.begin(), scans.lower_bound(lo));
    std::vector<int> missing;
    for (int j = lo; j < first + count; ++j) {
      if (scans.count(j) == 0) missing.push_back(j);
    }
    std::vector<SimScan> cast(missing.size());
    std::vector<std::exception_ptr> cast_errors(missing.size());
    parallelFor(static_cast<int>(missing.size()), threads, [&](int k) {
      try {
        cast[static_cast<size_t>(k)] = sim.scan(missing[static_cast<size_t>(k)]);
      } catch (...) {
        cast_errors[static_cast<size_t>(k)] = std::current_exception();
      }
    });
    for (size_t k = 0; k < missing.size(); ++k) {
      if (cast_errors[k]) std::rethrow_exception(cast_errors[k]);
      scans.emplace(missing[k], std::move(cast[k]));
    }

    slots.assign(static_cast<size_t>(count), FrameSlot{});
    parallelFor(count, threads, [&](int k) {
      FrameSlot& slot = slots[static_cast<size_t>(k)];
      const int i = first + k;
      try {
        std::vector<const SimScan*> merged;
        for (int j = sim.firstScan(i); j <= i; ++j) merged.push_back(&scans.at(j));
        const SimFrame f = sim.merge(i, merged);
        io::writeKittiBin(dir + "/velodyne/" + frameName(i) + ".bin", f.points, f.intensity, overwrite);
        io::writeLabelFile(dir + "/labels/" + frameName(i) + ".label", f.labels, overwrite);
        slot.points = static_cast<uint32_t>(f.points.size());
        for (uint32_t w : f.labels) ++slot.classes[static_cast<uint16_t>(w & 0xFFFF)];
        if (options.node_stats_every > 0 && i % options.node_stats_every == 0) {
          slot.sampled = true;
          slot.nodes = nodesPerClass(extractor, f, false);
          slot.true_nodes = nodesPerClass(extractor, f, true);
        }
      } catch (...) {
        slot.error = std::current_exception();
      }
    });
    for (FrameSlot& slot : slots) {
      if (slot.error) std::rethrow_exception(slot.error);
      stats.points.push_back(slot.points);
      for (const auto& [id, c] : slot.classes) stats.class_points[id] += c;
      if (slot.sampled) {
        stats.nodes.push_back(slot.nodes);
        stats.true_nodes.push_back(slot.true_nodes);
      }
    }
    if (progress) progress(first + count);
  }
  if (options.previews) {
    // The scan shown is a typical one: the sampled frame with the median number of graph nodes (true labels).
    std::vector<std::pair<int, int>> by_nodes;  // (nodes, frame)
    for (size_t k = 0; k < stats.true_nodes.size(); ++k) {
      by_nodes.push_back({std::accumulate(stats.true_nodes[k].begin(), stats.true_nodes[k].end(), 0),
                          static_cast<int>(k) * options.node_stats_every});
    }
    std::sort(by_nodes.begin(), by_nodes.end());
    const int preview = by_nodes.empty() ? n / 2 : by_nodes[by_nodes.size() / 2].second;
    writeScanPreview(dir + "/preview_scan.png", sim.frame(preview),
                     "frame " + frameName(preview) + " (" + sceneName(sim.config().scene) + ", " +
                         sensorName(sim.config().sensor.kind) + "), coloured by label",
                     overwrite);
    writeTrajectoryPreview(dir + "/preview_trajectory.png", sim, lidar, pairs, overwrite);
  }
  return stats;
}

}  // namespace sgtllc::sim
