// Trajectory errors (ATE, RPE, KITTI segments) against hand-computed references, real KISS-ICP odometry against
// an independent computation, and the top-view plot.
#include <cmath>
#include <fstream>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/eval/trajectory_error.h"
#include "sgtllc/eval/trajectory_plot.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/types.h"
#include "test_io_support.h"
#include "test_support.h"
#include "test_trajectory_support.h"

namespace {

using sgtllc::Error;
using sgtllc::eval::ErrorStats;
using Poses = std::vector<Eigen::Isometry3d>;

Eigen::Isometry3d pose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = t;
  return T;
}

Eigen::Matrix3d yaw(double rad) { return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

void expectStats(const ErrorStats& s, double rmse, double mean, double median, double max, double tol) {
  EXPECT_NEAR(s.rmse, rmse, tol);
  EXPECT_NEAR(s.mean, mean, tol);
  EXPECT_NEAR(s.median, median, tol);
  EXPECT_NEAR(s.max, max, tol);
}

TEST(ErrorStats, HandComputed) {
  const ErrorStats even = sgtllc::eval::errorStats({3, 1, 2, 4});
  expectStats(even, std::sqrt(30.0 / 4.0), 2.5, 2.5, 4.0, 1e-15);
  EXPECT_EQ(even.count, 4u);
  EXPECT_EQ(sgtllc::eval::errorStats({5, 1, 2}).median, 2.0);
  EXPECT_EQ(sgtllc::eval::errorStats({}).count, 0u);
}

// Estimate: the square (±1, ±1, 0). Ground truth: the estimate moved by a known rigid T0 (90° yaw, 10 m along x)
// and perturbed by ±d along z in a saddle pattern. The perturbation has no correlation with x or y, so the best
// alignment is T0 itself and every aligned error is d. Unaligned, by hand: GT = (9, 1, d), (11, 1, −d),
// (11, −1, d), (9, −1, −d) against (1, 1, 0), (1, −1, 0), (−1, −1, 0), (−1, 1, 0).
TEST(Ate, SquareWithKnownOffsetAndPerturbation) {
  const double d = 0.1;
  const Eigen::Isometry3d T0 = pose(yaw(M_PI / 2), Eigen::Vector3d(10, 0, 0));
  const std::vector<Eigen::Vector3d> p = {{1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {-1, 1, 0}};
  const double dz[] = {d, -d, d, -d};
  Poses est, gt;
  for (size_t i = 0; i < p.size(); ++i) {
    est.push_back(pose(yaw(0.3 * static_cast<double>(i)), p[i]));  // orientations do not enter the ATE
    gt.push_back(pose(Eigen::Matrix3d::Identity(), T0 * p[i] + Eigen::Vector3d(0, 0, dz[i])));
  }
  const sgtllc::eval::AteResult r = sgtllc::eval::absoluteTrajectoryError(gt, est);
  expectStats(r.aligned, d, d, d, d, 1e-12);
  EXPECT_LE((r.T_gt_est.matrix() - T0.matrix()).cwiseAbs().maxCoeff(), 1e-12);
  const double e[] = {std::sqrt(64 + d * d), std::sqrt(104 + d * d), std::sqrt(144 + d * d), std::sqrt(104 + d * d)};
  const double rmse = std::sqrt((e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]) / 4);
  expectStats(r.unaligned, rmse, (e[0] + e[1] + e[2] + e[3]) / 4, e[1], e[2], 1e-12);
}

// Umeyama against brute force: on noisy random points, no small rigid perturbation of the returned alignment
// lowers the sum of squared errors.
TEST(Ate, AlignmentIsALocalMinimumOfTheSquaredError) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.5);
  const Eigen::Isometry3d T0 = sgtllc::test::randomPose(rng, 50.0);
  std::vector<Eigen::Vector3d> src, dst;
  for (int i = 0; i < 40; ++i) {
    src.push_back(sgtllc::test::randomPose(rng, 20.0).translation());
    dst.push_back(T0 * src.back() + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  const Eigen::Isometry3d T = sgtllc::eval::alignRigid(src, dst);
  const auto cost = [&](const Eigen::Isometry3d& A) {
    double c = 0;
    for (size_t i = 0; i < src.size(); ++i) c += (dst[i] - A * src[i]).squaredNorm();
    return c;
  };
  const double best = cost(T);
  EXPECT_LT((T.linear() - T0.linear()).norm(), 0.05);
  for (int axis = 0; axis < 3; ++axis) {
    for (double step : {-1e-3, 1e-3}) {
      const Eigen::Vector3d u = Eigen::Vector3d::Unit(axis);
      Eigen::Isometry3d rotated = T, shifted = T;
      rotated.linear() = Eigen::AngleAxisd(step, u).toRotationMatrix() * T.linear();
      rotated.translation() = Eigen::AngleAxisd(step, u) * T.translation();
      shifted.translation() += step * u;
      EXPECT_GT(cost(rotated), best);
      EXPECT_GT(cost(shifted), best);
    }
  }
}

// Ground truth: 1 m steps along x. Estimate: each step moves 1.1 m along x and then turns by α. Relative error of
// one step: E = [Rz(α) | (0.1, 0, 0)]. Of two steps: E = [Rz(2α) | (1.1 (1 + cos α) − 2, 1.1 sin α, 0)].
TEST(Rpe, HandComputedOneAndTwoFrameSteps) {
  const double alpha = 2.0 * M_PI / 180.0;
  const Eigen::Isometry3d step = pose(yaw(alpha), Eigen::Vector3d(1.1, 0, 0));
  Poses gt, est = {Eigen::Isometry3d::Identity()};
  for (int i = 0; i < 5; ++i) gt.push_back(pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(i, 0, 0)));
  for (int i = 1; i < 5; ++i) est.push_back(est.back() * step);
  const sgtllc::eval::RpeResult one = sgtllc::eval::relativePoseError(gt, est, 1);
  EXPECT_EQ(one.translation_m.count, 4u);
  expectStats(one.translation_m, 0.1, 0.1, 0.1, 0.1, 1e-12);
  expectStats(one.rotation_deg, 2.0, 2.0, 2.0, 2.0, 1e-12);
  const sgtllc::eval::RpeResult two = sgtllc::eval::relativePoseError(gt, est, 2);
  const double t2 = std::hypot(1.1 * (1 + std::cos(alpha)) - 2, 1.1 * std::sin(alpha));
  EXPECT_EQ(two.translation_m.count, 3u);
  expectStats(two.translation_m, t2, t2, t2, t2, 1e-12);
  expectStats(two.rotation_deg, 4.0, 4.0, 4.0, 4.0, 1e-12);
  EXPECT_THROW(sgtllc::eval::relativePoseError(gt, est, 0), Error);
}

