// The footprint check (algorithm §7.7, footprint.h): which cells a scan occupies, the overlap of two footprints
// under a pose against a brute-force reference, and verification rejecting a pose the structure contradicts, on
// real KITTI 00 scans.
#include <cmath>
#include <random>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "sgtllc/detector.h"
#include "sgtllc/footprint.h"
#include "sgtllc/node_extraction.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

// SemanticKITTI raw ids (LabelConfig's default preset).
constexpr uint32_t kBuildingId = 50, kTerrainId = 72, kRoadId = 40, kPoleId = 80;

VerificationConfig defaults() { return VerificationConfig{}; }

LabeledCloud cloudOf(const std::vector<std::pair<Eigen::Vector3f, uint32_t>>& points) {
  LabeledCloud c;
  for (const auto& [p, id] : points) {
    c.points.push_back(p);
    c.labels.push_back(id);
  }
  return c;
}

TEST(Footprint, StructureCellsAreSetAndGroundTerrainAndFarPointsAreNot) {
  const LabelMap labels{LabelConfig{}};
  const LabeledCloud cloud = cloudOf({{{0.5f, 0.5f, 0.0f}, kBuildingId},
                                      {{-3.2f, 7.9f, 2.0f}, kPoleId},
                                      {{5.5f, 5.5f, -1.7f}, kTerrainId},
                                      {{6.5f, 6.5f, -1.7f}, kRoadId},
                                      {{45.0f, 0.0f, 0.0f}, kBuildingId},  // beyond footprint_radius 40 m
                                      {{NAN, 0.0f, 0.0f}, kBuildingId}});
  const Footprint f = computeFootprint(cloud, labels, defaults());
  ASSERT_FALSE(f.empty());
  EXPECT_EQ(f.half, 80);                          // 40 m in cells of 0.5 m
  EXPECT_EQ(f.bytes(), (160u * 160u / 64u) * 8u);  // 3,200 bytes; no sight with the seen-through check off
  VerificationConfig seen = defaults();
  seen.max_seen_through = 0.5;
  EXPECT_EQ(computeFootprint(cloud, labels, seen).bytes(), (160u * 160u / 64u) * 8u + 720u);  // and its 720
  int set = 0;
  for (int i = 0; i < 160; ++i) {
    for (int j = 0; j < 160; ++j) set += f.occupied(i, j);
  }
  EXPECT_EQ(set, 2);
  EXPECT_TRUE(f.occupied(80 + 1, 80 + 1));    // (0.5, 0.5): cell [0.5, 1) × [0.5, 1)
  EXPECT_TRUE(f.occupied(80 - 7, 80 + 15));   // (−3.2, 7.9): cell [−3.5, −3) × [7.5, 8)
  EXPECT_FALSE(f.occupied(80 + 11, 80 + 11));  // terrain
  EXPECT_FALSE(f.occupied(-1, 0));          // outside the grid
  VerificationConfig off = defaults();
  off.min_footprint_overlap = 0.0;
  EXPECT_TRUE(computeFootprint(cloud, labels, off).empty());
}

void expectSameFootprint(const Footprint& a, const Footprint& b) {
  EXPECT_EQ(a.cell, b.cell);
  EXPECT_EQ(a.half, b.half);
  EXPECT_EQ(a.bits, b.bits);
  EXPECT_EQ(a.sight.low, b.sight.low);
  EXPECT_EQ(a.sight.high, b.sight.high);
}

