/// @file shape_features.h
/// @brief Shape of a point set from the eigenvalues λ1 ≥ λ2 ≥ λ3 of its covariance: linearity (λ1 − λ2)/λ1,
///        planarity (λ2 − λ3)/λ1, scattering λ3/λ1 (they sum to 1), and how vertical its main axis and its normal
///        are (Demantké et al., "Dimensionality based scale selection in 3D lidar point clouds", ISPRS 2011;
///        docs/labeller.md §3).
#pragma once

#include <utility>

#include <Eigen/Core>

namespace sgtllc::label {

/// Running first and second moments of points, in double, relative to a reference point (the first point added)
/// so that far-away sets keep their precision.
class Moments {
 public:
  /// Inline: called for every non-ground point. The outer product is symmetric, so its six distinct products are
  /// each added to both mirrored entries (the same sums as d dᵀ, in fewer multiplications).
  void add(const Eigen::Vector3f& p) {
    const Eigen::Vector3d q = p.cast<double>();
    if (count_ == 0) origin_ = q;
    const Eigen::Vector3d d = q - origin_;
    ++count_;
    sum_ += d;
    const double xx = d.x() * d.x(), xy = d.x() * d.y(), xz = d.x() * d.z();
    const double yy = d.y() * d.y(), yz = d.y() * d.z(), zz = d.z() * d.z();
    outer_(0, 0) += xx;
    outer_(0, 1) += xy;
    outer_(0, 2) += xz;
    outer_(1, 0) += xy;
    outer_(1, 1) += yy;
    outer_(1, 2) += yz;
    outer_(2, 0) += xz;
    outer_(2, 1) += yz;
    outer_(2, 2) += zz;
  }
  void merge(const Moments& other);
  long count() const { return count_; }
  Eigen::Vector3d mean() const;
  /// Population covariance (m²); zero for fewer than two points.
  Eigen::Matrix3d covariance() const;

 private:
  long count_ = 0;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer_ = Eigen::Matrix3d::Zero();
};

struct ShapeFeatures {
  double linearity = 0.0;   ///< (λ1 − λ2)/λ1: 1 for a line
  double planarity = 0.0;   ///< (λ2 − λ3)/λ1: 1 for an isotropic plane
  double scattering = 0.0;  ///< λ3/λ1: 1 for an isotropic blob
  /// |z| of the main axis e1: 1 for a vertical line (pole), 0 for a horizontal one.
  double axis_verticality = 0.0;
  /// |z| of the normal e3: 0 for a vertical plane (wall), 1 for a horizontal one (ground, roof).
  double normal_verticality = 0.0;
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();  ///< λ1 ≥ λ2 ≥ λ3 (m²)
};

/// Features of a covariance. A zero covariance (one point, or all points in one place) has all features 0.
ShapeFeatures shapeFeatures(const Eigen::Matrix3d& covariance);

/// 4 standard deviations of a covariance's horizontal (x, y) spread along its major and its minor axis (m): the
/// length and width of a uniform bar, whatever its heading.
std::pair<double, double> horizontalExtent(const Eigen::Matrix3d& covariance);

}  // namespace sgtllc::label
