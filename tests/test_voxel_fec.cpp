// Voxel downsampling and FEC (algorithm §1–§2), against brute-force references on synthetic clouds.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "internal/fec_search.h"
#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"
#include "test_clustering_support.h"

namespace {

using Clusters = std::vector<std::vector<uint32_t>>;
using sgtllc::fastEuclideanClustering;
using namespace sgtllc::test;  // test_clustering_support.h

// --- Brute-force references ----------------------------------------------------------------------------------------

struct UnionFind {
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) { return parent[x] == x ? x : parent[x] = find(parent[x]); }
  void unite(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
  std::vector<uint32_t> parent;
};

/// Components as clusters ordered by their smallest index, members ascending, those below min_size removed.
Clusters groups(UnionFind& uf, int min_size) {
  std::map<uint32_t, size_t> slot_of_root;
  Clusters out;
  for (uint32_t i = 0; i < uf.parent.size(); ++i) {
    const auto [it, added] = slot_of_root.emplace(uf.find(i), out.size());
    if (added) out.emplace_back();
    out[it->second].push_back(i);
  }
  Clusters kept;
  for (auto& c : out) {
    if (static_cast<int>(c.size()) >= min_size) kept.push_back(std::move(c));
  }
  return kept;
}

/// Squared distance as the library computes it (float), so the two agree on pairs at the radius.
float dist2(const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return (a - b).squaredNorm(); }

/// O(n²) connected components over the edges d ≤ r.
Clusters connectedComponents(const Cloud& pts, double r, int min_size) {
  const float r2 = static_cast<float>(r * r);
  UnionFind uf(pts.size());
  for (uint32_t a = 0; a < pts.size(); ++a) {
    for (uint32_t b = a + 1; b < pts.size(); ++b) {
      if (dist2(pts[a], pts[b]) <= r2) uf.unite(a, b);
    }
  }
  return groups(uf, min_size);
}

/// FEC transliterated from algorithm §2: points in index order; an unreached point is a seed; its neighbours are the cap
/// nearest points within r (itself included, ties to the lower index); the seed joins each, and they are reached.
Clusters fecReference(const Cloud& pts, double r, int cap, int min_size) {
  const float r2 = static_cast<float>(r * r);
  UnionFind uf(pts.size());
  std::vector<bool> reached(pts.size(), false);
  for (uint32_t s = 0; s < pts.size(); ++s) {
    if (reached[s]) continue;
    std::vector<std::pair<float, uint32_t>> near;
    for (uint32_t q = 0; q < pts.size(); ++q) {
      const float d2 = dist2(pts[q], pts[s]);
      if (d2 <= r2) near.emplace_back(d2, q);
    }
    std::sort(near.begin(), near.end());
    if (near.size() > static_cast<size_t>(cap)) near.resize(cap);
    for (const auto& [d2, q] : near) {
      reached[q] = true;
      uf.unite(s, q);
    }
  }
  return groups(uf, min_size);
}

/// True if every cluster of @p fine lies inside one cluster of @p coarse and both cover the same points.
bool refines(const Clusters& fine, const Clusters& coarse) {
  std::map<uint32_t, size_t> owner;
  size_t fine_points = 0, coarse_points = 0;
  for (size_t c = 0; c < coarse.size(); ++c) {
    for (uint32_t i : coarse[c]) owner[i] = c;
    coarse_points += coarse[c].size();
  }
  for (const auto& cluster : fine) {
    fine_points += cluster.size();
    for (uint32_t i : cluster) {
      if (!owner.count(i) || owner[i] != owner[cluster.front()]) return false;
    }
  }
  return fine_points == coarse_points;
}

// --- Synthetic clouds (fixed seeds) --------------------------------------------------------------------------------

Cloud gaussianBlobs(uint32_t seed, int blobs, int per_blob, float sigma, float spacing) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  Cloud pts;
  for (int b = 0; b < blobs; ++b) {
    const Eigen::Vector3f c(spacing * static_cast<float>(b % 3), spacing * static_cast<float>(b / 3), 0.0f);
    for (int k = 0; k < per_blob; ++k) pts.push_back(c + Eigen::Vector3f(noise(rng), noise(rng), 0.3f * noise(rng)));
  }
  std::shuffle(pts.begin(), pts.end(), rng);
  return pts;
}

Cloud uniformBox(uint32_t seed, int n, const Eigen::Vector3f& size) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Cloud pts(n);
  for (auto& p : pts) p = Eigen::Vector3f(u(rng), u(rng), u(rng)).cwiseProduct(size);
  return pts;
}

