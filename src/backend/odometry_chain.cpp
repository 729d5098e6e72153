#include "sgtllc/backend/odometry_chain.h"

namespace sgtllc::backend {

OdometryChain::OdometryChain() : poses_{Eigen::Isometry3d::Identity()}, length_{0.0} {}

void OdometryChain::append(const Eigen::Isometry3d& T_prev_curr) {
  poses_.push_back(poses_.back() * T_prev_curr);
  length_.push_back(length_.back() + T_prev_curr.translation().norm());
}

}  // namespace sgtllc::backend
