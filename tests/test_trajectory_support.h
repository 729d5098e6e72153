// Shared by the trajectory / g2o / trajectory-error suites: seeded random poses and pose comparison.
#pragma once

#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace sgtllc::test {

/// A random rigid transform: uniform rotation (normalised Gaussian quaternion), translation in ±@p extent m.
inline Eigen::Isometry3d randomPose(std::mt19937& rng, double extent = 100.0) {
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uniform(-extent, extent);
  const Eigen::Quaterniond q = Eigen::Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
  return T;
}

inline std::vector<Eigen::Isometry3d> randomPoses(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Eigen::Isometry3d> poses;
  for (size_t i = 0; i < n; ++i) poses.push_back(randomPose(rng));
  return poses;
}

/// Every entry of the 4×4 matrices within @p tol.
inline void expectPosesNear(const std::vector<Eigen::Isometry3d>& a, const std::vector<Eigen::Isometry3d>& b,
                            double tol) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_LE((a[i].matrix() - b[i].matrix()).cwiseAbs().maxCoeff(), tol) << "pose " << i;
  }
}

}  // namespace sgtllc::test
