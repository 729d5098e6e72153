// The kd-tree of fine registration (include/sgtllc/point_kdtree.h) against brute force on random points: the
// nearest point, the k nearest, and the nearest within a bound (points exactly at the bound included, beyond it not;
// among tied points the same one as nearest()).
#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sgtllc/point_kdtree.h"

namespace {

using sgtllc::PointKdTree;

float squared(const float* a, const float* b) {
  float s = 0.0f;
  for (int d = 0; d < 3; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
  return s;
}

TEST(PointKdTree, NearestKnnAndNearestWithinEqualBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
  std::vector<float> xyz(3 * 2000);
  for (float& v : xyz) v = coordinate(rng);
  // Ties: every tenth point repeats the one before it, so a nearest point often has a twin at the same distance.
  for (int i = 10; i < 2000; i += 10) std::copy_n(&xyz[3 * (i - 1)], 3, &xyz[3 * i]);
  const PointKdTree tree(&xyz);
  std::vector<uint32_t> near;
  for (int q = 0; q < 300; ++q) {
    const float query[3] = {coordinate(rng), coordinate(rng), coordinate(rng)};
    std::vector<std::pair<float, int>> all;
    for (int i = 0; i < 2000; ++i) all.emplace_back(squared(query, &xyz[3 * i]), i);
    std::sort(all.begin(), all.end());
    const auto [j, d2] = tree.nearest(query);
    EXPECT_EQ(d2, all[0].first);
    EXPECT_EQ(squared(query, &xyz[3 * j]), all[0].first);
    tree.knn(query, 5, &near);
    ASSERT_EQ(near.size(), 5u);
    for (int k = 0; k < 5; ++k) EXPECT_EQ(squared(query, &xyz[3 * near[k]]), all[k].first);
    for (double bound : {0.0, 0.25, 1.0, 4.0, 1e300}) {
      const auto [w, wd2] = tree.nearestWithin(query, bound);
      if (static_cast<double>(all[0].first) <= bound) {
        EXPECT_EQ(w, j) << bound;  // the same point as nearest()
        EXPECT_EQ(wd2, d2);
      } else {
        EXPECT_EQ(w, -1) << bound;
        EXPECT_EQ(wd2, std::numeric_limits<float>::infinity());
      }
    }
    // A bound exactly at the nearest distance admits it; the next smaller double does not.
    const double at = static_cast<double>(all[0].first);
    EXPECT_EQ(tree.nearestWithin(query, at).first, j);
    if (at > 0.0) {
      EXPECT_EQ(tree.nearestWithin(query, std::nextafter(at, 0.0)).first, -1);
    }
  }
  EXPECT_EQ(tree.nearestWithin(xyz.data(), -1.0).first, -1);  // a negative bound admits nothing
  const std::vector<float> none;
  const PointKdTree empty(&none);
  EXPECT_EQ(empty.nearestWithin(xyz.data(), 1.0).first, -1);
  EXPECT_EQ(empty.nearest(xyz.data()).first, -1);
}

}  // namespace