// 300 frames, ground truth in 1 m steps, the estimate 1 % too long per step. A segment of L m from frame f ends at
// frame f + L + 1 (the first strictly farther), so its error is 0.01 (L + 1) m. From every 10th frame: 20 segments
// of 100 m (f ≤ 198) and 10 of 200 m (f ≤ 98): mean of 0.01·101/100 and 0.01·201/200 weighted 20:10.
TEST(KittiSegments, HandComputedScaleDrift) {
  Poses gt, est;
  for (int i = 0; i < 300; ++i) {
    gt.push_back(pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(i, 0, 0)));
    est.push_back(pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.01 * i, 0, 0)));
  }
  const sgtllc::eval::SegmentError s = sgtllc::eval::kittiSegmentError(gt, est);
  EXPECT_EQ(s.segments, 30u);
  EXPECT_NEAR(s.translation_percent, 100.0 * (20 * 0.01 * 101 / 100 + 10 * 0.01 * 201 / 200) / 30, 1e-10);
  EXPECT_NEAR(s.rotation_deg_per_100m, 0.0, 1e-12);
  EXPECT_EQ(sgtllc::eval::kittiSegmentError(gt, est, {1000}).segments, 0u);
}

TEST(TrajectoryError, RotationAngleNearZeroAndPi) {
  EXPECT_NEAR(sgtllc::eval::rotationAngleDeg(yaw(1e-9)), 1e-9 * 180 / M_PI, 1e-20);
  EXPECT_NEAR(sgtllc::eval::rotationAngleDeg(yaw(M_PI - 1e-9)), 180.0 - 1e-9 * 180 / M_PI, 1e-10);
}

