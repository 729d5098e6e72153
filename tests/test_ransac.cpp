// Rigid fitting and RANSAC (algorithm §7.2, §7.5): closed-form fits against known transforms and exhaustive
// references, RANSAC at known outlier ratios.
#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "sgtllc/ransac.h"
#include "test_support.h"

namespace {

using Points = std::vector<Eigen::Vector3d>;
using sgtllc::test::apply;
using sgtllc::test::makeT;

Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

Points randomPoints(std::mt19937& rng, int n, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  Points pts(n);
  for (auto& p : pts) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return pts;
}

double cost(const Eigen::Matrix4d& T, const Points& src, const Points& dst) {
  double c = 0.0;
  for (size_t k = 0; k < src.size(); ++k) c += (apply(T, src[k]) - dst[k]).squaredNorm();
  return c;
}

void expectProperRotation(const Eigen::Matrix4d& T) {
  const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
  EXPECT_NEAR(R.determinant(), 1.0, 1e-9);
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  EXPECT_EQ(T.row(3), Eigen::RowVector4d(0, 0, 0, 1));
}

/// 30 exact correspondences and 18 gross outliers (moved 5–20 m), shuffled; *inliers gets the true inlier indices.
void makeCorrespondences(uint32_t seed, const Eigen::Matrix4d& T, Points* src, Points* dst, std::vector<int>* inliers) {
  std::mt19937 rng(seed);
  *src = randomPoints(rng, 48, 40.0);
  std::vector<int> order(48);
  for (int k = 0; k < 48; ++k) order[k] = k;
  std::shuffle(order.begin(), order.end(), rng);
  inliers->assign(order.begin(), order.begin() + 30);
  std::sort(inliers->begin(), inliers->end());
  std::uniform_real_distribution<double> len(5.0, 20.0);
  dst->clear();
  for (int k = 0; k < 48; ++k) {
    const bool in = std::binary_search(inliers->begin(), inliers->end(), k);
    const Eigen::Vector3d off =
        in ? Eigen::Vector3d::Zero() : Eigen::Vector3d(randomPoints(rng, 1, 1.0)[0].normalized() * len(rng));
    dst->push_back(apply(T, (*src)[k]) + off);
  }
}

// --- (a) fitRigid --------------------------------------------------------------------------------------------------

TEST(FitRigid, RecoversKnownTransformExactly) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix4d T = makeT(randomRotation(rng), randomPoints(rng, 1, 50.0)[0]);
    const bool planar = trial % 2 == 1;
    Points src = randomPoints(rng, 3 + trial, 30.0);
    if (planar) {
      for (auto& p : src) p.z() = 0.0;  // a rank-2 cross-covariance: the reflection trap of plain Kabsch
    }
    Points dst;
    for (const auto& p : src) dst.push_back(apply(T, p));
    const Eigen::Matrix4d fit = sgtllc::fitRigid(src, dst);
    EXPECT_LT((fit - T).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
    expectProperRotation(fit);
  }
}

TEST(FitRigid, MirroredPlanarInputGivesTheRotationNotTheReflection) {
  // (x, y, 0) → (−x, y, 0) is both the reflection diag(−1, 1, 1) and the rotation diag(−1, 1, −1) on this plane.
  std::mt19937 rng(2);
  Points src = randomPoints(rng, 12, 10.0), dst;
  for (auto& p : src) {
    p.z() = 0.0;
    dst.emplace_back(-p.x(), p.y(), 0.0);
  }
  const Eigen::Matrix4d fit = sgtllc::fitRigid(src, dst);
  expectProperRotation(fit);
  EXPECT_LT(cost(fit, src, dst), 1e-18);
  EXPECT_LT((fit.topLeftCorner<3, 3>() - Eigen::Vector3d(-1, 1, -1).asDiagonal().toDenseMatrix()).norm(), 1e-9);
}

TEST(FitRigid, MirroredInputGivesTheBestRotation) {
  // No rotation maps a 3-D point set onto its mirror image: the result must still be a rotation, and no worse than
  // any of 2000 random rotations (each with its optimal translation, the centroid difference).
  std::mt19937 rng(3);
  const Points src = randomPoints(rng, 15, 10.0);
  Points dst;
  for (const auto& p : src) dst.emplace_back(-p.x() + 3.0, p.y(), p.z());
  const Eigen::Matrix4d fit = sgtllc::fitRigid(src, dst);
  expectProperRotation(fit);
  Eigen::Vector3d mu_s = Eigen::Vector3d::Zero(), mu_t = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < src.size(); ++k) {
    mu_s += src[k] / static_cast<double>(src.size());
    mu_t += dst[k] / static_cast<double>(dst.size());
  }
  const double best = cost(fit, src, dst);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Matrix3d R = randomRotation(rng);
    ASSERT_LE(best, cost(makeT(R, mu_t - R * mu_s), src, dst) + 1e-9);
  }
}

