// The class split of node extraction (src/internal/class_split.h): a scan cut into fixed index ranges, split in
// parallel and joined per class, equals one pass over the whole scan per class (voxelDownsample of the class's points,
// or the points in scan order), with the same bookkeeping, at any thread count.
#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "internal/class_split.h"
#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"

namespace {

using sgtllc::LabeledCloud;
using sgtllc::internal::ClassSplit;

// SemanticKITTI ids of the seven stable classes (building … traffic-sign), a dropped class (road) and an unknown id.
constexpr uint32_t kStable[] = {50, 51, 70, 71, 72, 80, 81};
constexpr uint32_t kRoad = 40;
constexpr uint32_t kUnknown = 12345;

/// @p n points in a 6 m cube at random, with a stable class for most, road or an unknown id for the rest. With
/// @p dyadic the coordinates are multiples of 1/64 m, so every voxel sum is exact in any order of addition.
LabeledCloud randomScan(size_t n, bool dyadic, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coord(-3.0f, 3.0f);
  std::uniform_int_distribution<int> label(0, 8);
  LabeledCloud cloud;
  for (size_t i = 0; i < n; ++i) {
    Eigen::Vector3f p(coord(rng), coord(rng), coord(rng));
    if (dyadic) p = (p * 64.0f).array().round().matrix() / 64.0f;
    const int l = label(rng);
    cloud.points.push_back(p);
    cloud.labels.push_back(l < 7 ? kStable[l] : (l == 7 ? kRoad : kUnknown));
  }
  return cloud;
}

/// Class c's points in scan order, by brute force.
std::vector<Eigen::Vector3f> classPoints(const LabeledCloud& cloud, int c) {
  std::vector<Eigen::Vector3f> out;
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (cloud.labels[i] == kStable[c] && cloud.points[i].allFinite()) out.push_back(cloud.points[i]);
  }
  return out;
}

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return std::memcmp(a.data(), b.data(), 24) == 0; }

sgtllc::ClusterConfig mixedLeaves() {
  sgtllc::ClusterConfig config;  // trunk, pole and traffic-sign are not downsampled by default
  config.classes[0].voxel = 0.5;
  config.classes[2].voxel = 0.3;
  return config;
}

TEST(ClassSplit, EqualsOnePassPerClassAndCountsEveryPoint) {
  const LabeledCloud cloud = randomScan(20000, true, 5);  // every voxel of the 6 m cube gets points of both halves
  const sgtllc::ClusterConfig config = mixedLeaves();
  const sgtllc::LabelMap labels{sgtllc::LabelConfig{}};
  for (int threads : {1, 2}) {
    sgtllc::ExtractionStats stats;
    ClassSplit split(cloud, labels, config, threads, stats);
    size_t kept = 0, unknown = 0;
    for (uint32_t l : cloud.labels) unknown += l == kUnknown ? 1 : 0;
    for (int c = 0; c < 7; ++c) {
      const std::vector<Eigen::Vector3f> reference = classPoints(cloud, c);
      kept += reference.size();
      EXPECT_EQ(stats.class_points[c], reference.size()) << c;
      ASSERT_EQ(split.voxelized(c), config.classes[c].voxel > 0.0) << c;
      if (!split.voxelized(c)) {
        EXPECT_EQ(split.points(c), reference) << c;
        continue;
      }
      const sgtllc::VoxelizedCloud expected = sgtllc::voxelDownsample(reference, config.classes[c].voxel);
      const sgtllc::VoxelizedCloud got = split.voxels(c);
      ASSERT_GT(expected.counts.size(), 100u) << c;
      ASSERT_EQ(got.counts, expected.counts) << c;  // same voxels in the same order of first appearance
      for (size_t v = 0; v < expected.sums.size(); ++v) {
        ASSERT_TRUE(sameBits(got.sums[v], expected.sums[v])) << c << " voxel " << v;
        ASSERT_EQ(got.centroids[v], expected.centroids[v]) << c << " voxel " << v;
      }
    }
    size_t road = 0;
    for (uint32_t l : cloud.labels) road += l == kRoad ? 1 : 0;
    EXPECT_EQ(kept + road + unknown, cloud.points.size());  // every point kept by one class or dropped
    EXPECT_EQ(stats.unknown_label_points, unknown);
    EXPECT_EQ(stats.nonfinite_points + stats.far_points, 0u);
  }
}

