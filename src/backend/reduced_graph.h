// Internal: the reduced pose graph of the online step (docs/backend.md, "Online: the reduced graph"). Only the
// anchors (frame 0, the loop endpoints, one per stretch of path, the newest frame) are optimised; the odometry
// between two consecutive anchors becomes one edge, a loop whose endpoint is not an anchor is carried along the
// odometry to the nearer anchor, and afterwards every frame in between is placed from the two optimised anchors.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::backend::internal {

struct ReducedGraph {
  std::vector<int> anchors;  ///< frames kept, ascending, unique: anchors.front() = 0, anchors.back() = N − 1
  /// Chain k: the odometry anchors[k] → anchors[k+1] composed, as an edge between reduced indices k → k+1 with
  /// the propagated covariance's inverse as information.
  std::vector<Edge> chains;
  std::vector<Matrix6d> chain_covariance;  ///< per chain, the covariance whose inverse is its information
  /// Per frame i, within the chain that starts at anchor a ≤ i: the composed odometry T_a_i and its covariance
  /// (over the right perturbation in frame i). At an anchor: identity and zero.
  std::vector<Eigen::Isometry3d> T_anchor_frame;
  std::vector<Matrix6d> covariance_anchor_frame;

  /// Reduced index of the last anchor at or before @p frame.
  int indexAtOrBefore(int frame) const;
};

/// Composes the odometry edges i−1 → i (at index i − 1, of frames 0..N−1, with covariances Ω⁻¹ @p covariance)
/// between consecutive @p anchors (sorted and made unique here; 0 and N − 1 are added).
/// First-order propagation: with Z_i = Ẑ_i Exp(ε_i), the chain's error is Σ_i Ad(Ẑ_{i+1} ⋯ Ẑ_b)⁻¹ ε_i, so the
/// covariance grows as Σ ← Ad(Ẑ_i)⁻¹ Σ Ad(Ẑ_i)⁻ᵀ + Σ_i. In a linear Gaussian chain this is the exact
/// marginal of its two ends.
ReducedGraph reduceOdometry(const std::vector<Edge>& odometry, const std::vector<Matrix6d>& covariance,
                            std::vector<int> anchors);

/// @p loop (frames f → g) as an edge between anchors A and B, each the one before or after its endpoint whose
/// odometry piece to it is shorter (if that is one anchor for both, the earlier endpoint's before and the later
/// one's after): T_A_B = T̂_A_f · Z · T̂_B_g⁻¹, with covariance
/// Ad(T̂_B_g) (Ad(Z)⁻¹ Σ_A_f Ad(Z)⁻ᵀ + Ω⁻¹ + Σ_B_g) Ad(T̂_B_g)ᵀ over the right perturbation at B, to first order
/// (the pieces' correlation with the odometry chains is left out). When f and g are anchors the loop is returned
/// as it is, reindexed.
Edge carryLoop(const ReducedGraph& reduced, const Edge& loop);

/// Places every frame strictly between two anchors, given the anchors' optimised poses in @p poses (T_world_frame,
/// indexed by frame): T_i = T_a Ẑ_a_i ⊕ ε_i, with ε_i = Σ_a_i Ad(Ẑ_i_b)⁻ᵀ Σ_a_b⁻¹ c the conditional mean of the
/// chain's error at i given its misclosure c = e(T_a, T_b) at the far anchor, i.e. the least-squares solution of
/// the chain between the two fixed anchors, to first order. Anchors are left as they are.
void redistribute(const ReducedGraph& reduced, std::vector<Eigen::Isometry3d>& poses);

}  // namespace sgtllc::backend::internal
