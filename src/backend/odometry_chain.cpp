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
  const double start = std::floor(length_[frame] / spacing) * spacing;
  const int first = static_cast<int>(std::lower_bound(length_.begin(), length_.end(), start) - length_.begin());
  return std::min(first, frame);  // rounding in floor() · spacing never moves it past the frame
}

}  // namespace sgtllc::backend
