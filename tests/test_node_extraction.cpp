// Node extraction (algorithm §1–§2): class filtering, per-class minimum sizes, node centres and order, same-class
// duplicate suppression and bookkeeping, on synthetic labelled clouds.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "sgtllc/node_extraction.h"
#include "test_clustering_support.h"

namespace {

using sgtllc::LabeledCloud;
using sgtllc::NodeExtractor;
using namespace sgtllc::test;  // test_clustering_support.h

// --- Synthetic labelled clouds -------------------------------------------------------------------------------------

/// Appends an nu × nv grid of points spaced 0.2 m, starting 0.1 m into the voxel at @p origin along @p u and @p v
/// (so with a 0.4 m leaf every voxel holds 2 × 2 points and no point lies on a voxel face). Returns its points.
Cloud addGrid(LabeledCloud* cloud, uint32_t label, const Eigen::Vector3f& origin, const Eigen::Vector3f& u,
              const Eigen::Vector3f& v, int nu, int nv) {
  Cloud pts;
  for (int a = 0; a < nu; ++a) {
    for (int b = 0; b < nv; ++b) pts.push_back(origin + (0.1f + 0.2f * a) * u + (0.1f + 0.2f * b) * v);
  }
  cloud->points.insert(cloud->points.end(), pts.begin(), pts.end());
  cloud->labels.insert(cloud->labels.end(), pts.size(), label);
  return pts;
}

/// Appends @p n points on a horizontal ring (or a vertical segment when radius is 0).
Cloud addRing(LabeledCloud* cloud, uint32_t label, const Eigen::Vector3f& centre, float radius, int n) {
  Cloud pts;
  for (int k = 0; k < n; ++k) {
    const float a = 2.0f * static_cast<float>(M_PI) * static_cast<float>(k) / static_cast<float>(n);
    pts.push_back(radius > 0 ? centre + Eigen::Vector3f(radius * std::cos(a), radius * std::sin(a), 0.0f)
                             : centre + Eigen::Vector3f(0.0f, 0.0f, 0.1f * static_cast<float>(k)));
  }
  cloud->points.insert(cloud->points.end(), pts.begin(), pts.end());
  cloud->labels.insert(cloud->labels.end(), pts.size(), label);
  return pts;
}

Eigen::Vector3d mean(const Cloud& pts) {
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  for (const auto& p : pts) s += p.cast<double>();
  return s / static_cast<double>(pts.size());
}

/// The node of @p pts as class @p c: its points' mean, at the sensor's height for the upright classes (trunk, pole
/// and traffic-sign by default; algorithm §2).
Eigen::Vector3d nodeAt(const Cloud& pts, int c) {
  Eigen::Vector3d m = mean(pts);
  if (sgtllc::ClusterConfig{}.classes.at(c).centre_height == sgtllc::CentreHeight::kSensor) m.z() = 0.0;
  return m;
}

const Eigen::Vector3f kX = Eigen::Vector3f::UnitX(), kY = Eigen::Vector3f::UnitY(), kZ = Eigen::Vector3f::UnitZ();

sgtllc::NodeExtractionResult extract(const LabeledCloud& cloud, const sgtllc::ClusterConfig& config = {}) {
  return NodeExtractor(config, sgtllc::LabelConfig{}).extract(cloud);
}

// --- NodeExtractor -------------------------------------------------------------------------------------------------

TEST(NodeExtractor, TwoBuildingBlobsWithBookkeeping) {
  LabeledCloud cloud;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // Wall B comes first in the cloud, so it is the first cluster and the first node. 50 × 20 points = 250 voxels.
  const Cloud wall_b = addGrid(&cloud, 50, {20.0f, -6.0f, 0.0f}, kX, kZ, 50, 20);
  cloud.points.insert(cloud.points.end(), {{nan, 0, 0}, {0, inf, 0}, {1, 2, -inf}});
  cloud.labels.insert(cloud.labels.end(), {50, 50, 70});
  addGrid(&cloud, 40, {0.0f, 0.0f, -2.0f}, kX, kY, 40, 40);  // road: dropped, not counted anywhere
  cloud.points.insert(cloud.points.end(), 4, Eigen::Vector3f(1, 1, 1));
  cloud.labels.insert(cloud.labels.end(), {12345, 2, 12345, 2});  // unknown ids
  const Cloud wall_a = addGrid(&cloud, (7u << 16) | 50u, {0.0f, 10.0f, 0.0f}, kX, kZ, 50, 20);
  addRing(&cloud, 80, {5.0f, 5.0f, 0.0f}, 0.0f, 19);  // a pole one point short of min_size 20

  const auto result = extract(cloud);
  ASSERT_EQ(result.nodes.size(), 2u);
  EXPECT_EQ(result.nodes[0].label, sgtllc::kBuilding);
  EXPECT_EQ(result.nodes[1].label, sgtllc::kBuilding);
  EXPECT_LT((result.nodes[0].centre - mean(wall_b)).norm(), 1e-9);
  EXPECT_LT((result.nodes[1].centre - mean(wall_a)).norm(), 1e-9);

  const auto& st = result.stats;
  EXPECT_EQ(st.input_points, cloud.points.size());
  EXPECT_EQ(st.nonfinite_points, 3u);
  EXPECT_EQ(st.unknown_label_points, 4u);
  EXPECT_EQ(st.class_points[sgtllc::kBuilding], 2000u);
  EXPECT_EQ(st.class_points[sgtllc::kPole], 19u);
  for (int c : {1, 2, 3, 4, 6}) EXPECT_EQ(st.class_points[c], 0u) << c;
  EXPECT_EQ(st.clusters[sgtllc::kBuilding], 2);
  EXPECT_EQ(st.clusters[sgtllc::kPole], 0);
  EXPECT_EQ(st.duplicates_suppressed, 0);
}

TEST(NodeExtractor, MinSizeCountsVoxelsOrPoints) {
  // Building: 40 × 20 grid = 200 voxels (kept); 38 × 20 = 190 voxels of 760 points (dropped: voxels count).
  LabeledCloud cloud;
  addGrid(&cloud, 50, {0, 0, 0}, kX, kZ, 40, 20);
  addGrid(&cloud, 50, {0, 20, 0}, kX, kZ, 38, 20);
  // Poles (not downsampled): 20 points kept, 19 dropped.
  const Cloud pole20 = addRing(&cloud, 80, {30, 0, 0}, 0.0f, 20);
  addRing(&cloud, 80, {30, 20, 0}, 0.0f, 19);
  const auto result = extract(cloud);
  ASSERT_EQ(result.nodes.size(), 2u);
  EXPECT_EQ(result.nodes[0].label, sgtllc::kBuilding);
  EXPECT_NEAR(result.nodes[0].centre.y(), 0.0, 1e-6);
  EXPECT_EQ(result.nodes[1].label, sgtllc::kPole);
  EXPECT_LT((result.nodes[1].centre - nodeAt(pole20, sgtllc::kPole)).norm(), 1e-9);
  EXPECT_EQ(result.stats.clusters[sgtllc::kBuilding], 1);
  EXPECT_EQ(result.stats.clusters[sgtllc::kPole], 1);
}

TEST(NodeExtractor, NodeOrderIsClassOrder) {
  // Classes appear in the cloud in reverse order; nodes must come out building … traffic-sign.
  LabeledCloud cloud;
  std::vector<Cloud> by_class(sgtllc::kNumPaperClasses);
  by_class[6] = addGrid(&cloud, 81, {60, 0, 2}, kX, kZ, 5, 5);            // traffic-sign, 25 points
  by_class[5] = addRing(&cloud, 80, {50, 0, 0}, 0.0f, 25);               // pole
  by_class[4] = addGrid(&cloud, 72, {0, 30, -1.8f}, kX, kY, 40, 40);     // terrain, 400 voxels
  by_class[3] = addRing(&cloud, 71, {40, 0, 0}, 0.0f, 25);               // trunk
  by_class[2] = addGrid(&cloud, 70, {0, -20, 0}, kX, kZ, 40, 20);        // vegetation, 200 voxels
  by_class[1] = addGrid(&cloud, 51, {0, 10, 0}, kX, kZ, 50, 2);          // fence, 25 voxels
  by_class[0] = addGrid(&cloud, 50, {0, 0, 0}, kX, kZ, 50, 20);          // building, 250 voxels
  const auto result = extract(cloud);
  ASSERT_EQ(result.nodes.size(), 7u);
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) {
    EXPECT_EQ(result.nodes[c].label, c);
    EXPECT_LT((result.nodes[c].centre - nodeAt(by_class[c], c)).norm(), 1e-9) << sgtllc::kClassNames[c];
    EXPECT_EQ(result.stats.class_points[c], by_class[c].size());
    EXPECT_EQ(result.stats.clusters[c], 1);
  }
}

