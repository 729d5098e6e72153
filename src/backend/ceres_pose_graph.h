// Internal: the one place that speaks Ceres. Solves a pose graph on SE(3) (unit quaternion × R³ manifold).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/config/backend_config.h"
#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::backend::internal {

struct SolveSummary {
  int iterations = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  bool converged = false;
};

/// The edge error of pose_graph_types.h: e = (t, rotation vector) of Δ = T_from_to⁻¹ · T_world_from⁻¹ · T_world_to.
Eigen::Matrix<double, 6, 1> edgeError(const Edge& edge, const Eigen::Isometry3d& T_world_from,
                                      const Eigen::Isometry3d& T_world_to);

/// The whitened residual U·e (Ω = UᵀU) of an edge and its Jacobians over the solver's tangent space of each pose
/// (quaternion: left perturbation by half the rotation vector; translation: added), i.e. the block Jacobian times
/// the manifold's PlusJacobian, which is all the solver uses. Analytic, or by automatic differentiation if
/// @p automatic (the reference the analytic one is tested against).
struct EdgeJacobians {
  Eigen::Matrix<double, 6, 1> residual;
  Matrix6d from;
  Matrix6d to;
};
EdgeJacobians edgeJacobians(const Edge& edge, const Eigen::Isometry3d& T_world_from, const Eigen::Isometry3d& T_world_to,
                            bool automatic);

/// Minimises Σ odometry eᵀΩe + Σ loops ρ(eᵀΩe) over @p poses (in place; the first @p fixed poses held as they are:
/// frame 0 as the gauge, or a prior map's frames, docs/sessions.md). @p loops are the edges (of any kind) that get
/// the robust loss.
SolveSummary solve(const std::vector<Edge>& odometry, const std::vector<Edge>& loops,
                   std::vector<Eigen::Isometry3d>& poses, const BackendConfig& config, int fixed = 1);

}  // namespace sgtllc::backend::internal
