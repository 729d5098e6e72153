// The simulator's drifting odometry (sim/odometry.h): frame 0 is the truth, every step is the true motion with
// a bounded scale and yaw error, the drift over a path matches the model's analytic variance, and the result
// depends on the seed alone.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/sim/odometry.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

Eigen::Matrix4d pose(double yaw, double pitch, double roll, const Eigen::Vector3d& t) {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  T.topRightCorner<3, 1>() = t;
  return T;
}

/// A curving, hilly drive of @p n frames in frame 0's coordinates, standing still for frames 40–49.
std::vector<Eigen::Matrix4d> drive(int n) {
  std::vector<Eigen::Matrix4d> T;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  double yaw = 0.0;
  for (int i = 0; i < n; ++i) {
    if (i > 0 && (i < 40 || i >= 50)) {
      yaw += 0.02 * std::sin(0.05 * i);
      p += (0.5 + 0.4 * std::sin(0.01 * i)) * Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0.02 * std::cos(0.1 * i));
    }
    T.push_back(pose(yaw, 0.01 * std::sin(0.07 * i), 0.005 * std::cos(0.03 * i), p));
  }
  const Eigen::Matrix4d to_0 = T[0].inverse();
  for (Eigen::Matrix4d& m : T) m = to_0 * m;
  return T;
}

Eigen::Matrix4d step(const std::vector<Eigen::Matrix4d>& T, size_t k) { return T[k - 1].inverse() * T[k]; }

TEST(SimOdometry, FrameZeroIsTheTruthAndEveryStepIsTheTrueMotionWithinTheNoiseBounds) {
  const std::vector<Eigen::Matrix4d> truth = drive(300);
  const OdometryNoise noise;
  const std::vector<Eigen::Matrix4d> odo = driftingOdometry(truth, noise, 5);
  ASSERT_EQ(odo.size(), truth.size());
  EXPECT_EQ(odo[0], truth[0]);
  const double max_scale = 3.0 * noise.scale_bias_sigma + 3.0 * noise.scale_sigma;
  double largest_scale = 0.0, largest_yaw_ratio = 0.0;
  for (size_t k = 1; k < truth.size(); ++k) {
    const Eigen::Matrix4d g = step(truth, k), o = step(odo, k);
    const Eigen::Vector3d tg = g.topRightCorner<3, 1>(), to = o.topRightCorner<3, 1>();
    // The residual rotation o·gᵀ is a rotation about z of at most 3 σ_ψ √d: roll and pitch stay exact.
    const Eigen::Matrix3d residual = o.topLeftCorner<3, 3>() * g.topLeftCorner<3, 3>().transpose();
    const double yaw = std::atan2(residual(1, 0), residual(0, 0));
    EXPECT_TRUE(residual.isApprox(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-9)) << k;
    const double d = tg.norm();
    EXPECT_LE(std::abs(yaw), 3.0 * noise.yaw_walk * std::sqrt(d) + 1e-12) << k;
    if (d < 1e-9) {
      EXPECT_LT(to.norm(), 1e-9) << k;  // standing still: no motion and no drift
      EXPECT_LT(std::abs(yaw), 1e-9) << k;
      continue;
    }
    // Translation: the true direction, scaled by 1 + b + σ_s n with |b| ≤ 3 σ_b and |n| ≤ 3.
    EXPECT_LT(to.normalized().cross(tg.normalized()).norm(), 1e-9) << k;
    EXPECT_GT(to.dot(tg), 0.0) << k;
    const double scale = to.norm() / d - 1.0;
    EXPECT_LE(std::abs(scale), max_scale + 1e-9) << k;
    largest_scale = std::max(largest_scale, std::abs(scale));
    largest_yaw_ratio = std::max(largest_yaw_ratio, std::abs(yaw) / (noise.yaw_walk * std::sqrt(d)));
  }
  EXPECT_GT(largest_scale, noise.scale_sigma);  // the noise is there, at the size documented
  EXPECT_GT(largest_yaw_ratio, 1.5);
}

TEST(SimOdometry, ZeroNoiseIsTheTruth) {
  const std::vector<Eigen::Matrix4d> truth = drive(200);
  const std::vector<Eigen::Matrix4d> odo = driftingOdometry(truth, OdometryNoise::scaled(0.0), 9);
  for (size_t i = 0; i < truth.size(); ++i) EXPECT_TRUE(odo[i].isApprox(truth[i], 1e-9)) << i;
}

TEST(SimOdometry, DriftOverAKilometreMatchesTheModel) {
  // 1,000 steps of 1 m straight ahead. To first order the end-point error is Σ_i ψ_i (N − i) across the track
  // and b·N + σ_s Σ n_i along it, so E‖e‖² = c (σ_ψ² Σ (N − i)² + σ_b² N² + σ_s² N), c = 0.9950 the
  // variance of a standard normal clamped to ±3. The RMS over 300 seeds must be within 12 % of that (about 4 standard errors).
  const int n = 1001;
  std::vector<Eigen::Matrix4d> truth;
  for (int i = 0; i < n; ++i) truth.push_back(pose(0.0, 0.0, 0.0, Eigen::Vector3d(i, 0.0, 0.0)));
  const OdometryNoise noise;
  double sum_sq = 0.0, lateral_sum = 0.0;
  for (int i = 1; i < n; ++i) lateral_sum += std::pow(n - 1 - i, 2);
  const double expected = std::sqrt(0.9950 * (noise.yaw_walk * noise.yaw_walk * lateral_sum +
                                              std::pow(noise.scale_bias_sigma * (n - 1), 2) +
                                              noise.scale_sigma * noise.scale_sigma * (n - 1)));
  const int seeds = 300;
  for (int seed = 0; seed < seeds; ++seed) {
    const Eigen::Matrix4d end = driftingOdometry(truth, noise, static_cast<uint64_t>(seed)).back();
    sum_sq += (end.topRightCorner<3, 1>() - truth.back().topRightCorner<3, 1>()).squaredNorm();
  }
  const double rms = std::sqrt(sum_sq / seeds);
  EXPECT_NEAR(rms, expected, 0.12 * expected);
  // The documented size: about 2 % of the distance driven at 1 km.
  EXPECT_GT(rms / 1000.0, 0.015);
  EXPECT_LT(rms / 1000.0, 0.027);
}

TEST(SimOdometry, TheSeedAloneDecides) {
  const std::vector<Eigen::Matrix4d> truth = drive(300);
  const std::vector<Eigen::Matrix4d> a = driftingOdometry(truth, OdometryNoise{}, 11);
  const std::vector<Eigen::Matrix4d> b = driftingOdometry(truth, OdometryNoise{}, 11);
  const std::vector<Eigen::Matrix4d> c = driftingOdometry(truth, OdometryNoise{}, 12);
  EXPECT_EQ(a, b);
  EXPECT_GT((a.back().topRightCorner<3, 1>() - c.back().topRightCorner<3, 1>()).norm(), 1e-3);
}

TEST(SimOdometry, RejectsNegativeOrNonFiniteNoise) {
  EXPECT_THROW(OdometryNoise::scaled(-1.0), Error);
  EXPECT_THROW(OdometryNoise::scaled(std::nan("")), Error);
  OdometryNoise bad;
  bad.yaw_walk = -0.1;
  EXPECT_THROW(driftingOdometry(drive(3), bad, 1), Error);
  EXPECT_TRUE(driftingOdometry({}, OdometryNoise{}, 1).empty());
}

}  // namespace
}  // namespace sgtllc::sim
