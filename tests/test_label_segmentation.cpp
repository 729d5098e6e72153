// The labeller's voxel segmentation (docs/labeller.md §2) against a brute-force component search: on a real KITTI
// scan, and on tall sparse columns whose heights alias in the neighbour search's filter.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>

#include "sgtllc/io/kitti.h"
#include "sgtllc/label/segmentation.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

// Segments against a brute-force reference: voxels in a std::map, each joined to every occupied voxel of its
// 26-neighbourhood. Two points share a segment iff they share a reference component; returns the segment count.
int expectBruteForceComponents(const std::vector<Eigen::Vector3f>& pts, double leaf) {
  const std::vector<uint8_t> use(pts.size(), 1);
  const label::Segmentation s = label::segmentVoxels(pts, use, leaf);
  std::map<std::array<int, 3>, int> voxel_of;
  std::vector<int> point_voxel(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    const double inv = 1.0 / leaf;  // the cell arithmetic of segmentVoxels, so boundary points agree
    const std::array<int, 3> c = {static_cast<int>(std::floor(pts[i].x() * inv)),
                                  static_cast<int>(std::floor(pts[i].y() * inv)),
                                  static_cast<int>(std::floor(pts[i].z() * inv))};
    point_voxel[i] = voxel_of.emplace(c, static_cast<int>(voxel_of.size())).first->second;
  }
  std::vector<int> parent(voxel_of.size());
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v];
    return v;
  };
  for (const auto& [c, v] : voxel_of) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = voxel_of.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it != voxel_of.end()) parent[root(it->second)] = root(v);
        }
      }
    }
  }
  EXPECT_EQ(s.num_voxels, static_cast<int>(voxel_of.size()));
  // The partitions agree: a one-to-one map between reference roots and segment ids.
  std::map<int, int> segment_of_root, root_of_segment;
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_GE(s.point_voxel[i], 0);
    if (s.point_voxel[i] < 0) return -1;
    const int seg = s.voxel_segment[s.point_voxel[i]], r = root(point_voxel[i]);
    EXPECT_EQ(segment_of_root.emplace(r, seg).first->second, seg) << "point " << i;
    EXPECT_EQ(root_of_segment.emplace(seg, r).first->second, r) << "point " << i;
  }
  EXPECT_EQ(static_cast<int>(segment_of_root.size()), s.num_segments);
  return s.num_segments;
}

TEST(Segmentation, RealScanMatchesBruteForceComponents) {
  const std::vector<Eigen::Vector3f> pts = io::readKittiBin(test::dataPath("kitti/00/velodyne/004501.bin"));
  EXPECT_GT(expectBruteForceComponents(pts, 0.4), 100);  // a real scene, not one blob
}

// The neighbour search answers a column's three heights from one word of 64 bits, a bit per height modulo 64:
// voxels 64 (or 128) heights apart share a bit. Sparse points in tall thin columns, below and above 0, make many
// such aliases, which must cost a probe and never a join.
TEST(Segmentation, TallColumnsMatchBruteForceComponents) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> xy(-0.3f, 0.3f), z(-20.0f, 20.0f);
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i < 1500; ++i) pts.emplace_back(xy(rng), xy(rng), z(rng));
  EXPECT_GT(expectBruteForceComponents(pts, 0.1), 100);
  // Two voxels of neighbouring columns 64 heights apart: the same bit, not neighbours.
  const std::vector<Eigen::Vector3f> aliased = {{0.05f, 0.05f, 0.05f}, {0.15f, 0.05f, 6.45f}, {0.05f, 0.15f, -6.35f}};
  EXPECT_EQ(expectBruteForceComponents(aliased, 0.1), 3);
}

}  // namespace
}  // namespace sgtllc