// Node extraction sets the footprint's cells in its own pass over the points (FootprintMarker); it must be
// computeFootprint's footprint, bit for bit: on a real scan, at both thread counts, with the sight on, and on a
// scan whose bad points send the split down its checked path (a NaN z still sets its cell: the footprint reads x
// and y only; a point beyond the coordinate bound sets none).
TEST(Footprint, NodeExtractionsPassGivesComputeFootprintsCells) {
  LabeledCloud scan = test::kittiScan("004501");
  size_t structure = 0;
  for (const uint32_t id : scan.labels) structure += (id & 0xFFFFu) == kBuildingId;
  ASSERT_GT(structure, 10000u);
  VerificationConfig seen = defaults();
  seen.max_seen_through = 0.5;
  for (const VerificationConfig& config : {defaults(), seen}) {
    for (int threads : {1, 2}) {
      const NodeExtractor extractor(ClusterConfig{}, LabelConfig{}, GraphConfig{}.max_nodes, threads);
      Footprint f;
      const NodeExtractionResult with = extractor.extract(scan, config, &f);
      const Footprint reference = computeFootprint(scan, extractor.labelMap(), config);
      ASSERT_FALSE(reference.empty());
      expectSameFootprint(f, reference);
      EXPECT_EQ(f.sight.low.empty(), config.max_seen_through >= 1.0);
      EXPECT_EQ(with.nodes.size(), extractor.extract(scan).nodes.size());
    }
  }
  // Bad points in the first half of the scan, so one range of the split checks every point. The sensor's own
  // cell holds no return of a real scan.
  ASSERT_FALSE(computeFootprint(scan, LabelMap{LabelConfig{}}, defaults()).occupied(80, 80));
  scan.points[10] = {0.2f, 0.3f, NAN};     // a structure point with a bad z: its cell is set
  scan.labels[10] = kBuildingId;
  scan.points[11] = {2.0e6f, 0.0f, 0.0f};  // beyond the coordinate bound: nothing
  scan.labels[11] = kBuildingId;
  scan.points[12] = {NAN, 1.0f, 0.0f};     // a bad x: nothing
  scan.labels[12] = kBuildingId;
  const NodeExtractor extractor(ClusterConfig{}, LabelConfig{});
  Footprint f;
  extractor.extract(scan, defaults(), &f);
  const Footprint reference = computeFootprint(scan, extractor.labelMap(), defaults());
  expectSameFootprint(f, reference);
  EXPECT_TRUE(f.occupied(80, 80));  // (0.2, 0.3): cell [0, 0.5) × [0, 0.5)
  // Off, the extraction leaves it empty.
  VerificationConfig off = defaults();
  off.min_footprint_overlap = 0.0;
  extractor.extract(scan, off, &f);
  EXPECT_TRUE(f.empty());
}

/// The overlap by its definition, over a set of cells, for comparison.
FootprintOverlap bruteForceOverlap(const Footprint& q, const Footprint& m, const Eigen::Matrix4d& T) {
  std::set<std::pair<int, int>> match_cells;
  for (int i = 0; i < 2 * m.half; ++i) {
    for (int j = 0; j < 2 * m.half; ++j) {
      if (m.occupied(i, j)) match_cells.emplace(i - m.half, j - m.half);
    }
  }
  FootprintOverlap o;
  int hits = 0;
  for (int i = 0; i < 2 * q.half; ++i) {
    for (int j = 0; j < 2 * q.half; ++j) {
      if (!q.occupied(i, j)) continue;
      const Eigen::Vector3d p = test::apply(T, Eigen::Vector3d((i - q.half + 0.5) * q.cell, (j - q.half + 0.5) * q.cell, 0));
      if (std::hypot(p.x(), p.y()) > 0.8 * q.half * q.cell) continue;
      ++o.compared;
      const int ci = static_cast<int>(std::floor(p.x() / m.cell)), cj = static_cast<int>(std::floor(p.y() / m.cell));
      bool hit = false;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) hit = hit || match_cells.count({ci + di, cj + dj}) > 0;
      }
      hits += hit;
    }
  }
  o.share = o.compared ? static_cast<double>(hits) / o.compared : 0.0;
  return o;
}

TEST(Footprint, OverlapEqualsTheBruteForceReferenceOnRandomScenesAndPoses) {
  const LabelMap labels{LabelConfig{}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-40.0f, 40.0f);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI), shift(-8.0, 8.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::pair<Eigen::Vector3f, uint32_t>> a, b;
    for (int k = 0; k < 400; ++k) a.push_back({{coord(rng), coord(rng), 0.0f}, kBuildingId});
    for (int k = 0; k < 400; ++k) b.push_back({{coord(rng), coord(rng), 0.0f}, kPoleId});
    const Footprint fa = computeFootprint(cloudOf(a), labels, defaults());
    const Footprint fb = computeFootprint(cloudOf(b), labels, defaults());
    const Eigen::Matrix4d T = test::rigid(yaw(rng) * 180.0 / M_PI, 1.0, -2.0, {shift(rng), shift(rng), 0.3});
    const FootprintOverlap fast = footprintOverlap(fa, fb, T), slow = bruteForceOverlap(fa, fb, T);
    EXPECT_EQ(fast.compared, slow.compared) << trial;
    EXPECT_DOUBLE_EQ(fast.share, slow.share) << trial;
    // A stored frame is kept dilated: the same overlap with one look-up a cell.
    const Footprint stored = dilateFootprint(fb);
    ASSERT_TRUE(stored.dilated);
    const FootprintOverlap dilated = footprintOverlap(fa, stored, T);
    EXPECT_EQ(dilated.compared, slow.compared) << trial;
    EXPECT_DOUBLE_EQ(dilated.share, slow.share) << trial;
  }
}

