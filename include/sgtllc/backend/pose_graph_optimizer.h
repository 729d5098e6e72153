/// @file pose_graph_optimizer.h
/// @brief Pose-graph optimisation with an explicit outlier step, batch and online (docs/backend.md).
///
/// Every optimize() does the same three steps on all loops received so far, so the online result after the
/// last loop equals the batch result up to the solver tolerance (only the starting point differs):
///   1. pairwise consistency of the loops with the odometry → largest consistent set (loop_consistency.h);
///   2. Dogleg (Ceres trust region) on SE(3) over odometry (squared) and the kept loops (robust loss), frame 0 fixed;
///   3. residual check: while a kept loop's χ² exceeds max_loop_chi2, drop the worst and re-optimise.
/// optimizeReduced() (what closeLoop() runs by default) does the same steps on the reduced graph of the anchors
/// (frame 0, the loop endpoints, one per stretch of config.online.anchor_spacing_m of path, the newest frame),
/// then places the frames in between: an approximation of optimize() whose cost is bounded by the path length, not
/// the number of loops (docs/backend.md, "Online").
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/config/backend_config.h"
#include "sgtllc/backend/loop_consistency.h"
#include "sgtllc/backend/odometry_chain.h"
#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::backend {

enum class LoopDecision {
  kAccepted,       ///< in the consistent set and within the residual bound: used by the optimisation
  kInconsistent,   ///< outside the largest set of pairwise-consistent loops (step 1)
  kLargeResidual,  ///< consistent, but its χ² after optimising exceeded max_loop_chi2 (step 3)
};

/// "accepted", "inconsistent" or "large_residual".
const char* loopDecisionName(LoopDecision d);

struct LoopReport {
  int from = 0;                ///< match frame
  int to = 0;                  ///< query frame
  LoopDecision decision = LoopDecision::kAccepted;
  int consistent_with = 0;     ///< other loops it is pairwise consistent with
  double chi2 = 0.0;  ///< eᵀΩe at the returned poses (also for rejected loops); reduced: as carried to its anchors
};

struct BackendResult {
  std::vector<Eigen::Isometry3d> poses;  ///< T_world_frame, frame 0 unchanged
  std::vector<LoopReport> loops;         ///< one per loop, in the order received
  int num_accepted = 0;
  int num_rejected = 0;                  ///< inconsistent + large residual
  int solves = 0;  ///< Ceres solves: the reduced warm start if any, 1 + residual-check rounds that dropped a loop
  int iterations = 0;                    ///< trust-region (Dogleg) iterations over all solves
  double final_cost = 0.0;               ///< ½ Σ ρ(eᵀΩe) of the last solve
  bool converged = true;                 ///< every solve met a tolerance within max_iterations
  bool reduced = false;                  ///< from optimizeReduced(): the anchors' graph, frames in between placed
  int num_poses_solved = 0;              ///< poses in the last solve: all frames, or the anchors if `reduced`
};

/// A growing pose graph. Online use: addOdometry() per frame, closeLoop() when the detector reports a loop (which
/// re-optimises the reduced graph, warm-started from the current estimate), and optimize() when the full
/// solution is wanted (at the end of a run, or now and then): its result is the batch result. Batch use:
/// optimize(graph, config). Not thread-safe.
class PoseGraphOptimizer {
 public:
  /// Frame 0 at @p T_world_first. Throws sgtllc::Error if @p config is invalid.
  explicit PoseGraphOptimizer(const BackendConfig& config = {},
                              const Eigen::Isometry3d& T_world_first = Eigen::Isometry3d::Identity());
  /// All of a graph, to optimise from its poses: it needs an odometry edge i−1 → i for every frame i ≥ 1 (and
  /// no other odometry edge); every loop edge joins two distinct frames. Throws sgtllc::Error naming the edge.
  PoseGraphOptimizer(const PoseGraph& graph, const BackendConfig& config);

  /// Adds frame N after frame N−1 with information odometryInformation(T_prev_curr); returns N. Its initial
  /// pose is the current estimate of frame N−1 composed with the step.
  int addOdometry(const Eigen::Isometry3d& T_prev_curr);
  /// The same with a given information matrix.
  int addOdometry(const Eigen::Isometry3d& T_prev_curr, const Matrix6d& information);
  /// Records a loop (any kind of edge: it gets the robust loss and the outlier step) without optimising.
  /// Throws sgtllc::Error if a frame does not exist or from == to.
  void addLoop(const Edge& loop);
  /// addLoop() then optimizeReduced(), or optimize() if config.online.reduced_graph is false: what a running
  /// robot does when a loop arrives.
  const BackendResult& closeLoop(const Edge& loop);
  /// Runs the outlier step and the optimisation of the full graph over everything received, from the current
  /// estimate (first from the reduced graph's solution if config.solver.reduced_warm_start).
  const BackendResult& optimize();
  /// Runs the outlier step and the optimisation over everything received on the reduced graph: the anchors are
  /// frame 0, the loop endpoints (the middle one of those within one stretch of config.online.anchor_spacing_m of
  /// path; the others' loops are carried to an anchor along the odometry) and the newest frame; the odometry
  /// between consecutive anchors is one edge with the propagated covariance; each frame between two anchors is
  /// then placed by the least-squares solution of its chain between them, to first order. O(frames + loops)
  /// outside the solver, whose size is the number of anchors.
  const BackendResult& optimizeReduced();

  int numFrames() const { return static_cast<int>(poses_.size()); }
  int numLoops() const { return static_cast<int>(loops_.size()); }
  /// Current estimate (T_world_frame): optimised up to the last optimize(), dead-reckoned after.
  const std::vector<Eigen::Isometry3d>& poses() const { return poses_; }
  /// The result of the last optimize().
  const BackendResult& result() const { return result_; }

 private:
  const BackendResult& run(bool reduced);

  BackendConfig config_;
  std::vector<Eigen::Isometry3d> poses_;
  std::vector<Edge> odometry_;
  std::vector<Matrix6d> odometry_covariance_;  ///< Ω⁻¹ of each odometry edge, for the reduced graph
  std::vector<Edge> loops_;
  OdometryChain chain_;
  ConsistencyGraph consistency_;
  BackendResult result_;
};

/// Batch optimisation of a whole graph from its poses (PoseGraphOptimizer(graph, config).optimize()).
BackendResult optimize(const PoseGraph& graph, const BackendConfig& config = {});

}  // namespace sgtllc::backend
