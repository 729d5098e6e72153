// The reduced graph of the online step (docs/backend.md, "Online"): a loop carried from its endpoints to the anchors
// before them keeps its meaning — its composed transform and its covariance match a Monte Carlo of the noisy
// odometry and loop — and a loop between two anchors is left as it is.
#include <gtest/gtest.h>

#include <random>

#include "backend/ceres_pose_graph.h"
#include "backend/reduced_graph.h"
#include "backend/se3.h"
#include "sgtllc/backend/odometry_chain.h"
#include "sgtllc/backend/pose_graph_optimizer.h"

namespace sgtllc::backend {
namespace {

using internal::Vector6d;

Matrix6d randomCovariance(std::mt19937& rng, double t_sigma, double r_sigma) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix6d A;
  for (int i = 0; i < 36; ++i) A(i) = u(rng);
  Matrix6d S = A * A.transpose() / 6.0 + 0.2 * Matrix6d::Identity();
  Vector6d scale;
  scale << Eigen::Vector3d::Constant(t_sigma), Eigen::Vector3d::Constant(r_sigma);
  return scale.asDiagonal() * S * scale.asDiagonal();
}

Vector6d sample(std::mt19937& rng, const Eigen::LLT<Matrix6d>& chol) {
  std::normal_distribution<double> n01(0.0, 1.0);
  Vector6d z;
  for (int i = 0; i < 6; ++i) z(i) = n01(rng);
  return chol.matrixL() * z;
}

Eigen::Isometry3d step(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = internal::expSO3(Eigen::Vector3d(0.02 * u(rng), 0.02 * u(rng), 0.3 * u(rng)));
  T.translation() = Eigen::Vector3d(1.0 + 0.3 * u(rng), 0.2 * u(rng), 0.05 * u(rng));
  return T;
}

struct Chain {
  std::vector<Edge> odometry;
  std::vector<Matrix6d> covariance;
};

Chain randomChain(std::mt19937& rng, int frames) {
  Chain c;
  for (int i = 1; i < frames; ++i) {
    Edge e;
    e.from = i - 1;
    e.to = i;
    e.T_from_to = step(rng);
    c.covariance.push_back(randomCovariance(rng, 0.02, 0.002));
    e.information = c.covariance.back().inverse();
    c.odometry.push_back(e);
  }
  return c;
}

Eigen::Isometry3d compose(const std::vector<Eigen::Isometry3d>& steps, int a, int b) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int i = a + 1; i <= b; ++i) T = T * steps[i - 1];
  return T;
}

// T_a_b of the chain of steps, either way round.
Eigen::Isometry3d relative(const std::vector<Eigen::Isometry3d>& steps, int a, int b) {
  return a <= b ? compose(steps, a, b) : compose(steps, b, a).inverse();
}

