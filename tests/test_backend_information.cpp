// Information matrices: odometry noise model and the loop fit model on hand-computed cases; config validation.
#include <gtest/gtest.h>

#include "sgtllc/backend/information.h"
#include "sgtllc/backend/pose_graph_optimizer.h"
#include "test_backend_support.h"

namespace sgtllc::backend {
namespace {

TEST(BackendInformation, OdometryFromDistanceAndAngle) {
  OdometryNoise noise;
  noise.translation_sigma_per_m = 0.01;
  noise.translation_sigma_min = 0.02;
  noise.rotation_sigma_per_m = 0.001;
  noise.rotation_sigma_per_rad = 0.1;
  noise.rotation_sigma_min = 0.003;
  Eigen::Isometry3d T = test::planarPose({3.0, 4.0, 0.0}, 0.2);  // 5 m, 0.2 rad
  const Matrix6d I = odometryInformation(T, noise);
  const double var_t = 0.02 * 0.02 + 0.05 * 0.05;
  const double var_r = 0.003 * 0.003 + 0.005 * 0.005 + 0.02 * 0.02;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(I(k, k), 1.0 / var_t, 1e-9);
    EXPECT_NEAR(I(k + 3, k + 3), 1.0 / var_r, 1e-6);
  }
  EXPECT_EQ((I - Matrix6d(I.diagonal().asDiagonal())).norm(), 0.0);
}

// Four centres (±a, 0, 0), (0, ±a, 0), fitted exactly: σ = sigma_min, translation block n/σ², no coupling, rotation
// block diag(Σ(y²+z²), Σ(x²+z²), Σ(x²+y²))/σ² = diag(2a², 2a², 4a²)/σ², all times information_scale.
TEST(BackendInformation, LoopFromAnExactFitOfFourCentres) {
  const double a = 10.0;
  const std::vector<Eigen::Vector3d> s = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}};
  const Eigen::Isometry3d T = test::planarPose({1.0, -2.0, 0.5}, 0.7);
  std::vector<Eigen::Vector3d> d;
  for (const auto& p : s) d.push_back(T * p);
  LoopNoise noise;
  noise.sigma_min = 0.2;
  noise.information_scale = 0.5;
  const Matrix6d I = loopInformation(s, d, T, noise);
  const double k = 0.5 / 0.04;
  Matrix6d expected = Matrix6d::Zero();
  expected.diagonal() << 4 * k, 4 * k, 4 * k, 2 * a * a * k, 2 * a * a * k, 4 * a * a * k;
  EXPECT_LT((I - expected).norm(), 1e-9 * expected.norm());
}

// Residuals above the floor set σ: centres displaced by ±r along z give Σ‖r‖² = n r², σ² = n r² / (3n − 6).
TEST(BackendInformation, LoopNoiseFromTheFitResiduals) {
  const double r = 0.5;
  const std::vector<Eigen::Vector3d> s = {{5, 0, 0}, {-5, 0, 0}, {0, 5, 0}, {0, -5, 0}};
  std::vector<Eigen::Vector3d> d = s;
  for (size_t i = 0; i < d.size(); ++i) d[i].z() += (i % 2 == 0 ? r : -r);
  LoopNoise noise;
  noise.sigma_min = 0.01;
  noise.information_scale = 1.0;
  const Matrix6d I = loopInformation(s, d, Eigen::Isometry3d::Identity(), noise);
  const double var = 4 * r * r / 6.0;
  EXPECT_NEAR(I(0, 0), 4.0 / var, 1e-9);
  EXPECT_NEAR(I(5, 5), 4 * 25.0 / var, 1e-9);
}

TEST(BackendInformation, LoopFromADetectorMatchUsesItsInliers) {
  std::vector<Node> query(5), match(5);
  const std::vector<Eigen::Vector3d> centres = {{8, 1, 0}, {-3, 7, 1}, {-6, -5, 0}, {2, -9, 2}, {40, 40, 5}};
  for (int i = 0; i < 5; ++i) {
    query[i].centre = centres[i];
    match[4 - i].centre = centres[i] + Eigen::Vector3d(1.0, 0.0, 0.0);
  }
  MatchResult m;
  for (int i = 0; i < 5; ++i) m.associations.push_back({i, 4 - i, 1.0});
  m.inliers = {0, 1, 2, 3};  // the fifth association is an outlier: it must not count
  m.T_match_query.topRightCorner<3, 1>() = Eigen::Vector3d(1.0, 0.0, 0.0);
  LoopNoise noise;
  const Edge e = loopEdge(7, 90, m, query, match, noise);
  EXPECT_EQ(e.from, 7);
  EXPECT_EQ(e.to, 90);
  EXPECT_EQ(e.kind, EdgeKind::kLoop);
  EXPECT_NEAR(e.information(0, 0), 4 * noise.information_scale / (noise.sigma_min * noise.sigma_min), 1e-9);
  const std::vector<Eigen::Vector3d> s(centres.begin(), centres.begin() + 4);
  std::vector<Eigen::Vector3d> d;
  for (const auto& p : s) d.push_back(p + Eigen::Vector3d(1.0, 0.0, 0.0));
  EXPECT_EQ(e.information, loopInformation(s, d, e.T_from_to, noise));
  m.inliers = {0, 9};
  EXPECT_THROW(loopEdge(7, 90, m, query, match, noise), Error);
}

TEST(BackendInformation, LoopRejectsDegenerateFits) {
  LoopNoise noise;
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_THROW(loopInformation(two, two, I, noise), Error);
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 0, 0}};
  EXPECT_THROW(loopInformation(line, line, I, noise), Error);
  const std::vector<Eigen::Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(loopInformation(three, two, I, noise), Error);
}

void expectBadKey(const BackendConfig& c, const std::string& key) {
  try {
    c.validate();
    ADD_FAILURE() << "no error for " << key;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("backend." + key + " "), std::string::npos) << e.what();
  }
}

TEST(BackendConfig, DefaultsAreValidAndBadValuesNameTheirKey) {
  EXPECT_NO_THROW(BackendConfig{}.validate());
  BackendConfig c;
  c.odometry.translation_sigma_min = 0.0;
  expectBadKey(c, "odometry.translation_sigma_min");
  c = {};
  c.odometry.rotation_sigma_per_rad = -1.0;
  expectBadKey(c, "odometry.rotation_sigma_per_rad");
  c = {};
  c.loops.information_scale = 1.5;
  expectBadKey(c, "loops.information_scale");
  c = {};
  c.loss_scale = std::nan("");
  expectBadKey(c, "loss_scale");
  c = {};
  c.consistency.translation_per_m = -0.1;
  expectBadKey(c, "consistency.translation_per_m");
  c = {};
  c.max_loop_chi2 = 0.0;
  expectBadKey(c, "max_loop_chi2");
  c = {};
  c.solver.num_threads = 0;
  expectBadKey(c, "solver.num_threads");
  EXPECT_THROW(PoseGraphOptimizer{c}, Error);
}

}  // namespace
}  // namespace sgtllc::backend