TEST(ClassSplit, BitIdenticalAtAnyThreadCountOnInexactSums) {
  // Coordinates with full float mantissas: a range's sums then the ranges joined can round differently from one
  // pass, so what matters is that the ranges never depend on the thread count.
  const LabeledCloud cloud = randomScan(15001, false, 9);
  const sgtllc::ClusterConfig config = mixedLeaves();
  const sgtllc::LabelMap labels{sgtllc::LabelConfig{}};
  sgtllc::ExtractionStats s1, s2;
  ClassSplit one(cloud, labels, config, 1, s1);
  ClassSplit two(cloud, labels, config, 2, s2);
  EXPECT_EQ(s1.class_points, s2.class_points);
  for (int c : {0, 2, 1, 4}) {
    const sgtllc::VoxelizedCloud a = one.voxels(c), b = two.voxels(c);
    ASSERT_EQ(a.counts, b.counts) << c;
    for (size_t v = 0; v < a.sums.size(); ++v) ASSERT_TRUE(sameBits(a.sums[v], b.sums[v])) << c << " voxel " << v;
    // And equal to one pass up to rounding: a sum of at most a few hundred floats below 3 m.
    const sgtllc::VoxelizedCloud ref = sgtllc::voxelDownsample(classPoints(cloud, c), config.classes[c].voxel);
    ASSERT_EQ(a.counts, ref.counts) << c;
    for (size_t v = 0; v < a.sums.size(); ++v) ASSERT_LT((a.sums[v] - ref.sums[v]).norm(), 1e-9) << c;
  }
}

TEST(ClassSplit, BadPointsInOneRangeAreCountedAndSkipped) {
  LabeledCloud cloud = randomScan(4000, true, 3);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.points[3500] = Eigen::Vector3f(nan, 0.0f, 0.0f);  // second range only: it alone takes the checked path
  cloud.points[3600] = Eigen::Vector3f(0.0f, 2.0e6f, 0.0f);
  cloud.labels[3500] = cloud.labels[3600] = kStable[0];
  const sgtllc::ClusterConfig config = mixedLeaves();
  sgtllc::ExtractionStats stats;
  ClassSplit split(cloud, sgtllc::LabelMap{sgtllc::LabelConfig{}}, config, 2, stats);
  EXPECT_EQ(stats.nonfinite_points, 1u);
  EXPECT_EQ(stats.far_points, 1u);
  std::vector<Eigen::Vector3f> building = classPoints(cloud, 0);
  building.erase(std::remove_if(building.begin(), building.end(), [](const auto& p) { return p.y() > 1.0e6f; }),
                 building.end());
  EXPECT_EQ(stats.class_points[0], building.size());
  EXPECT_EQ(split.voxels(0).counts, sgtllc::voxelDownsample(building, 0.5).counts);
}

TEST(VoxelAccumulator, AbsorbingTheLaterPointsEqualsOneAccumulator) {
  const LabeledCloud cloud = randomScan(3000, true, 11);
  sgtllc::internal::VoxelAccumulator all(0.4, 64), first(0.4, 64), later(0.4, 64);
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    all.add(cloud.points[i]);
    (i < 1234 ? first : later).add(cloud.points[i]);
  }
  first.absorb(later);
  const sgtllc::VoxelizedCloud a = std::move(all).finish(), b = std::move(first).finish();
  ASSERT_EQ(a.counts, b.counts);
  for (size_t v = 0; v < a.sums.size(); ++v) ASSERT_TRUE(sameBits(a.sums[v], b.sums[v])) << v;
  EXPECT_EQ(a.centroids, b.centroids);
}

}  // namespace
