// Internal: the few SE(3) formulas the back end needs, in its tangent convention (pose_graph_types.h): a
// perturbation ε = (δt, δθ) acts on the right, T ⊕ ε = (R · Exp(δθ), t + R · δt), translation first.
#pragma once

#include <cmath>

#include <Eigen/Geometry>

#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::backend::internal {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// [v]×: the cross-product matrix, [v]× w = v × w.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

/// Exp of a rotation vector.
inline Eigen::Matrix3d expSO3(const Eigen::Vector3d& w) {
  const double a = w.norm();
  return a < 1e-300 ? Eigen::Matrix3d::Identity() : Eigen::AngleAxisd(a, w / a).toRotationMatrix();
}

/// T ⊕ ε (the right perturbation of the edge error; ε of edgeError(Δ) gives back Δ from the identity).
inline Eigen::Isometry3d retract(const Eigen::Isometry3d& T, const Vector6d& e) {
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  D.linear() = expSO3(e.tail<3>());
  D.translation() = e.head<3>();
  return T * D;
}

/// Ad(T)⁻¹ = Ad(T⁻¹) over (δt, δθ): moves a right perturbation across T, A · Exp(ε) · T = A · T · Exp(Ad(T)⁻¹ ε)
/// to first order. With T = (R, t): [Rᵀ, −Rᵀ[t]×; 0, Rᵀ].
inline Matrix6d adjointInverse(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d Rt = T.rotation().transpose();
  Matrix6d A = Matrix6d::Zero();
  A.topLeftCorner<3, 3>() = Rt;
  A.topRightCorner<3, 3>() = -Rt * skew(T.translation());
  A.bottomRightCorner<3, 3>() = Rt;
  return A;
}

/// J_r⁻¹(θ) of SO(3): Log(Exp(θ) · Exp(δ)) = θ + J_r⁻¹(θ) δ + O(δ²), for |θ| ≤ π.
inline Eigen::Matrix3d rightJacobianInverse(const Eigen::Vector3d& theta) {
  const double a = theta.norm();
  const Eigen::Matrix3d W = skew(theta);
  // Coefficient of W²: 1/a² − (1 + cos a)/(2a sin a) = 1/a² − cot(a/2)/(2a), whose series is 1/12 + a²/720.
  const double c = a < 1e-4 ? 1.0 / 12.0 + a * a / 720.0 : 1.0 / (a * a) - 1.0 / (2.0 * a * std::tan(0.5 * a));
  return Eigen::Matrix3d::Identity() + 0.5 * W + c * W * W;
}

}  // namespace sgtllc::backend::internal
