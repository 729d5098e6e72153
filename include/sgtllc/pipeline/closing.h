/// @file closing.h
/// @brief The back end over a drive's odometry and loops: one batch solve, or a re-solve at every loop as a robot
///        does (docs/backend.md, "Online"), and what came of each loop.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/backend/pose_graph_optimizer.h"
#include "sgtllc/pipeline/loop_edge.h"

namespace sgtllc::pipeline {

// The back end's verdicts are the pipeline's results too.
using backend::BackendResult;
using backend::LoopDecision;
using backend::loopDecisionName;
using backend::LoopReport;

/// What the back end made of the loops.
struct Closing {
  backend::BackendResult result;         ///< per-loop decisions (loops in the order given), solver statistics
  std::vector<Eigen::Isometry3d> poses;  ///< corrected trajectory, T_world_frame
  double ms = 0.0;                       ///< optimisation time (all solves)
  double final_ms = 0.0;                 ///< online: the full solve after the last frame (included in ms)
  /// Online: the process CPU time of each re-solve at a loop (ms), in the order of the loops; the final full solve
  /// is not among them.
  std::vector<double> online_solve_cpu_ms;
  /// Online: how far the final full solve moved each frame from the online estimate (m): the error of the online
  /// poses, had the drive ended before the last frame.
  std::vector<double> online_final_shift_m;
};

/// The odometry edges of @p T_world_frame (one per frame) and all @p loops, optimised once (batch).
Closing closeLoopsBatch(const std::vector<Eigen::Isometry3d>& T_world_frame, const std::vector<ClosingLoop>& loops,
                        const backend::BackendConfig& config);

/// The online back end: frames as they arrive, a re-optimisation at every loop (PoseGraphOptimizer::closeLoop).
class OnlineClosing {
 public:
  /// Frame 0 at @p T_world_first. Throws sgtllc::Error if @p config is invalid.
  OnlineClosing(const backend::BackendConfig& config, const Eigen::Isometry3d& T_world_first);
  /// Adds the next frame at odometry pose @p T_world_frame (its step from the previous frame's odometry pose).
  void addFrame(const Eigen::Isometry3d& T_world_frame);
  /// Adds the loop and re-optimises; its frames must have been added.
  const backend::BackendResult& closeLoop(const ClosingLoop& loop);
  /// The current estimate of every frame added (corrected at the last re-solve, dead-reckoned after).
  const std::vector<Eigen::Isometry3d>& poses() const { return optimizer_.poses(); }
  /// The full solve with every frame added (the batch result): what a robot does once the drive ends.
  Closing finish();

 private:
  backend::PoseGraphOptimizer optimizer_;
  Eigen::Isometry3d last_;  // odometry pose of the newest frame
  double ms_ = 0.0;
  std::vector<double> solve_cpu_ms_;
};

/// Loops by decision, as the summaries give them.
struct ClosingCounts {
  int loops = 0, accepted = 0, inconsistent = 0, large_residual = 0, nominal = 0;
  int injected = 0, injected_rejected = 0;
};
ClosingCounts countLoops(const std::vector<ClosingLoop>& loops, const backend::BackendResult& result);

/// The corrected pose graph: @p closing's poses, the odometry edges of @p T_world_odometry and the accepted loops.
backend::PoseGraph correctedGraph(const std::vector<Eigen::Isometry3d>& T_world_odometry,
                                  const std::vector<ClosingLoop>& loops, const Closing& closing,
                                  const backend::BackendConfig& config);

/// Every loop as a g2o EDGE_SE3:QUAT line, each rejected or injected one after a `# ` comment saying so.
std::string loopListG2o(const std::vector<ClosingLoop>& loops, const Closing& closing);

}  // namespace sgtllc::pipeline