TEST(TrajectoryError, CountMismatchThrows) {
  const Poses two = sgtllc::test::randomPoses(2, 1), three = sgtllc::test::randomPoses(3, 1);
  EXPECT_THROW(sgtllc::eval::absoluteTrajectoryError(two, three), Error);
  EXPECT_THROW(sgtllc::eval::relativePoseError(two, three), Error);
  EXPECT_THROW(sgtllc::eval::kittiSegmentError(two, three), Error);
  EXPECT_THROW(sgtllc::eval::absoluteTrajectoryError({}, {}), Error);
}

// KISS-ICP odometry of KITTI 00 frames 0–999 against SemanticKITTI's poses, both in the LiDAR frame (data/README.md).
// Reference values from an independent script (Python, no numpy: Gauss-Jordan inverse of Tr, Horn's quaternion
// alignment by power iteration); on the whole sequence the same two programs give the README's 3.85 m / 6.74 m
// ("Closing the loop on real KITTI 00").
TEST(TrajectoryError, RealKissIcpAgainstSemanticKittiPoses) {
  const std::string dir = sgtllc::test::dataPath("kitti/00/");
  const auto gt = sgtllc::io::readTrajectory(dir + "odometry/semantickitti_poses_first1000.txt", dir + "calib.txt");
  for (const std::string odo : {"kissicp_first1000_kitti.txt", "kissicp_first1000_tum.txt"}) {
    const auto est = sgtllc::io::readTrajectory(dir + "odometry/" + odo, dir + "calib.txt");
    const sgtllc::eval::AteResult r = sgtllc::eval::absoluteTrajectoryError(gt.poses, est.poses);
    SCOPED_TRACE(odo);
    expectStats(r.aligned, 0.544182, 0.510865, 0.487916, 1.197692, 2e-6);
    expectStats(r.unaligned, 1.453910, 1.200383, 0.952555, 2.563211, 2e-6);
  }
}

class TrajectoryPlot : public sgtllc::test::TempDirTest {};

TEST_F(TrajectoryPlot, WritesAPngAndChecksLoopFrames) {
  sgtllc::eval::TrajectoryPlotData data;
  for (int i = 0; i < 50; ++i) {
    const double a = 2 * M_PI * i / 50.0;
    data.ground_truth.push_back(pose(yaw(a), Eigen::Vector3d(20 * std::cos(a), 20 * std::sin(a), 0)));
    data.odometry.push_back(pose(yaw(a), Eigen::Vector3d(21 * std::cos(a), 20 * std::sin(a), 0)));
  }
  data.corrected = data.ground_truth;
  data.loops = {{0, 49, true}, {5, 30, false}};
  data.odometry_ate = {0.812, 1.004};  // legend and title figures: any values draw
  data.corrected_ate = {0.0, 0.0};
  sgtllc::eval::plotTrajectories(path("top.png"), data);
  EXPECT_EQ(sgtllc::test::pngSize(path("top.png")), std::make_pair(1400, 900));
  data.loops.push_back({0, 50, true});
  EXPECT_THAT([&] { sgtllc::eval::plotTrajectories(path("bad.png"), data); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("loop 0 -> 50 names a frame outside")));
  sgtllc::eval::plotTrajectories(path("empty.png"), sgtllc::eval::TrajectoryPlotData{});
  EXPECT_EQ(sgtllc::test::pngSize(path("empty.png")), std::make_pair(1400, 900));
  // The legend gives the ATE the report's table gives, after alignment and as drawn.
  EXPECT_EQ(sgtllc::eval::ateLabel("odometry", {3.8544, 6.7436}), "odometry: ATE 3.854 m aligned, 6.744 m as drawn");
  EXPECT_EQ(sgtllc::eval::ateLabel("corrected", {0.777, -1.0}), "corrected: ATE 0.777 m aligned");
  EXPECT_EQ(sgtllc::eval::ateLabel("corrected", {}), "corrected");
}

}  // namespace