TEST(NodeExtractor, AnUprightObjectsNodeIsAtTheSensorsHeight) {
  // One pole (x = 12, y = 3) seen over two stretches of its height, as from two places: 1.9 m of it from 1.5 m
  // below the sensor, and 2.4 m of it from 0.5 m below (the foot behind a car, more of the top in view). By
  // default the node is where its axis crosses the sensor's plane, the same in both; at its points' mean height
  // (centre_height: points) the two nodes lie 1.25 m apart, beyond any inlier bound (algorithm §2).
  const auto poleFrom = [](float bottom, int n) {
    LabeledCloud cloud;
    addRing(&cloud, 80, {12.0f, 3.0f, bottom}, 0.0f, n);
    return cloud;
  };
  const LabeledCloud low = poleFrom(-1.5f, 20), high = poleFrom(-0.5f, 25);
  const auto a = extract(low), b = extract(high);
  ASSERT_EQ(a.nodes.size(), 1u);
  ASSERT_EQ(b.nodes.size(), 1u);
  EXPECT_LT((a.nodes[0].centre - Eigen::Vector3d(12.0, 3.0, 0.0)).norm(), 1e-6);
  EXPECT_LT((b.nodes[0].centre - Eigen::Vector3d(12.0, 3.0, 0.0)).norm(), 1e-6);
  sgtllc::ClusterConfig config;
  config.classes[sgtllc::kPole].centre_height = sgtllc::CentreHeight::kPoints;
  const auto pa = extract(low, config), pb = extract(high, config);
  EXPECT_NEAR(pa.nodes[0].centre.z(), -1.5 + 0.95, 1e-6);  // 20 points 0.1 m apart from −1.5 m
  EXPECT_NEAR(pb.nodes[0].centre.z(), -0.5 + 1.2, 1e-6);   // 25 from −0.5 m
  EXPECT_NEAR((pa.nodes[0].centre - pb.nodes[0].centre).norm(), 1.25, 1e-6);
  // The defaults: the upright classes at the sensor's height, the others at their points' mean.
  EXPECT_EQ(sgtllc::ClusterConfig{}.classes[sgtllc::kBuilding].centre_height, sgtllc::CentreHeight::kPoints);
  EXPECT_EQ(sgtllc::ClusterConfig{}.classes[sgtllc::kTrunk].centre_height, sgtllc::CentreHeight::kSensor);
  EXPECT_EQ(sgtllc::ClusterConfig{}.classes[sgtllc::kTrafficSign].centre_height, sgtllc::CentreHeight::kSensor);
}

