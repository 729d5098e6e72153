// The analytic Jacobians of the relative-pose residual against automatic differentiation of the same residual,
// on random poses, measurements and information matrices (fixed seed), from tiny to near-π rotation errors.
#include <gtest/gtest.h>

#include <random>

#include "backend/ceres_pose_graph.h"
#include "backend/se3.h"

namespace sgtllc::backend {
namespace {

Eigen::Isometry3d randomPose(std::mt19937& rng, double angle, double extent) {
  std::normal_distribution<double> n01(0.0, 1.0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d axis = Eigen::Vector3d(n01(rng), n01(rng), n01(rng)).normalized();
  T.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  T.translation() = extent * Eigen::Vector3d(n01(rng), n01(rng), n01(rng));
  return T;
}

Matrix6d randomInformation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix6d A;
  for (int i = 0; i < 36; ++i) A(i) = u(rng);
  return A * A.transpose() + 0.5 * Matrix6d::Identity();
}

double maxAbs(const Matrix6d& m) { return m.cwiseAbs().maxCoeff(); }

TEST(BackendCost, AnalyticJacobiansMatchAutomaticDifferentiation) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  // Rotation error of the edge: ~1e-6 rad (series branch of J_r⁻¹), ~1e-2 rad (a good loop), up to ~3 rad.
  const double error_angles[] = {1e-6, 1e-2, 0.5, 3.0};
  int cases = 0;
  for (const double error_angle : error_angles) {
    for (int k = 0; k < 50; ++k) {
      const Eigen::Isometry3d T_from = randomPose(rng, angle(rng), 100.0);
      const Eigen::Isometry3d T_to = T_from * randomPose(rng, angle(rng), 20.0);
      Edge edge;
      edge.from = 0;
      edge.to = 1;
      // Measured so that Δ = Z⁻¹ T_from⁻¹ T_to has a rotation of error_angle.
      edge.T_from_to = T_from.inverse() * T_to * randomPose(rng, error_angle, 0.5).inverse();
      edge.information = randomInformation(rng);
      const internal::EdgeJacobians a = internal::edgeJacobians(edge, T_from, T_to, false);
      const internal::EdgeJacobians r = internal::edgeJacobians(edge, T_from, T_to, true);
      const double scale = std::max({1.0, maxAbs(r.from), maxAbs(r.to)});
      EXPECT_LT((a.residual - r.residual).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, r.residual.norm()));
      EXPECT_LT(maxAbs(a.from - r.from), 1e-9 * scale) << "angle " << error_angle << " case " << k;
      EXPECT_LT(maxAbs(a.to - r.to), 1e-9 * scale) << "angle " << error_angle << " case " << k;
      ++cases;
    }
  }
  EXPECT_EQ(cases, 200);
}

// The tangent Jacobians are not trivially equal: moving `to` changes the residual (the reference is non-zero and
// depends on the pose), so a sign or frame slip in the analytic form would fail the comparison above.
TEST(BackendCost, JacobiansAreNonTrivial) {
  std::mt19937 rng(42);
  const Eigen::Isometry3d T_from = randomPose(rng, 1.0, 10.0);
  const Eigen::Isometry3d T_to = T_from * randomPose(rng, 0.3, 5.0);
  Edge edge;
  edge.T_from_to = T_from.inverse() * T_to;
  edge.information = Matrix6d::Identity();
  const internal::EdgeJacobians r = internal::edgeJacobians(edge, T_from, T_to, true);
  EXPECT_LT(r.residual.norm(), 1e-9);  // exact measurement
  // At zero error the rotation rows over the `to` rotation are 2 R_toᵀ (half-angle left perturbation).
  const Eigen::Matrix3d expected = 2.0 * T_to.rotation().transpose();
  EXPECT_LT((r.to.bottomLeftCorner<3, 3>() - expected).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((r.from.bottomLeftCorner<3, 3>() + expected).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace sgtllc::backend