/// Points along x spaced @p step, in order along the line (shuffled if @p seed != 0).
Cloud line(int n, float step, uint32_t seed) {
  Cloud pts;
  for (int k = 0; k < n; ++k) pts.emplace_back(step * static_cast<float>(k), 1.0f, -2.0f);
  if (seed != 0) {
    std::mt19937 rng(seed);
    std::shuffle(pts.begin(), pts.end(), rng);
  }
  return pts;
}

/// Uniform points in a cube of half-edge @p half, none within 1e-4 leaf of a voxel face (float vs double rounding).
Cloud voxelTestCloud(uint32_t seed, int n, float half, double leaf) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-half, half);
  Cloud pts;
  while (static_cast<int>(pts.size()) < n) {
    const Eigen::Vector3f p(u(rng), u(rng), u(rng));
    bool near_face = false;
    for (int d = 0; d < 3; ++d) {
      const double t = p[d] / leaf;
      const double frac = t - std::floor(t);
      near_face = near_face || frac < 1e-4 || frac > 1.0 - 1e-4;
    }
    if (!near_face) pts.push_back(p);
  }
  return pts;
}

struct FecCase {
  const char* name;
  Cloud pts;
  double radius;
};

std::vector<FecCase> fecCases() {
  return {{"blobs", gaussianBlobs(11, 6, 250, 0.6f, 8.0f), 1.0},
          {"blobs_sparse", gaussianBlobs(12, 6, 120, 1.2f, 9.0f), 1.0},
          {"uniform_dense", uniformBox(13, 1500, {15.0f, 15.0f, 3.0f}), 1.0},
          {"uniform_sparse", uniformBox(14, 600, {20.0f, 20.0f, 5.0f}), 1.0},
          {"line_below_r", line(80, 0.98f, 0), 1.0},
          {"line_above_r", line(80, 1.02f, 0), 1.0},
          {"line_below_r_shuffled", line(80, 0.98f, 15), 1.0},
          {"blobs_r0.5", gaussianBlobs(16, 6, 250, 0.6f, 8.0f), 0.5}};
}

// --- (a) voxelDownsample -------------------------------------------------------------------------------------------

TEST(VoxelDownsample, MatchesMapReference) {
  struct Case { uint32_t seed; int n; float half; double leaf; };
  for (const Case& c : {Case{1, 20000, 4.0f, 0.4}, Case{2, 5000, 30.0f, 0.4}, Case{3, 8000, 2.0f, 1.0},
                        Case{4, 3000, 1.0f, 0.25}}) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    const Cloud pts = voxelTestCloud(c.seed, c.n, c.half, c.leaf);
    const auto out = sgtllc::voxelDownsample(pts, c.leaf);
    const RefVoxels ref = voxelReference(pts, c.leaf);
    ASSERT_EQ(out.centroids.size(), ref.sums.size());
    ASSERT_EQ(out.sums.size(), ref.sums.size());
    ASSERT_EQ(out.counts, ref.counts);  // same voxels, in order of first appearance
    for (size_t v = 0; v < ref.sums.size(); ++v) {
      ASSERT_LT((out.sums[v] - ref.sums[v]).norm(), 1e-9) << "voxel " << v;
      const Eigen::Vector3d mean = ref.sums[v] / ref.counts[v];
      ASSERT_LT((out.centroids[v].cast<double>() - mean).norm(), 1e-5) << "voxel " << v;
    }
    EXPECT_EQ(std::accumulate(out.counts.begin(), out.counts.end(), size_t{0}), pts.size());
    if (c.seed == 1) {
      EXPECT_LT(out.centroids.size(), pts.size() / 2);  // several points share voxels here
    }
  }
}

TEST(VoxelDownsample, DistantVoxelsNeverShareACell) {
  // 838870.8 m is 2^21 voxels of 0.4 m beyond 10 m: a key packed into 21 bits per axis would merge them.
  const auto out = sgtllc::voxelDownsample({{10.f, 0.f, 0.f}, {838870.8f, 0.f, 0.f}, {10.1f, 0.f, 0.f}}, 0.4);
  ASSERT_EQ(out.centroids.size(), 2u);
  EXPECT_EQ(out.counts[0], 2u);
  EXPECT_NEAR(out.centroids[0].x(), 10.05f, 1e-5f);
  EXPECT_EQ(out.centroids[1].x(), 838870.8f);
}

