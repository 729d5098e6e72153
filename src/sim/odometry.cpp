#include "sgtllc/sim/odometry.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "sgtllc/sim/rng.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

/// Standard normal clamped to ±3: the documented bound on every step's error.
double clampedNormal(Rng& rng) { return std::clamp(rng.normal(), -3.0, 3.0); }

Eigen::Matrix4d rigidInverse(const Eigen::Matrix4d& T) {
  Eigen::Matrix4d inv = Eigen::Matrix4d::Identity();
  inv.topLeftCorner<3, 3>() = T.topLeftCorner<3, 3>().transpose();
  inv.topRightCorner<3, 1>() = -inv.topLeftCorner<3, 3>() * T.topRightCorner<3, 1>();
  return inv;
}

void checkSigma(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw Error(std::string("odometry noise ") + name + " must be finite and >= 0, got " + std::to_string(value));
  }
}

}  // namespace

OdometryNoise OdometryNoise::scaled(double factor) {
  if (!std::isfinite(factor) || factor < 0.0) {
    throw Error("odometry drift factor must be finite and >= 0, got " + std::to_string(factor));
  }
  OdometryNoise n;
  n.scale_bias_sigma *= factor;
  n.scale_sigma *= factor;
  n.yaw_walk *= factor;
  return n;
}

std::vector<Eigen::Matrix4d> driftingOdometry(const std::vector<Eigen::Matrix4d>& T_0_i, const OdometryNoise& noise,
                                              uint64_t seed) {
  checkSigma(noise.scale_bias_sigma, "scale_bias_sigma");
  checkSigma(noise.scale_sigma, "scale_sigma");
  checkSigma(noise.yaw_walk, "yaw_walk");
  std::vector<Eigen::Matrix4d> out;
  if (T_0_i.empty()) return out;
  out.reserve(T_0_i.size());
  out.push_back(T_0_i[0]);
  // One sequential stream of its own (Stream::kOdometry): the scans, labels and loop pairs draw from other
  // streams, so adding this output changed none of them.
  Rng rng(seed, Stream::kOdometry);
  const double bias = noise.scale_bias_sigma * clampedNormal(rng);
  for (size_t k = 1; k < T_0_i.size(); ++k) {
    Eigen::Matrix4d step = rigidInverse(T_0_i[k - 1]) * T_0_i[k];  // true motion in the LiDAR frame of k − 1
    // Both numbers are drawn at every step, so the stream position never depends on the motion.
    const double n = clampedNormal(rng), m = clampedNormal(rng);
    const double d = step.topRightCorner<3, 1>().norm();
    step.topRightCorner<3, 1>() *= 1.0 + bias + noise.scale_sigma * n;
    const double yaw = noise.yaw_walk * std::sqrt(d) * m;
    step.topLeftCorner<3, 3>() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                                 step.topLeftCorner<3, 3>();
    out.push_back(out.back() * step);
  }
  return out;
}

}  // namespace sgtllc::sim