// Carries loop f → g of a 20-frame chain with anchors 0, 5, 12, 19 and checks the carried edge against sampling:
// its anchors, its transform (the pieces composed) and its covariance.
void checkCarriedLoop(int f, int g, int expected_from, int expected_to) {
  std::mt19937 rng(17);
  const Chain chain = randomChain(rng, 20);
  const internal::ReducedGraph reduced = internal::reduceOdometry(chain.odometry, chain.covariance, {5, 12});
  ASSERT_EQ(reduced.anchors, (std::vector<int>{0, 5, 12, 19}));

  Edge loop;
  loop.from = f;
  loop.to = g;
  loop.T_from_to = step(rng) * step(rng);
  const Matrix6d loop_covariance = randomCovariance(rng, 0.1, 0.01);
  loop.information = loop_covariance.inverse();
  loop.kind = EdgeKind::kLoop;
  const Edge carried = internal::carryLoop(reduced, loop);
  ASSERT_EQ(carried.from, expected_from);
  ASSERT_EQ(carried.to, expected_to);
  EXPECT_EQ(carried.kind, EdgeKind::kLoop);
  const int A = reduced.anchors[carried.from], B = reduced.anchors[carried.to];

  std::vector<Eigen::Isometry3d> nominal;
  std::vector<Eigen::LLT<Matrix6d>> chol;
  for (size_t i = 0; i < chain.odometry.size(); ++i) {
    nominal.push_back(chain.odometry[i].T_from_to);
    chol.emplace_back(chain.covariance[i]);
  }
  const Eigen::Isometry3d expected = relative(nominal, A, f) * loop.T_from_to * relative(nominal, B, g).inverse();
  EXPECT_LT((carried.T_from_to.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-12);

  // Sample the odometry steps and the loop, compose, and take the error's covariance at the carried edge.
  const Eigen::LLT<Matrix6d> loop_chol(loop_covariance);
  const int samples = 40000;
  Matrix6d second = Matrix6d::Zero();
  Vector6d first = Vector6d::Zero();
  for (int s = 0; s < samples; ++s) {
    std::vector<Eigen::Isometry3d> noisy = nominal;
    for (size_t i = 0; i < noisy.size(); ++i) noisy[i] = internal::retract(noisy[i], sample(rng, chol[i]));
    const Eigen::Isometry3d Z = internal::retract(loop.T_from_to, sample(rng, loop_chol));
    const Eigen::Isometry3d T_A_B = relative(noisy, A, f) * Z * relative(noisy, B, g).inverse();
    const Vector6d e = internal::edgeError(carried, Eigen::Isometry3d::Identity(), T_A_B);
    first += e;
    second += e * e.transpose();
  }
  const Vector6d mean = first / samples;
  const Matrix6d sampled = second / samples - mean * mean.transpose();
  const Matrix6d predicted = carried.information.inverse();
  // Compare in the predicted covariance's own units: its whitened sample covariance is the identity up to the
  // sampling error (about 1/√samples per entry) and the first-order error of the composition.
  const Eigen::LLT<Matrix6d> predicted_chol(predicted);
  const Matrix6d L_inv = predicted_chol.matrixL().solve(Matrix6d::Identity());
  const Matrix6d whitened = L_inv * sampled * L_inv.transpose();
  EXPECT_LT((whitened - Matrix6d::Identity()).cwiseAbs().maxCoeff(), 0.04) << whitened;
  // Without the odometry pieces the covariance is clearly too small: the test can tell.
  const Matrix6d loop_only_whitened = L_inv * loop_covariance * L_inv.transpose();
  EXPECT_GT((loop_only_whitened - Matrix6d::Identity()).cwiseAbs().maxCoeff(), 0.2);
}

// 7 is 2 steps after anchor 5 and 15 is 3 steps after anchor 12: both carried back.
TEST(BackendReduced, LoopCarriedBackMatchesAMonteCarloOfItsPieces) { checkCarriedLoop(7, 15, 1, 2); }

// 10 is 2 steps before anchor 12 and 17 is 2 steps before anchor 19: both carried forward.
TEST(BackendReduced, LoopCarriedForwardMatchesAMonteCarloOfItsPieces) { checkCarriedLoop(10, 17, 2, 3); }

// 10 and 13 would both go to anchor 12: then the earlier goes back (to 5) and the later forward (to 19).
TEST(BackendReduced, LoopNeverJoinsAnAnchorToItself) { checkCarriedLoop(10, 13, 1, 3); }

TEST(BackendReduced, LoopBetweenAnchorsIsOnlyReindexed) {
  std::mt19937 rng(5);
  const Chain chain = randomChain(rng, 10);
  const internal::ReducedGraph reduced = internal::reduceOdometry(chain.odometry, chain.covariance, {3, 7});
  Edge loop;
  loop.from = 3;
  loop.to = 7;
  loop.T_from_to = step(rng);
  loop.information = randomCovariance(rng, 0.1, 0.01).inverse();
  const Edge carried = internal::carryLoop(reduced, loop);
  EXPECT_EQ(carried.from, 1);
  EXPECT_EQ(carried.to, 2);
  EXPECT_TRUE(carried.T_from_to.isApprox(loop.T_from_to, 0.0));
  EXPECT_EQ(carried.information, loop.information);
  EXPECT_EQ(reduced.indexAtOrBefore(6), 1);
  EXPECT_EQ(reduced.indexAtOrBefore(7), 2);
  EXPECT_EQ(reduced.indexAtOrBefore(9), 3);
}

TEST(BackendReduced, StretchStartIsTheFirstFrameOfItsStretchOfPath) {
  OdometryChain chain;
  Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
  move.translation().x() = 2.0;
  for (int i = 0; i < 3; ++i) chain.append(move);                         // frames 1-3 at 2, 4, 6 m
  for (int i = 0; i < 4; ++i) chain.append(Eigen::Isometry3d::Identity());  // frames 4-7 stand at 6 m
  chain.append(move);                                                     // frame 8 at 8 m
  EXPECT_EQ(chain.stretchStart(0, 5.0), 0);
  EXPECT_EQ(chain.stretchStart(2, 5.0), 0);  // 4 m: the first stretch
  EXPECT_EQ(chain.stretchStart(3, 5.0), 3);  // 6 m
  EXPECT_EQ(chain.stretchStart(7, 5.0), 3);  // standing still keeps the stretch
  EXPECT_EQ(chain.stretchStart(8, 5.0), 3);
  EXPECT_EQ(chain.stretchStart(8, 0.0), 8);
}

// A loop whose two endpoints fall in one stretch of path (a slow revisit) does not join an anchor to itself: the
// stretch's anchor is one endpoint and the loop reaches the other through the newest frame, here the other one.
TEST(BackendReduced, LoopWithinOneStretchStillSolves) {
  BackendConfig config;
  config.online.anchor_spacing_m = 10.0;
  PoseGraphOptimizer optimizer(config);
  Eigen::Isometry3d creep = Eigen::Isometry3d::Identity();
  creep.translation().x() = 0.05;
  creep.linear() = internal::expSO3(Eigen::Vector3d(0.0, 0.0, 2.0 * M_PI / 80.0));
  for (int i = 0; i < 80; ++i) optimizer.addOdometry(creep);  // a 4 m circle back to the start
  Edge loop;
  loop.from = 0;
  loop.to = 80;
  loop.T_from_to = Eigen::Isometry3d::Identity();
  loop.information = 1e4 * Matrix6d::Identity();
  loop.kind = EdgeKind::kLoop;
  const BackendResult& r = optimizer.closeLoop(loop);
  EXPECT_EQ(r.num_accepted, 1);
  EXPECT_TRUE(r.reduced);
  EXPECT_EQ(r.num_poses_solved, 2);
  EXPECT_LT(r.loops[0].chi2, 1e-6);
}

}  // namespace
}  // namespace sgtllc::backend
