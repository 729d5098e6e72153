// Internal: the whitened edge error U·e (Ω = UᵀU) of pose_graph_types.h as a Ceres cost over two pose blocks
// (quaternion x, y, z, w then translation), with analytic Jacobians. Automatic differentiation of the same error
// is kept as the reference the tests compare against (docs/backend.md, "Solver").
#pragma once

#include <array>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/product_manifold.h>
#include <ceres/sized_cost_function.h>

#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::backend::internal {

/// Pose parameter block: quaternion (x, y, z, w; Eigen's memory order) then translation.
using PoseBlock = std::array<double, 7>;
/// Its manifold: Ceres' quaternion tangent is a left perturbation by half the rotation vector,
/// q ⊞ δ = [cos|δ|, sin|δ| δ/|δ|] ⊗ q; the translation is added.
using PoseManifold = ceres::ProductManifold<ceres::EigenQuaternionManifold, ceres::EuclideanManifold<3>>;

PoseBlock toBlock(const Eigen::Isometry3d& T);
Eigen::Isometry3d fromBlock(const PoseBlock& b);

/// Analytic. Ceres only uses the product of a block's Jacobian with the manifold's PlusJacobian P, so the
/// quaternion columns are the tangent Jacobian times Pᵀ (P has orthonormal columns at a unit quaternion, so
/// Pᵀ is its pseudo-inverse and the product is exact).
class RelativePoseCost final : public ceres::SizedCostFunction<6, 7, 7> {
 public:
  explicit RelativePoseCost(const Edge& edge);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Quaterniond q_measured_inv_;
  Eigen::Vector3d t_measured_;
  Matrix6d sqrt_information_;
};

/// The same residual by automatic differentiation (the reference for the analytic Jacobians).
struct RelativePoseError {
  explicit RelativePoseError(const Edge& edge);

  template <typename T>
  bool operator()(const T* from, const T* to, T* residual) const;

  Eigen::Quaterniond q_measured_inv;
  Eigen::Vector3d t_measured;
  Matrix6d sqrt_information;
};
using AutoDiffRelativePoseCost = ceres::AutoDiffCostFunction<RelativePoseError, 6, 7, 7>;

}  // namespace sgtllc::backend::internal