// --- (b) ransacRigid -----------------------------------------------------------------------------------------------

TEST(Ransac, RecoversTransformAndInlierSet) {
  std::mt19937 rng(10);
  const Eigen::Matrix4d T = makeT(randomRotation(rng), Eigen::Vector3d(12.0, -4.0, 1.5));
  Points src, dst;
  std::vector<int> truth;
  makeCorrespondences(11, T, &src, &dst, &truth);
  // 3 with replacement is the default: minimal samples with the distance check before the fit.
  for (const auto& [with_replacement, size] : {std::pair{false, 3}, std::pair{true, 3}, std::pair{true, 7}}) {
    SCOPED_TRACE(std::to_string(size) + (with_replacement ? " with replacement" : " distinct"));
    sgtllc::RansacParams params;
    params.with_replacement = with_replacement;
    params.sample_size = size;
    const auto result = sgtllc::ransacRigid(src, dst, params);
    EXPECT_TRUE(result.accepted);
    EXPECT_EQ(result.inliers, truth);
    EXPECT_LT((result.T_target_source - T).cwiseAbs().maxCoeff(), 1e-6);
    expectProperRotation(result.T_target_source);
    // Same seed, same answer; another seed still finds the same inliers.
    const auto again = sgtllc::ransacRigid(src, dst, params);
    EXPECT_EQ(again.inliers, result.inliers);
    EXPECT_EQ(again.T_target_source, result.T_target_source);
    params.seed = 12345;
    EXPECT_EQ(sgtllc::ransacRigid(src, dst, params).inliers, truth);
  }
}

TEST(Ransac, AcceptanceNeedsMinInliersAndFraction) {
  std::mt19937 rng(20);
  const Eigen::Matrix4d T = makeT(randomRotation(rng), Eigen::Vector3d(1.0, 2.0, 3.0));
  Points src, dst;
  std::vector<int> truth;
  makeCorrespondences(21, T, &src, &dst, &truth);
  const auto accepted = [&](int min_inliers, double fraction) {
    sgtllc::RansacParams params;
    params.min_inliers = min_inliers;
    params.min_inlier_fraction = fraction;
    return sgtllc::ransacRigid(src, dst, params).accepted;
  };
  EXPECT_TRUE(accepted(30, 0.01));   // 30 inliers ≥ 30
  EXPECT_FALSE(accepted(31, 0.01));
  EXPECT_TRUE(accepted(5, 0.625));   // 30 / 48 = 0.625 exactly
  EXPECT_FALSE(accepted(5, 0.626));
  EXPECT_FALSE(accepted(31, 0.5));
}

