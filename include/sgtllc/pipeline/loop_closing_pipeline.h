/// @file loop_closing_pipeline.h
/// @brief Loop closing as a SLAM system embeds it (docs/pipeline.md): frames in, one at a time, with their odometry
///        poses when there are any; loops, their pose-graph edges and the corrected trajectory out. `sgtllc run`, the
///        Python module and examples/close_loops.cpp all go through it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/map/map.h"
#include "sgtllc/pipeline/closing.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/pipeline/loop_edge.h"

namespace sgtllc {
class ScanAccumulator;
}

namespace sgtllc::pipeline {

class FrameReducer;

/// How the pipeline uses the odometry poses.
struct PipelineOptions {
  /// Re-solve the pose graph at every loop (the reduced graph, docs/backend.md "Online") so that poses() is
  /// corrected as the drive goes; finish() then solves the full graph once. Off: one batch solve at finish().
  bool online = false;
  /// Scans given to addScan() merged into each frame, the newest and the N − 1 before it moved by their poses
  /// (accumulate/scan_accumulator.h; for narrow sensors). 1 = off. Needs a pose with every scan.
  int accumulate = 1;
};

/// What one frame brought.
struct PipelineFrame {
  int index = -1;                   ///< the frame's number: 0, 1, 2, … in the order given
  FrameResult detection;            ///< the detector's candidates, verification and timing
  std::optional<ClosingLoop> loop;  ///< the loop found at this frame, as a pose-graph edge (also in loops())
  bool solved = false;              ///< online: the graph was re-solved at this loop, poses() moved
  /// That re-solve's decision on each loop so far and its statistics (poses() has its poses); nullptr unless
  /// solved. Valid until the next call on the pipeline.
  const backend::BackendResult* update = nullptr;
  double solve_ms = 0.0;  ///< wall time of the re-solve
};

/// Not thread-safe; uses config.threads inside the detector (results do not depend on it).
class LoopClosingPipeline {
 public:
  /// Throws sgtllc::Error if the configuration or the options are invalid.
  explicit LoopClosingPipeline(const Config& config, PipelineOptions options = {});
  ~LoopClosingPipeline();
  LoopClosingPipeline(LoopClosingPipeline&&) noexcept;
  LoopClosingPipeline& operator=(LoopClosingPipeline&&) noexcept;

  /// A scan (points in the sensor frame) with a label per point, or with labeller.source geometric any labels
  /// (they are replaced). @p T_world_frame: the frame's odometry pose (sensor frame in the odometry's world);
  /// give it with every frame or with none (no poses: detection only). @p name defaults to the index, six digits.
  /// Throws sgtllc::Error for points and labels of different lengths, a pose missing or given after frames without
  /// one, or a frame after finish().
  PipelineFrame addScan(const LabeledCloud& scan, const std::optional<Eigen::Isometry3d>& T_world_frame = {},
                        std::string name = {});
  /// A frame given as nodes (centre + stable class, e.g. from an instance segmentation); as addScan().
  PipelineFrame addNodes(std::vector<Node> nodes, const std::optional<Eigen::Isometry3d>& T_world_frame = {},
                         std::string name = {});
  /// A frame already reduced to nodes (FrameSource::load or streamFrames, which read and reduce frames in
  /// parallel); as addScan().
  PipelineFrame addFrame(LoadedFrame frame, const std::optional<Eigen::Isometry3d>& T_world_frame = {},
                         std::string name = {});

  /// Ends the drive: the batch solve of every loop, or online the full solve after the last re-solve. Needs the
  /// frames' poses (throws sgtllc::Error otherwise). Called once; later frames are refused.
  const Closing& finish();

  int numFrames() const;
  /// Whether the frames came with poses (and the back end runs).
  bool hasPoses() const { return !odometry_.empty(); }
  /// Every loop found so far, in the order found.
  const std::vector<ClosingLoop>& loops() const { return loops_; }
  const std::vector<std::string>& names() const { return names_; }
  /// The odometry poses as given, rotations orthonormalised (orthonormalised()).
  const std::vector<Eigen::Isometry3d>& odometry() const { return odometry_; }
  /// The best poses now: after finish() the final solution; online, the last re-solve's (frames after it
  /// dead-reckoned); otherwise the odometry.
  const std::vector<Eigen::Isometry3d>& poses() const;
  /// The result of finish(), or nullptr before it.
  const Closing* closing() const { return closing_.get(); }
  const LoopDetector& detector() const { return detector_; }
  const Config& config() const { return detector_.config(); }

  /// The frames as a map for relocalization (map/map.h): the database, the names and @p poses (T_world_frame, one
  /// per frame, or none); without @p poses, poses() if the frames had poses.
  map::Map map(std::optional<std::vector<Eigen::Matrix4d>> poses = {}) const;

 private:
  void checkPose(const std::optional<Eigen::Isometry3d>& T_world_frame) const;
  void addPose(const Eigen::Isometry3d& T_world_frame);

  PipelineOptions options_;
  LoopDetector detector_;
  std::unique_ptr<FrameReducer> reducer_;
  std::unique_ptr<ScanAccumulator> accumulator_;
  std::vector<std::string> names_;
  std::vector<Eigen::Isometry3d> odometry_;
  std::vector<ClosingLoop> loops_;
  std::unique_ptr<OnlineClosing> online_;
  std::unique_ptr<Closing> closing_;
};

/// @p T with its rotation projected onto SO(3) (through a unit quaternion): trajectory files leave rotations
/// orthonormal to about 1e-7 only (KITTI's Tr conversion), and the back end needs them exact.
Eigen::Isometry3d orthonormalised(const Eigen::Isometry3d& T);

}  // namespace sgtllc::pipeline