TEST(NodeExtractor, CentreSourcePointsOrVoxels) {
  // A wall plus 300 extra points packed into its first voxel: the point mean moves, the voxel mean barely does.
  LabeledCloud cloud;
  Cloud all = addGrid(&cloud, 50, {0, 0, 0}, kX, kZ, 50, 20);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.05f, 0.35f);
  for (int k = 0; k < 300; ++k) {
    all.emplace_back(u(rng), 0.0f, u(rng));
    cloud.points.push_back(all.back());
    cloud.labels.push_back(50);
  }
  sgtllc::ClusterConfig config;
  config.centre = sgtllc::CentreSource::kPoints;
  const auto by_points = extract(cloud, config);
  config.centre = sgtllc::CentreSource::kVoxels;
  const auto by_voxels = extract(cloud, config);
  ASSERT_EQ(by_points.nodes.size(), 1u);
  ASSERT_EQ(by_voxels.nodes.size(), 1u);
  EXPECT_LT((by_points.nodes[0].centre - mean(all)).norm(), 1e-9);
  const RefVoxels ref = voxelReference(all, 0.4);
  Eigen::Vector3d voxel_mean = Eigen::Vector3d::Zero();
  for (size_t v = 0; v < ref.sums.size(); ++v) voxel_mean += ref.sums[v] / ref.counts[v];
  voxel_mean /= static_cast<double>(ref.sums.size());
  EXPECT_LT((by_voxels.nodes[0].centre - voxel_mean).norm(), 1e-5);
  EXPECT_GT((by_points.nodes[0].centre - by_voxels.nodes[0].centre).norm(), 0.5);
}

