/// @file odometry_chain.h
/// @brief The odometry of a frame sequence, chained: relative motion and path length between any two frames.
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace sgtllc::backend {

/// Frames 0..N−1 with frame 0 at the identity; append() adds frame N from the step T_prev_curr.
class OdometryChain {
 public:
  OdometryChain();

  void append(const Eigen::Isometry3d& T_prev_curr);
  int size() const { return static_cast<int>(poses_.size()); }

  /// Odometry estimate of T_a_b (p_a = T_a_b · p_b).
  Eigen::Isometry3d relative(int a, int b) const { return poses_[a].inverse() * poses_[b]; }
  /// Odometry path length between frames a and b (m), in either order.
  double pathLength(int a, int b) const { return a < b ? length_[b] - length_[a] : length_[a] - length_[b]; }
  /// The first frame of the @p spacing-metre stretch of path (measured from frame 0) that holds @p frame: frames
  /// that share a stretch share it, so a standstill never adds one. @p spacing ≤ 0: @p frame itself.
  int stretchStart(int frame, double spacing) const;

 private:
  std::vector<Eigen::Isometry3d> poses_;  ///< T_first_frame
  std::vector<double> length_;            ///< path length from frame 0 (m)
};

}  // namespace sgtllc::backend