TEST(VoxelCells, FloorMatchesStdFloorAndClamps) {
  // The cell arithmetic replaces std::floor (internal/voxel_hash.h): it must agree on integers, on both sides of
  // zero, next to integers and at the clamp, and map NaN to a fixed cell.
  using sgtllc::internal::floorBounded;
  using sgtllc::internal::floorCell;
  using sgtllc::internal::kMaxCell;
  std::vector<float> values = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 2.999999f, -2.999999f, 1e-30f, -1e-30f,
                               123456.7f, -123456.7f, 1.0e9f, -1.0e9f};
  for (float v : {1.0f, -1.0f, 1000.0f, -1000.0f, 1048576.0f, -1048576.0f}) {
    values.push_back(std::nextafter(v, 0.0f));
    values.push_back(std::nextafter(v, 2.0f * v));
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-2.5e3f, 2.5e3f);
  for (int k = 0; k < 10000; ++k) values.push_back(u(rng));
  for (float v : values) {
    const auto expected = static_cast<int32_t>(std::floor(v));
    EXPECT_EQ(floorCell(v), expected) << v;
    EXPECT_EQ(floorBounded(v), expected) << v;
  }
  const auto max_cell = static_cast<int32_t>(kMaxCell);
  EXPECT_EQ(floorCell(3.0e9f), max_cell);
  EXPECT_EQ(floorCell(-3.0e9f), -max_cell);
  EXPECT_EQ(floorCell(std::numeric_limits<float>::infinity()), max_cell);
  EXPECT_EQ(floorCell(std::numeric_limits<float>::quiet_NaN()), -max_cell);
}

TEST(VoxelDownsample, EmptyInput) { EXPECT_TRUE(sgtllc::voxelDownsample({}, 0.4).centroids.empty()); }

// --- (b) FEC -------------------------------------------------------------------------------------------------------

TEST(Fec, UncappedEqualsSpecTransliteration) {
  for (const FecCase& c : fecCases()) {
    SCOPED_TRACE(c.name);
    const int n = static_cast<int>(c.pts.size());
    for (int min_size : {1, 2, 20, 150}) {
      SCOPED_TRACE("min_size " + std::to_string(min_size));
      EXPECT_EQ(fastEuclideanClustering(c.pts, c.radius, n, min_size), fecReference(c.pts, c.radius, n, min_size));
    }
  }
}

TEST(Fec, UncappedEqualsConnectedComponentsOnDenseBlobsAndOrderedLines) {
  // Plain connected components (edges d ≤ r) equal FEC only where every edge ends up in a chain of seed
  // neighbourhoods: dense blobs, and lines visited in order. Elsewhere FEC splits more (next tests).
  for (const FecCase& c : fecCases()) {
    const std::string name = c.name;
    if (name != "blobs" && name != "line_below_r" && name != "line_above_r") continue;
    SCOPED_TRACE(name);
    const int n = static_cast<int>(c.pts.size());
    for (int min_size : {1, 2, 20}) {
      EXPECT_EQ(fastEuclideanClustering(c.pts, c.radius, n, min_size), connectedComponents(c.pts, c.radius, min_size));
    }
  }
  EXPECT_EQ(fastEuclideanClustering(line(80, 0.98f, 0), 1.0, 1000, 1).size(), 1u);
  EXPECT_EQ(fastEuclideanClustering(line(80, 1.02f, 0), 1.0, 1000, 1).size(), 80u);
  EXPECT_TRUE(fastEuclideanClustering(line(80, 1.02f, 0), 1.0, 1000, 2).empty());
}

TEST(Fec, UncappedRefinesConnectedComponents) {
  // FEC only joins points within r, so each of its clusters lies inside one connected component.
  int strictly_finer = 0;
  for (const FecCase& c : fecCases()) {
    SCOPED_TRACE(c.name);
    const Clusters fec = fastEuclideanClustering(c.pts, c.radius, static_cast<int>(c.pts.size()), 1);
    const Clusters cc = connectedComponents(c.pts, c.radius, 1);
    EXPECT_TRUE(refines(fec, cc));
    strictly_finer += fec.size() > cc.size();
  }
  EXPECT_GE(strictly_finer, 2);  // uniform_dense, blobs_r0.5 and the shuffled line split further
}