TEST(NodeExtractor, SameClassDuplicatesSuppressed) {
  // Concentric trunk rings (r = 0.3 m and 1.6 m: 1.3 m apart, so two FEC clusters) share a centre; the second
  // (outer) cluster is suppressed. A pole at the same place is another class and stays.
  LabeledCloud cloud;
  const Cloud inner = addRing(&cloud, 71, {5, 5, 0}, 0.3f, 20);
  addRing(&cloud, 71, {5, 5, 0}, 1.6f, 40);
  const Cloud pole = addRing(&cloud, 80, {5, 5, -0.5f}, 0.0f, 20);
  const auto result = extract(cloud);
  ASSERT_EQ(result.nodes.size(), 2u);
  EXPECT_EQ(result.nodes[0].label, sgtllc::kTrunk);
  EXPECT_LT((result.nodes[0].centre - nodeAt(inner, sgtllc::kTrunk)).norm(), 1e-9);
  EXPECT_EQ(result.nodes[1].label, sgtllc::kPole);
  EXPECT_LT((result.nodes[1].centre - nodeAt(pole, sgtllc::kPole)).norm(), 1e-9);
  EXPECT_EQ(result.stats.clusters[sgtllc::kTrunk], 2);
  EXPECT_EQ(result.stats.duplicates_suppressed, 1);
}

TEST(NodeExtractor, DuplicateRadiusIsConfigurable) {
  // Rings whose centres are 0.8 m apart (r = 0.3 m at x = 5, r = 2.5 m at x = 5.8; ≥ 1.4 m apart, not connected).
  LabeledCloud cloud;
  const Cloud inner = addRing(&cloud, 71, {5, 5, 0}, 0.3f, 20);
  const Cloud outer = addRing(&cloud, 71, {5.8f, 5, 0}, 2.5f, 64);
  sgtllc::ClusterConfig config;
  const auto suppressed = extract(cloud, config);  // duplicate_radius 1.0 m
  ASSERT_EQ(suppressed.nodes.size(), 1u);
  EXPECT_LT((suppressed.nodes[0].centre - nodeAt(inner, sgtllc::kTrunk)).norm(), 1e-9);
  EXPECT_EQ(suppressed.stats.duplicates_suppressed, 1);
  config.duplicate_radius = 0.5;
  const auto kept = extract(cloud, config);
  ASSERT_EQ(kept.nodes.size(), 2u);
  EXPECT_LT((kept.nodes[1].centre - nodeAt(outer, sgtllc::kTrunk)).norm(), 1e-9);
  EXPECT_EQ(kept.stats.duplicates_suppressed, 0);
}

