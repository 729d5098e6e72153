#include "sgtllc/backend/odometry_chain.h"

#include <algorithm>
#include <cmath>

namespace sgtllc::backend {

OdometryChain::OdometryChain() : poses_{Eigen::Isometry3d::Identity()}, length_{0.0} {}

void OdometryChain::append(const Eigen::Isometry3d& T_prev_curr) {
  poses_.push_back(poses_.back() * T_prev_curr);
  length_.push_back(length_.back() + T_prev_curr.translation().norm());
}

int OdometryChain::stretchStart(int frame, double spacing) const {
  if (!(spacing > 0.0)) return frame;
  // Compare stretch numbers, not lengths, so that rounding cannot split the frames of one stretch.
  const double stretch = std::floor(length_[frame] / spacing);
  const auto first = std::partition_point(length_.begin(), length_.begin() + frame,
                                          [&](double length) { return std::floor(length / spacing) < stretch; });
  return static_cast<int>(first - length_.begin());
}

}  // namespace sgtllc::backend
