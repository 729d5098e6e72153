/// @file rigid_inverse.h
/// @brief The inverse of a rigid 4 × 4 pose (internal): the checks that compare two frames both ways under one
///        pose (the seen-through check, the covisible score) turn it around with it.
#pragma once

#include <Eigen/Core>

namespace sgtllc::internal {

/// [Rᵀ, −Rᵀ t]: exact for a rotation R, without a general 4 × 4 inverse.
inline Eigen::Matrix4d rigidInverse(const Eigen::Matrix4d& T) {
  Eigen::Matrix4d inverse = Eigen::Matrix4d::Identity();
  inverse.topLeftCorner<3, 3>() = T.topLeftCorner<3, 3>().transpose();
  inverse.topRightCorner<3, 1>() = -inverse.topLeftCorner<3, 3>() * T.topRightCorner<3, 1>();
  return inverse;
}

}  // namespace sgtllc::internal
