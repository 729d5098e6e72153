#include "relative_pose_cost.h"

#include <ceres/rotation.h>

#include "se3.h"

namespace sgtllc::backend::internal {
namespace {

Matrix6d sqrtInformation(const Edge& edge) { return edge.information.llt().matrixU(); }

// Rotation vector of a quaternion, as Ceres computes it (atan2 form, stable near 0 and π).
template <typename T>
Eigen::Matrix<T, 3, 1> logQuaternion(const Eigen::Quaternion<T>& q) {
  const T wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
  Eigen::Matrix<T, 3, 1> w;
  ceres::QuaternionToAngleAxis(wxyz, w.data());
  return w;
}

}  // namespace

PoseBlock toBlock(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.rotation());
  return {q.x(), q.y(), q.z(), q.w(), T.translation().x(), T.translation().y(), T.translation().z()};
}

Eigen::Isometry3d fromBlock(const PoseBlock& b) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(b[3], b[0], b[1], b[2]).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(b[4], b[5], b[6]);
  return T;
}

RelativePoseCost::RelativePoseCost(const Edge& edge)
    : q_measured_inv_(Eigen::Quaterniond(edge.T_from_to.rotation()).conjugate()),
      t_measured_(edge.T_from_to.translation()),
      sqrt_information_(sqrtInformation(edge)) {}

// With T_from = (R_a, t_a), T_to = (R_b, t_b), Z = (R_z, t_z) and M = (R_a R_z)ᵀ:
//   e_t = R_zᵀ (R_aᵀ (t_b − t_a) − t_z),   e_r = Log(M R_b).
// Under the manifold's perturbations (R ← Exp(2δ) R, t ← t + δt):
//   ∂e_t/∂δt_a = −M,  ∂e_t/∂δt_b = M,  ∂e_t/∂δ_a = 2 M [t_b − t_a]×,  ∂e_t/∂δ_b = 0,
//   ∂e_r/∂δ_b = 2 J_r⁻¹(e_r) R_bᵀ = −∂e_r/∂δ_a,  ∂e_r/∂δt = 0,
// since M Exp(±φ) R_b = M R_b Exp(±R_bᵀ φ) (R_aᵀ ← R_aᵀ Exp(−φ)).
bool RelativePoseCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const Eigen::Map<const Eigen::Quaterniond> q_a(parameters[0]);
  const Eigen::Map<const Eigen::Vector3d> t_a(parameters[0] + 4);
  const Eigen::Map<const Eigen::Quaterniond> q_b(parameters[1]);
  const Eigen::Map<const Eigen::Vector3d> t_b(parameters[1] + 4);
  const Eigen::Quaterniond q_a_inv = q_a.conjugate();
  const Eigen::Vector3d d = t_b - t_a;
  const Eigen::Quaterniond q_delta = q_measured_inv_ * (q_a_inv * q_b);
  Vector6d e;
  e.head<3>() = q_measured_inv_ * (q_a_inv * d - t_measured_);
  e.tail<3>() = logQuaternion(q_delta);
  Eigen::Map<Vector6d> r(residuals);
  r = sqrt_information_ * e;
  if (jacobians == nullptr || (jacobians[0] == nullptr && jacobians[1] == nullptr)) return true;

  const Eigen::Matrix3d M = (q_measured_inv_ * q_a_inv).toRotationMatrix();
  const Eigen::Matrix3d D = 2.0 * rightJacobianInverse(e.tail<3>()) * q_b.conjugate().toRotationMatrix();
  const Eigen::Matrix3d M_d = 2.0 * M * skew(d);
  using Jacobian = Eigen::Matrix<double, 6, 7, Eigen::RowMajor>;
  // The quaternion's PlusJacobian P (4 × 3, rows x, y, z, w) is [w I − [v]×; −vᵀ]; Pᵀ lifts a tangent
  // Jacobian to the ambient columns.
  auto lift = [](const Eigen::Map<const Eigen::Quaterniond>& q) {
    Eigen::Matrix<double, 3, 4> Pt;
    Pt.leftCols<3>() = q.w() * Eigen::Matrix3d::Identity() + skew(q.vec());
    Pt.col(3) = -q.vec();
    return Pt;
  };
  if (jacobians[0] != nullptr) {
    Jacobian J = Jacobian::Zero();
    const Eigen::Matrix<double, 3, 4> Pt = lift(q_a);
    J.topLeftCorner<3, 4>() = M_d * Pt;
    J.topRightCorner<3, 3>() = -M;
    J.bottomLeftCorner<3, 4>() = -D * Pt;
    Eigen::Map<Jacobian> out(jacobians[0]);
    out = sqrt_information_ * J;
  }
  if (jacobians[1] != nullptr) {
    Jacobian J = Jacobian::Zero();
    J.topRightCorner<3, 3>() = M;
    J.bottomLeftCorner<3, 4>() = D * lift(q_b);
    Eigen::Map<Jacobian> out(jacobians[1]);
    out = sqrt_information_ * J;
  }
  return true;
}

RelativePoseError::RelativePoseError(const Edge& edge)
    : q_measured_inv(Eigen::Quaterniond(edge.T_from_to.rotation()).conjugate()),
      t_measured(edge.T_from_to.translation()),
      sqrt_information(sqrtInformation(edge)) {}

template <typename T>
bool RelativePoseError::operator()(const T* from, const T* to, T* residual) const {
  const Eigen::Map<const Eigen::Quaternion<T>> q_from(from);
  const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_from(from + 4);
  const Eigen::Map<const Eigen::Quaternion<T>> q_to(to);
  const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_to(to + 4);
  const Eigen::Quaternion<T> q_from_inv = q_from.conjugate();
  const Eigen::Quaternion<T> q_m = q_measured_inv.template cast<T>();
  Eigen::Matrix<T, 6, 1> e;
  e.template head<3>() = q_m * (q_from_inv * (t_to - t_from) - t_measured.template cast<T>());
  e.template tail<3>() = logQuaternion(Eigen::Quaternion<T>(q_m * (q_from_inv * q_to)));
  Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
  r = sqrt_information.template cast<T>() * e;
  return true;
}

template bool RelativePoseError::operator()(const double*, const double*, double*) const;
template bool RelativePoseError::operator()(const ceres::Jet<double, 14>*, const ceres::Jet<double, 14>*,
                                            ceres::Jet<double, 14>*) const;

}  // namespace sgtllc::backend::internal
