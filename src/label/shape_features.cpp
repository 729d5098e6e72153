// Eigenvalue shape features (docs/labeller.md §3).
#include "sgtllc/label/shape_features.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace sgtllc::label {

void Moments::merge(const Moments& other) {
  if (other.count_ == 0) return;
  if (count_ == 0) {
    *this = other;
    return;
  }
  // Shift the other's sums to this origin: Σ(d + o) = Σd + n·o, Σ(d + o)(d + o)ᵀ = Σddᵀ + Σd oᵀ + o Σdᵀ + n o oᵀ.
  const Eigen::Vector3d o = other.origin_ - origin_;
  const double m = static_cast<double>(other.count_);
  outer_ += other.outer_ + other.sum_ * o.transpose() + o * other.sum_.transpose() + m * o * o.transpose();
  sum_ += other.sum_ + m * o;
  count_ += other.count_;
}

Eigen::Vector3d Moments::mean() const {
  return count_ == 0 ? origin_ : Eigen::Vector3d(origin_ + sum_ / static_cast<double>(count_));
}

Eigen::Matrix3d Moments::covariance() const {
  if (count_ < 2) return Eigen::Matrix3d::Zero();
  const double n = static_cast<double>(count_);
  const Eigen::Vector3d m = sum_ / n;
  return outer_ / n - m * m.transpose();
}

ShapeFeatures shapeFeatures(const Eigen::Matrix3d& covariance) {
  ShapeFeatures f;
  // Closed-form 3×3 solver: fast, and the same result wherever it runs. Eigenvalues come in ascending order.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const Eigen::Vector3d ev = solver.eigenvalues().cwiseMax(0.0);
  const double l1 = ev(2), l2 = ev(1), l3 = ev(0);
  f.eigenvalues = Eigen::Vector3d(l1, l2, l3);
  if (!(l1 > 0.0)) return f;
  f.linearity = (l1 - l2) / l1;
  f.planarity = (l2 - l3) / l1;
  f.scattering = l3 / l1;
  f.axis_verticality = std::abs(solver.eigenvectors()(2, 2));
  f.normal_verticality = std::abs(solver.eigenvectors()(2, 0));
  return f;
}

std::pair<double, double> horizontalExtent(const Eigen::Matrix3d& covariance) {
  const Eigen::Matrix2d c = covariance.topLeftCorner<2, 2>();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
  solver.computeDirect(c);
  const Eigen::Vector2d ev = solver.eigenvalues().cwiseMax(0.0);
  return {4.0 * std::sqrt(ev(1)), 4.0 * std::sqrt(ev(0))};
}

}  // namespace sgtllc::label