TEST(Ransac, AdaptiveStopNeverCutsALowInlierSearchShort) {
  // 300 pairs, half of them outliers: an all-inlier sample of 7 (with replacement) has probability 1/128, so the
  // adaptive bound exceeds 500 and the search must run exactly as with confidence 1. An early, poor hypothesis
  // (1–2 inliers: all-inlier probability ~1e-16) must not end it either (log(1 − p) underflow).
  std::mt19937 rng(30);
  std::uniform_real_distribution<double> u(-40.0, 40.0);
  const Eigen::Matrix4d T = makeT(randomRotation(rng), Eigen::Vector3d(3.0, -1.0, 0.5));
  Points src, dst;
  for (int k = 0; k < 300; ++k) {
    src.emplace_back(u(rng), u(rng), u(rng));
    dst.push_back(k % 2 == 0 ? Eigen::Vector3d(T.topLeftCorner<3, 3>() * src.back() + T.topRightCorner<3, 1>())
                             : Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  int found = 0;
  for (uint32_t seed = 0; seed < 40; ++seed) {
    sgtllc::RansacParams adaptive;
    adaptive.seed = seed;
    sgtllc::RansacParams exhaustive = adaptive;
    exhaustive.confidence = 1.0;
    const auto a = sgtllc::ransacRigid(src, dst, adaptive);
    const auto b = sgtllc::ransacRigid(src, dst, exhaustive);
    EXPECT_EQ(a.inliers, b.inliers) << "seed " << seed;
    found += a.inliers.size() >= 150;
  }
  EXPECT_GE(found, 35);  // 500 draws find an all-inlier sample with probability 0.98
}

TEST(Ransac, MinimalSampleCheckSkipsOnlySamplesThatCannotBeAllInliers) {
  // An equilateral triangle of side 10 m matched to one whose sides are longer by d. The best rigid fit leaves each
  // vertex d / √3 from its target (analytic). d = 0.5: residual 0.289 m < 0.4 m, so all three are inliers, although
  // every pair's distances differ by 0.5 m; the check before the fit (skip at 2 × 0.4 m or more) must let that
  // sample through. d = 0.85: the distances differ by 0.85 ≥ 0.8, the sample is skipped, and rightly: its fit would
  // leave 0.491 m > 0.4 m.
  std::mt19937 rng(50);
  const Eigen::Matrix4d T = makeT(randomRotation(rng), Eigen::Vector3d(4.0, -3.0, 1.0));
  const auto triangle = [](double side) {
    const double r = side / std::sqrt(3.0);  // circumradius
    Points p;
    for (int k = 0; k < 3; ++k) p.emplace_back(r * std::cos(2.0 * M_PI * k / 3), r * std::sin(2.0 * M_PI * k / 3), 0.0);
    return p;
  };
  const Points src = triangle(10.0);
  for (const double d : {0.5, 0.85}) {
    SCOPED_TRACE("sides longer by " + std::to_string(d));
    Points dst;
    for (const auto& p : triangle(10.0 + d)) dst.push_back(apply(T, p));
    const Eigen::Matrix4d fit = sgtllc::fitRigid(src, dst);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((apply(fit, src[k]) - dst[k]).norm(), d / std::sqrt(3.0), 1e-9);
    sgtllc::RansacParams params;  // with replacement, 0.4 m
    params.sample_size = 3;       // as VerificationConfig
    params.min_inliers = 3;
    const auto r = sgtllc::ransacRigid(src, dst, params);
    EXPECT_EQ(r.accepted, d < 0.8);
    // Samples that repeat a pair fit two points only and are not checked against a third: at most 2 inliers.
    EXPECT_EQ(r.inliers.size() == 3, d < 0.8);
  }
}

TEST(Ransac, MaxTiltSkipsUpsideDownFitsOfFlatScenes) {
  // Objects on flat ground (z = 0) and their mirror image across the x axis, (x, −y, 0): the rotation of 180° about x
  // maps every point exactly onto its partner, so without the check RANSAC accepts that upside-down fit with all
  // inliers; with max_tilt 30° no rotation fits them (a mirror image is no rigid motion within the plane).
  const Points src = {{3, 1, 0}, {7, -2, 0}, {-4, 5, 0}, {0, -6, 0}, {9, 8, 0}};
  Points mirrored;
  for (const auto& p : src) mirrored.emplace_back(p.x(), -p.y(), 0.0);
  sgtllc::RansacParams params;
  params.sample_size = 3;
  params.min_inliers = 3;
  // Distinct pairs: a sample that repeats a pair fits two points only, and its free turn about their line could
  // land within the bound by chance.
  params.with_replacement = false;
  const auto off = sgtllc::ransacRigid(src, mirrored, params);
  ASSERT_TRUE(off.accepted);
  EXPECT_EQ(off.inliers.size(), src.size());
  EXPECT_NEAR(off.T_target_source(2, 2), -1.0, 1e-9);  // z turned upside down
  params.max_tilt = 30.0 * M_PI / 180.0;
  EXPECT_FALSE(sgtllc::ransacRigid(src, mirrored, params).accepted);
  // An upright motion tilted by 29° is kept and one by 31° is not: the bound is on the angle between R·z and z.
  for (const double tilt_deg : {29.0, 31.0}) {
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(tilt_deg * M_PI / 180.0, Eigen::Vector3d(1, 1, 0).normalized()))
                                  .toRotationMatrix();
    const Eigen::Matrix4d T = makeT(R, Eigen::Vector3d(2, -1, 0.5));
    Points dst;
    for (const auto& p : src) dst.push_back(apply(T, p));
    const auto r = sgtllc::ransacRigid(src, dst, params);
    EXPECT_EQ(r.accepted, tilt_deg < 30.0) << tilt_deg;
    if (r.accepted) {
      EXPECT_LT((r.T_target_source - T).cwiseAbs().maxCoeff(), 1e-9);
    }
  }
}

}  // namespace