TEST(Footprint, AMovedCopyOverlapsFullyUnderItsMotionAndHardlyUnderAnother) {
  // A scan and the same scan seen from a sensor 3 m ahead and turned 20°: under the true motion every compared
  // cell lands on its own; turned a further 90°, far fewer do.
  const LabelMap labels{LabelConfig{}};
  const LabeledCloud scan = test::kittiScan("004501");
  const Eigen::Matrix4d T_match_query = test::rigid(20.0, 0.0, 0.0, {3.0, -1.0, 0.0});
  const LabeledCloud moved = test::transformed(scan, T_match_query);  // the query's points in the match's frame
  const Footprint query = computeFootprint(scan, labels, defaults());
  const Footprint match = computeFootprint(moved, labels, defaults());
  const FootprintOverlap right = footprintOverlap(query, match, T_match_query);
  EXPECT_GT(right.compared, 200);
  EXPECT_GT(right.share, 0.97);  // cells cut by the 40 m circle and the grid phase are the only misses
  const FootprintOverlap wrong = footprintOverlap(query, match, test::rigid(110.0, 0.0, 0.0, {3.0, -1.0, 0.0}));
  EXPECT_LT(wrong.share, right.share - 0.2);
  EXPECT_EQ(footprintOverlap(query, Footprint{}, T_match_query).compared, 0);  // nothing to compare with
}

TEST(Footprint, AVerifiedPoseThatTheStructureContradictsIsRejected) {
  // KITTI 00 4501 revisits 52 (3 m): the pose passes the check. The same nodes with the footprint of frame 850,
  // 300 m away, stand for two places whose objects agree by chance: the check rejects the pose.
  const Config config;
  const LabelMap labels(config.labels);
  const LabeledCloud q = test::kittiScan("004501"), m = test::kittiScan("000052");
  const PairResult loop = comparePair(q, m, config);
  ASSERT_TRUE(loop.is_loop);
  EXPECT_GT(loop.match.footprint.compared, 200);
  EXPECT_GT(loop.match.footprint.share, 0.9);
  const NodeExtractor extractor(config.cluster, config.labels);
  const PairResult contradicted =
      comparePair(extractor.extract(q).nodes, extractor.extract(m).nodes, config,
                  computeFootprint(q, labels, config.verification),
                  computeFootprint(test::kittiScan("000850"), labels, config.verification));
  EXPECT_EQ(contradicted.match.rejection, Rejection::kFootprint) << contradicted.match.footprint.share << " of " << contradicted.match.footprint.compared;
  EXPECT_FALSE(contradicted.is_loop);
  EXPECT_EQ(contradicted.match.score, 0.0);
  EXPECT_LT(contradicted.match.footprint.share, config.verification.min_footprint_overlap);
  EXPECT_STREQ(rejectionName(contradicted.match.rejection), "footprint_mismatch");
  // Without footprints (node input) there is nothing to check: the node-level result stands.
  const PairResult nodes_only = comparePair(extractor.extract(q).nodes, extractor.extract(m).nodes, config);
  EXPECT_TRUE(nodes_only.is_loop);
  EXPECT_EQ(nodes_only.match.footprint.compared, 0);
  EXPECT_EQ(nodes_only.match.score, loop.match.score);
}

TEST(Footprint, WeakEvidenceNeedsTheHigherShare) {
  // 4501 → 52: 16 inliers, share 0.966. Counted as weak (weak_inliers ≥ 16) it needs weak_min_footprint: 0.97
  // rejects it, 0.96 keeps it; with one inlier more than weak_inliers allows, 0.97 does not apply.
  const LabeledCloud q = test::kittiScan("004501"), m = test::kittiScan("000052");
  Config config;
  config.registration.pair = false;
  const PairResult base = comparePair(q, m, config);
  ASSERT_TRUE(base.is_loop);
  ASSERT_EQ(base.match.inliers.size(), 16u);
  ASSERT_NEAR(base.match.footprint.share, 0.966, 0.0005);
  config.verification.weak_inliers = 16;
  config.verification.weak_min_footprint = 0.97;
  const PairResult weak = comparePair(q, m, config);
  EXPECT_FALSE(weak.is_loop);
  EXPECT_EQ(weak.match.rejection, Rejection::kFootprint);
  config.verification.weak_min_footprint = 0.96;
  EXPECT_TRUE(comparePair(q, m, config).is_loop);
  config.verification.weak_inliers = 15;
  config.verification.weak_min_footprint = 0.97;
  const PairResult strong = comparePair(q, m, config);
  EXPECT_TRUE(strong.is_loop);
  EXPECT_EQ(strong.match.score, base.match.score);
}

}  // namespace
}  // namespace sgtllc
