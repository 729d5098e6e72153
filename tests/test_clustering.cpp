// Voxel downsampling, FEC and node extraction (spec §1–§2), against brute-force references on synthetic clouds.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "sgtllc/clustering.h"
#include "sgtllc/node_extraction.h"

namespace {

using Cloud = std::vector<Eigen::Vector3f>;
using Clusters = std::vector<std::vector<uint32_t>>;
using sgtllc::fastEuclideanClustering;
using sgtllc::LabeledCloud;
using sgtllc::NodeExtractor;

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

/// FEC transliterated from spec §2: points in index order; an unreached point is a seed; its neighbours are the cap
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

struct RefVoxels {
  std::vector<Eigen::Vector3d> sums;
  std::vector<uint32_t> counts;
};

RefVoxels voxelReference(const Cloud& pts, double leaf) {
  std::map<std::array<long, 3>, size_t> index;
  RefVoxels ref;
  for (const auto& p : pts) {
    const std::array<long, 3> key = {static_cast<long>(std::floor(p.x() / leaf)),
                                     static_cast<long>(std::floor(p.y() / leaf)),
                                     static_cast<long>(std::floor(p.z() / leaf))};
    const auto [it, added] = index.emplace(key, ref.sums.size());
    if (added) {
      ref.sums.emplace_back(Eigen::Vector3d::Zero());
      ref.counts.push_back(0);
    }
    ref.sums[it->second] += p.cast<double>();
    ++ref.counts[it->second];
  }
  return ref;
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

const Eigen::Vector3f kX = Eigen::Vector3f::UnitX(), kY = Eigen::Vector3f::UnitY(), kZ = Eigen::Vector3f::UnitZ();

sgtllc::NodeExtractionResult extract(const LabeledCloud& cloud, const sgtllc::ClusterConfig& config = {}) {
  return NodeExtractor(config, sgtllc::LabelConfig{}).extract(cloud);
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

TEST(VoxelDownsample, EmptyInput) { EXPECT_TRUE(sgtllc::voxelDownsample({}, 0.4).centroids.empty()); }

// --- (b), (c) FEC --------------------------------------------------------------------------------------------------

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

TEST(Fec, EmptyCloud) { EXPECT_TRUE(fastEuclideanClustering({}, 1.0, 100, 1).empty()); }

// --- (d) NodeExtractor ---------------------------------------------------------------------------------------------

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
  EXPECT_LT((result.nodes[1].centre - mean(pole20)).norm(), 1e-9);
  EXPECT_EQ(result.stats.clusters[sgtllc::kBuilding], 1);
  EXPECT_EQ(result.stats.clusters[sgtllc::kPole], 1);
}

TEST(NodeExtractor, NodeOrderIsClassOrder) {
  // Classes appear in the cloud in reverse order; nodes must come out building … traffic-sign.
  LabeledCloud cloud;
  std::vector<Cloud> by_class(sgtllc::kNumClasses);
  by_class[6] = addGrid(&cloud, 81, {60, 0, 2}, kX, kZ, 5, 5);            // traffic-sign, 25 points
  by_class[5] = addRing(&cloud, 80, {50, 0, 0}, 0.0f, 25);               // pole
  by_class[4] = addGrid(&cloud, 72, {0, 30, -1.8f}, kX, kY, 40, 40);     // terrain, 400 voxels
  by_class[3] = addRing(&cloud, 71, {40, 0, 0}, 0.0f, 25);               // trunk
  by_class[2] = addGrid(&cloud, 70, {0, -20, 0}, kX, kZ, 40, 20);        // vegetation, 200 voxels
  by_class[1] = addGrid(&cloud, 51, {0, 10, 0}, kX, kZ, 50, 2);          // fence, 25 voxels
  by_class[0] = addGrid(&cloud, 50, {0, 0, 0}, kX, kZ, 50, 20);          // building, 250 voxels
  const auto result = extract(cloud);
  ASSERT_EQ(result.nodes.size(), 7u);
  for (int c = 0; c < sgtllc::kNumClasses; ++c) {
    EXPECT_EQ(result.nodes[c].label, c);
    EXPECT_LT((result.nodes[c].centre - mean(by_class[c])).norm(), 1e-9) << sgtllc::kClassNames[c];
    EXPECT_EQ(result.stats.class_points[c], by_class[c].size());
    EXPECT_EQ(result.stats.clusters[c], 1);
  }
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
  EXPECT_LT((result.nodes[0].centre - mean(inner)).norm(), 1e-9);
  EXPECT_EQ(result.nodes[1].label, sgtllc::kPole);
  EXPECT_LT((result.nodes[1].centre - mean(pole)).norm(), 1e-9);
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
  EXPECT_LT((suppressed.nodes[0].centre - mean(inner)).norm(), 1e-9);
  EXPECT_EQ(suppressed.stats.duplicates_suppressed, 1);
  config.duplicate_radius = 0.5;
  const auto kept = extract(cloud, config);
  ASSERT_EQ(kept.nodes.size(), 2u);
  EXPECT_LT((kept.nodes[1].centre - mean(outer)).norm(), 1e-9);
  EXPECT_EQ(kept.stats.duplicates_suppressed, 0);
}

TEST(NodeExtractor, MismatchedLengthsThrowAndEmptyCloudGivesNoNodes) {
  LabeledCloud cloud;
  cloud.points.assign(3, Eigen::Vector3f::Zero());
  cloud.labels.assign(2, 50);
  EXPECT_THROW(extract(cloud), std::invalid_argument);
  const auto result = extract(LabeledCloud{});
  EXPECT_TRUE(result.nodes.empty());
  EXPECT_EQ(result.stats.input_points, 0u);
  for (int c = 0; c < sgtllc::kNumClasses; ++c) EXPECT_EQ(result.stats.clusters[c], 0);
}

}  // namespace