TEST(NodeExtractor, MaxNodesKeepsTheClustersWithTheMostPoints) {
  // Poles of 30, 50, 20 and 50 points, then a 25-voxel (100-point) fence: with max_nodes = 3 the 20-point pole
  // and, of the tied 30/50, the 30-point one go; the kept nodes stay in node order (fence first: class order).
  LabeledCloud cloud;
  addRing(&cloud, 80, {0, 0, 0}, 0.0f, 30);
  const Cloud p50a = addRing(&cloud, 80, {10, 0, 0}, 0.0f, 50);
  addRing(&cloud, 80, {20, 0, 0}, 0.0f, 20);
  const Cloud p50b = addRing(&cloud, 80, {30, 0, 0}, 0.0f, 50);
  const Cloud fence = addGrid(&cloud, 51, {0, 10, 0}, kX, kZ, 50, 2);
  const auto all = NodeExtractor({}, {}, 5).extract(cloud);
  ASSERT_EQ(all.nodes.size(), 5u);  // at the limit: nothing dropped
  EXPECT_EQ(all.stats.capped_nodes, 0);
  const auto capped = NodeExtractor({}, {}, 3).extract(cloud);
  ASSERT_EQ(capped.nodes.size(), 3u);
  EXPECT_EQ(capped.stats.capped_nodes, 2);
  EXPECT_LT((capped.nodes[0].centre - mean(fence)).norm(), 1e-9);
  EXPECT_LT((capped.nodes[1].centre - nodeAt(p50a, sgtllc::kPole)).norm(), 1e-9);
  EXPECT_LT((capped.nodes[2].centre - nodeAt(p50b, sgtllc::kPole)).norm(), 1e-9);
  // A tie at the cut goes to the earlier node: of the two 50-point poles, max_nodes = 2 keeps the first.
  const auto two = NodeExtractor({}, {}, 2).extract(cloud);
  ASSERT_EQ(two.nodes.size(), 2u);
  EXPECT_LT((two.nodes[1].centre - nodeAt(p50a, sgtllc::kPole)).norm(), 1e-9);
  EXPECT_EQ(NodeExtractor({}, {}, 0).extract(cloud).nodes.size(), 5u);  // 0 = no limit
}

TEST(NodeExtractor, MismatchedLengthsThrowAndEmptyCloudGivesNoNodes) {
  LabeledCloud cloud;
  cloud.points.assign(3, Eigen::Vector3f::Zero());
  cloud.labels.assign(2, 50);
  EXPECT_THROW(extract(cloud), sgtllc::Error);
  const auto result = extract(LabeledCloud{});
  EXPECT_TRUE(result.nodes.empty());
  EXPECT_EQ(result.stats.input_points, 0u);
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) EXPECT_EQ(result.stats.clusters[c], 0);
}

TEST(NodeExtractor, SameNodesAndStatsAtAnyThreadCount) {
  // Every class present, several clusters each, in random point order: classes clustered in parallel (largest
  // first) must merge back into exactly the single-thread nodes, centres to the bit.
  LabeledCloud cloud;
  const uint32_t labels[] = {50, 51, 70, 71, 72, 80, 81};
  for (int c = 0; c < 7; ++c) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3f origin(20.0f * static_cast<float>(k), 10.0f * static_cast<float>(c), 0.0f);
      if (c == 3 || c == 5 || c == 6) {
        addRing(&cloud, labels[c], origin, 0.0f, 40 + 10 * k);
      } else {
        addGrid(&cloud, labels[c], origin, kX, kZ, 30 + 5 * c, 20);
      }
    }
  }
  std::mt19937 rng(13);
  std::vector<size_t> perm(cloud.points.size());
  for (size_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::shuffle(perm.begin(), perm.end(), rng);
  LabeledCloud shuffled;
  for (size_t i : perm) {
    shuffled.points.push_back(cloud.points[i]);
    shuffled.labels.push_back(cloud.labels[i]);
  }
  sgtllc::ClusterConfig config;
  for (auto& c : config.classes) c.min_size = 5;
  const auto one = NodeExtractor(config, {}, 0, 1).extract(shuffled);
  for (int c = 0; c < 7; ++c) ASSERT_GE(one.stats.clusters[c], 3) << c;  // every class clustered
  for (int threads : {2, 3, 8}) {
    const auto many = NodeExtractor(config, {}, 0, threads).extract(shuffled);
    ASSERT_EQ(many.nodes.size(), one.nodes.size()) << threads;
    for (size_t k = 0; k < one.nodes.size(); ++k) {
      EXPECT_EQ(many.nodes[k].label, one.nodes[k].label);
      EXPECT_EQ(many.nodes[k].centre, one.nodes[k].centre);  // bitwise: same sums in the same order
    }
    EXPECT_EQ(many.stats.clusters, one.stats.clusters);
    EXPECT_EQ(many.stats.class_points, one.stats.class_points);
  }
}

