/// @file simulator.h
/// @brief The simulator's front door: a world, a route with revisits and the sensor, producing labelled scans.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/sim/label_noise.h"
#include "sgtllc/sim/route.h"
#include "sgtllc/sim/scene.h"
#include "sgtllc/sim/sensor.h"
#include "sgtllc/sim/trajectory.h"
#include "sgtllc/sim/world.h"

namespace sgtllc::sim {

/// Everything a simulated sequence depends on. The same config gives the same bytes.
struct SimConfig {
  int frames = 100;                         ///< frames of the sequence (10 Hz)
  uint64_t seed = 1;                        ///< seeds every random choice
  SceneKind scene = SceneKind::kUrban;      ///< world preset
  SensorConfig sensor;                      ///< HDL-64E by default
  int accumulate = 0;                       ///< raw scans merged into each frame; 0 = sensor default (HDL-64 1, Mid-70 10)
  double label_noise = kDefaultLabelNoise;  ///< segmentation error rate R (0 = ground-truth labels)
  int revisits = -1;                        ///< planned revisits; −1 = one per 500 frames (at least one)
  double sensor_height = 1.73;              ///< m above the road
  /// A second session (docs/relocalization.md): drive through the world of this earlier, first session — its
  /// streets, buildings and vegetation as they were at its end; parked and moving vehicles and people drawn anew
  /// from `seed`, as are the route, the start and the noise — with poses in the first session's frame 0. The
  /// scene must match; the first session may not itself be a second one. Null = a world of its own.
  std::shared_ptr<const SimConfig> world_of;
  /// A second session that drives only the first session's roads (either way), as a robot driving the same streets
  /// again: no stretches of new road. Needs world_of.
  bool follow = false;

  /// Throws sgtllc::Error naming the first bad field.
  void validate() const;
  /// Raw scans per frame after defaults are applied.
  int scansPerFrame() const;
  /// Planned revisits after defaults are applied (0 for a second session, whose route plans none).
  int plannedRevisits() const;
};

/// One output frame in its own LiDAR frame.
struct SimFrame {
  std::vector<Eigen::Vector3f> points;
  std::vector<float> intensity;
  std::vector<uint32_t> labels;       ///< written labels (with label noise)
  std::vector<uint32_t> true_labels;  ///< ground truth
};

/// One raw scan with its labels, in the sensor frame of the moment it was taken.
struct SimScan {
  std::vector<Eigen::Vector3f> points;
  std::vector<float> intensity;
  std::vector<uint32_t> labels;       ///< written labels (with label noise)
  std::vector<uint32_t> true_labels;  ///< ground truth
};

class Simulator {
 public:
  /// Generates the world, plans the route and drives it (about a second for a 2,000-frame urban sequence; a
  /// second session first rebuilds its first session, about twice that).
  explicit Simulator(const SimConfig& config);

  const SimConfig& config() const { return config_; }
  const World& world() const { return world_; }
  const SensorModel& sensor() const { return sensor_; }
  const std::vector<Leg>& route() const { return route_; }
  /// One pose per frame (size() == config().frames).
  const std::vector<FramePose>& poses() const { return poses_; }
  int numFrames() const { return static_cast<int>(poses_.size()); }
  /// The frame the written poses are in: LiDAR frame 0 of this session, or of the first one for a second session.
  const Eigen::Matrix4d& T_world_origin() const { return T_world_origin_; }
  bool isSecondSession() const { return config_.world_of != nullptr; }
  /// Second session: the first session's LiDAR poses T_world_lidar, one per frame (empty for a first session).
  const std::vector<Eigen::Matrix4d>& firstSessionPoses() const { return first_poses_; }

  /// Frame @p i: raw scans max(0, i − scansPerFrame() + 1) … i merged in the LiDAR frame of frame i (so the first
  /// frames of an accumulating sensor hold fewer scans). Pure and thread-safe: any thread may compute any frame.
  SimFrame frame(int i) const;
  /// The first raw scan frame @p i merges: max(0, i − scansPerFrame() + 1).
  int firstScan(int i) const;
  /// Raw scan @p j with its labels (the work of a frame; pure and thread-safe).
  SimScan scan(int j) const;
  /// Frame @p i from its raw scans: @p scans[k] must be scan(firstScan(i) + k), for every scan up to i. Writers
  /// that produce consecutive frames reuse each scan for every frame that merges it.
  SimFrame merge(int i, const std::vector<const SimScan*>& scans) const;

 private:
  void driveSecondSession();

  SimConfig config_;
  SensorModel sensor_;
  World world_;
  std::vector<Leg> route_;
  std::vector<FramePose> poses_;
  Eigen::Matrix4d T_world_origin_ = Eigen::Matrix4d::Identity();
  double world_time_offset_ = 0.0;  ///< s added to a frame's time when it looks at the world (second session)
  std::vector<Eigen::Matrix4d> first_poses_;
};

}  // namespace sgtllc::sim
