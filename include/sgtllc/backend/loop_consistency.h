/// @file loop_consistency.h
/// @brief The outlier step's first half: pairwise consistency of loops with the odometry and a maximum
/// consistent set (after Mangelson et al.'s PCM, ICRA 2018; see docs/backend.md).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "sgtllc/config/backend_config.h"
#include "sgtllc/backend/odometry_chain.h"
#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::backend {

/// Translation (m) and rotation (rad) by which the cycle a →(odometry) c →(j) d →(odometry) b →(i⁻¹) a of loops
/// i = (a→b) and j = (c→d) fails to close, and the odometry path length L of its two legs (m).
struct CycleError {
  double translation = 0.0;
  double rotation = 0.0;
  double path_length = 0.0;
};

CycleError cycleError(const Edge& i, const Edge& j, const OdometryChain& odometry);
/// The same cycle with its two legs given: T_a_c from i's `from` frame to j's, T_d_b from j's `to` frame to i's,
/// and their length (a prior map's corrected poses for one leg, docs/sessions.md).
CycleError cycleError(const Edge& i, const Edge& j, const Eigen::Isometry3d& T_a_c, const Eigen::Isometry3d& T_d_b,
                      double path_length);

/// Whether the cycle closes within the LoopConsistency bounds at its path length.
bool consistent(const CycleError& e, const LoopConsistency& bounds);

/// Loops and their pairwise consistency, grown one loop at a time (O(n) cycle checks per loop).
class ConsistencyGraph {
 public:
  /// Adds a loop (checked against all loops added before) and returns its index.
  int add(const Edge& loop, const OdometryChain& odometry, const LoopConsistency& bounds);
  /// Adds a loop, consistent with each earlier loop for which @p consistent_with says so; returns its index.
  int add(const Edge& loop, const std::function<bool(const Edge& earlier)>& consistent_with);
  int size() const { return static_cast<int>(loops_.size()); }
  bool adjacent(int i, int j) const { return (rows_[i][j / 64] >> (j % 64)) & 1u; }
  int degree(int i) const { return degree_[i]; }

  /// A largest set of mutually consistent loops, ascending.
  /// Greedy and deterministic: from every seed in descending degree (ties: lower index) that is not in the
  /// largest clique found so far, add the candidates in the same order while they stay consistent with all chosen;
  /// keep the largest (ties: the first found).
  std::vector<int> maximumClique() const;

 private:
  std::vector<Edge> loops_;
  std::vector<std::vector<uint64_t>> rows_;  ///< adjacency bit sets
  std::vector<int> degree_;
};

}  // namespace sgtllc::backend