TEST(Fec, ReachedPointsNeverSeedSoAChainCanSplit) {
  // Spec §2: points already reached never become seeds. x = 0, 3, 1, 2 (r = 1.2): seed 0 reaches x=1, seed 1 (x=3)
  // reaches x=2; the edge x=1 — x=2 is never a (seed, neighbour) edge, so FEC gives two clusters where
  // connected components give one.
  const Cloud pts = {{0, 0, 0}, {3, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_EQ(fastEuclideanClustering(pts, 1.2, 100, 1), (Clusters{{0, 2}, {1, 3}}));
  EXPECT_EQ(connectedComponents(pts, 1.2, 1), (Clusters{{0, 1, 2, 3}}));
}

TEST(Fec, CappedEqualsSpecTransliteration) {
  for (const FecCase& c : fecCases()) {
    SCOPED_TRACE(c.name);
    for (int cap : {1, 2, 5, 12}) {
      SCOPED_TRACE("cap " + std::to_string(cap));
      for (int min_size : {1, 20}) {
        EXPECT_EQ(fastEuclideanClustering(c.pts, c.radius, cap, min_size),
                  fecReference(c.pts, c.radius, cap, min_size));
      }
    }
  }
}

TEST(Fec, DenseNeighbourhoodsEqualSpecTransliteration) {
  // Thousands of points within r of each seed, as a trunk next to the sensor clustered without downsampling. Above
  // a threshold of candidates per seed (internal::kDenseCandidates) fastEuclideanClustering searches a finer grid ring
  // by ring (tight blobs settle within the rings, wide ones fall back to the full scan); the threshold is lowered
  // here so that these clouds take the rings, and the public function, which scans them in full, is checked too.
  // Every way, the clusters must equal the reference's.
  const std::pair<float, int> blobs[] = {{0.04f, 2400}, {0.15f, 2400}, {0.5f, 2000}};
  for (const auto& [sigma, n] : blobs) {
    Cloud pts = gaussianBlobs(31, 2, n / 2, sigma, 1.5f);
    const Cloud strand = line(60, 0.3f, 7);  // a sparse chain through and beyond the blobs
    pts.insert(pts.end(), strand.begin(), strand.end());
    for (int cap : {3, 5, 12, 100, 250}) {
      SCOPED_TRACE("sigma " + std::to_string(sigma) + " cap " + std::to_string(cap));
      const Clusters reference = fecReference(pts, 1.0, cap, 1);
      EXPECT_EQ(fastEuclideanClustering(pts, 1.0, cap, 1), reference);
      for (size_t dense : {size_t{256}, static_cast<size_t>(8 * cap)}) {
        EXPECT_EQ(sgtllc::internal::fastEuclideanClustering(pts, 1.0, cap, 1, dense), reference) << "dense " << dense;
      }
    }
  }
}

TEST(Fec, CapChangesTheResultOnDenseBlobs) {
  // Guards the comparison above against a cap that is silently ignored.
  const Cloud pts = gaussianBlobs(21, 3, 400, 0.3f, 6.0f);
  const int n = static_cast<int>(pts.size());
  const Clusters capped = fastEuclideanClustering(pts, 1.0, 5, 1);
  EXPECT_NE(capped, fastEuclideanClustering(pts, 1.0, n, 1));
  EXPECT_EQ(capped, fecReference(pts, 1.0, 5, 1));
}

TEST(Fec, TiesAtTheCapGoToTheLowerIndex) {
  // Seed 0 has points 1, 2, 3 at exactly 0.5 m; cap 3 keeps itself, 1 and 2. Point 3 then seeds with its own close
  // points 4, 5, which fill its cap before point 0, so it stays apart. With cap 4, 3 joins the first seed.
  const Cloud pts = {{0, 0, 0}, {0.5f, 0, 0}, {-0.5f, 0, 0}, {0, 0.5f, 0}, {0, 0.55f, 0}, {0, 0.6f, 0}};
  EXPECT_EQ(fastEuclideanClustering(pts, 1.0, 3, 1), (Clusters{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(fastEuclideanClustering(pts, 1.0, 4, 1), (Clusters{{0, 1, 2, 3, 4, 5}}));
  EXPECT_EQ(fecReference(pts, 1.0, 3, 1), (Clusters{{0, 1, 2}, {3, 4, 5}}));
}

TEST(Fec, FarFromTheOriginEqualsSpecTransliteration) {
  // Far from the origin cell coordinates lose float precision: the cells searched around a seed are widened by it,
  // and must still find exactly the reference's neighbours (and never more cells than the search holds).
  for (const float offset : {5.0e4f, 9.0e5f}) {
    for (const double radius : {0.01, 0.3, 1.0}) {
      Cloud pts = gaussianBlobs(5, 3, 200, static_cast<float>(radius), 4.0f * static_cast<float>(radius));
      for (auto& p : pts) p += Eigen::Vector3f(offset, -offset, 0.5f * offset);
      SCOPED_TRACE("offset " + std::to_string(offset) + " radius " + std::to_string(radius));
      for (int cap : {5, 100}) EXPECT_EQ(fastEuclideanClustering(pts, radius, cap, 1), fecReference(pts, radius, cap, 1));
    }
  }
}

TEST(Fec, EmptyCloud) { EXPECT_TRUE(fastEuclideanClustering({}, 1.0, 100, 1).empty()); }

}  // namespace