TEST(NodeExtractor, OutOfBoundsPointsAreCountedAndChangeNoNode) {
  // A scan whose coordinates are all finite and within ±kMaxCoordinate takes the class split without a per-point
  // bound test; one bad point sends it through the tested split. Both must give the same nodes, to the bit.
  LabeledCloud cloud;
  addGrid(&cloud, 50, {0, 0, 0}, kX, kZ, 40, 25);
  addGrid(&cloud, 70, {8, 3, 0}, kY, kZ, 30, 30);
  addRing(&cloud, 71, {-6, 2, 0}, 0.0f, 40);
  addRing(&cloud, 80, {3, -7, 0}, 0.0f, 30);
  cloud.points.emplace_back(1.0f, 2.0f, 3.0f);
  cloud.labels.push_back(12345);  // unknown id
  sgtllc::ClusterConfig config;
  for (auto& c : config.classes) c.min_size = 5;
  const auto clean = NodeExtractor(config, {}).extract(cloud);
  ASSERT_EQ(clean.nodes.size(), 4u);
  EXPECT_EQ(clean.stats.unknown_label_points, 1u);
  EXPECT_EQ(clean.stats.nonfinite_points + clean.stats.far_points, 0u);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const Eigen::Vector3f bad[] = {{nan, 0, 0}, {0, -inf, 0}, {0, 0, 2.0e6f}, {-1.5e6f, 0, 0}, {0, 1.0e6f, 0}};
  for (const Eigen::Vector3f& p : bad) {
    cloud.points.insert(cloud.points.begin() + 7, p);  // among the building's points
    cloud.labels.insert(cloud.labels.begin() + 7, 50);
  }
  const auto dirty = NodeExtractor(config, {}).extract(cloud);
  EXPECT_EQ(dirty.stats.nonfinite_points, 2u);
  EXPECT_EQ(dirty.stats.far_points, 2u);  // ±1e6 m itself is within bounds
  EXPECT_EQ(dirty.stats.class_points[0], clean.stats.class_points[0] + 1);
  ASSERT_EQ(dirty.nodes.size(), clean.nodes.size());  // the lone point at 1e6 m is below min_size
  for (size_t k = 0; k < clean.nodes.size(); ++k) {
    EXPECT_EQ(dirty.nodes[k].label, clean.nodes[k].label);
    EXPECT_EQ(dirty.nodes[k].centre, clean.nodes[k].centre);  // bitwise
  }
}

TEST(NodeExtractor, InvalidClassParametersThrowFromParallelClustering) {
  // A ClusterConfig that never went through Config::validate: the error of a worker thread reaches the caller.
  LabeledCloud cloud;
  addGrid(&cloud, 50, {0, 0, 0}, kX, kZ, 10, 10);
  addRing(&cloud, 80, {5, 0, 0}, 0.0f, 30);
  sgtllc::ClusterConfig config;
  config.classes[5].radius = 0.0;  // pole
  EXPECT_THROW(NodeExtractor(config, {}, 0, 2).extract(cloud), std::invalid_argument);
  EXPECT_THROW(NodeExtractor(config, {}, 0, 1).extract(cloud), std::invalid_argument);
}

}  // namespace
