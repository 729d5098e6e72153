// The consistency path of verification (algorithm §7.8): the largest pairwise-consistent set against a brute-force
// search, the hypothesis pairs, and matchFrames on a revisit whose descriptors were made to disagree.
#include <algorithm>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sgtllc/consistent_matching.h"
#include "sgtllc/frame.h"
#include "sgtllc/node_extraction.h"
#include "sgtllc/verification.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

using test::apply;
using test::rigid;

struct Pairs {
  std::vector<Eigen::Vector3d> source, target;
  std::vector<int> source_ids, target_ids;
};

/// Whether every two of @p set are one-to-one and their distances agree within @p tolerance.
bool consistent(const Pairs& p, const std::vector<int>& set, double tolerance) {
  for (size_t a = 0; a < set.size(); ++a) {
    for (size_t b = a + 1; b < set.size(); ++b) {
      const int i = set[a], j = set[b];
      if (p.source_ids[i] == p.source_ids[j] || p.target_ids[i] == p.target_ids[j]) return false;
      const double ds = (p.source[i] - p.source[j]).norm(), dt = (p.target[i] - p.target[j]).norm();
      if (std::abs(ds - dt) >= tolerance) return false;
    }
  }
  return true;
}

/// The size of the largest consistent set, by trying every subset.
size_t bruteForceLargest(const Pairs& p, double tolerance) {
  const int n = static_cast<int>(p.source.size());
  size_t best = 0;
  for (uint32_t mask = 1; mask < (1u << n); ++mask) {
    std::vector<int> set;
    for (int k = 0; k < n; ++k) {
      if (mask & (1u << k)) set.push_back(k);
    }
    if (set.size() > best && consistent(p, set, tolerance)) best = set.size();
  }
  return best;
}

/// Eight true pairs under a rigid motion (with noise), plus wrong pairs: some to other target points, some to
/// made-up ones, some reusing a point: the shape of the hypothesis pairs of two graphs.
Pairs randomPairs(std::mt19937& rng, int wrong) {
  std::uniform_real_distribution<double> coord(-30.0, 30.0), noise(-0.1, 0.1), yaw(-180.0, 180.0);
  const Eigen::Matrix4d T = rigid(yaw(rng), 0.0, 0.0, Eigen::Vector3d(coord(rng), coord(rng), 0.0));
  Pairs p;
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    points.emplace_back(coord(rng), coord(rng), 0.3 * coord(rng) / 30.0);
    p.source.push_back(points.back());
    p.target.push_back(apply(T, points.back()) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
    p.source_ids.push_back(k);
    p.target_ids.push_back(k);
  }
  std::uniform_int_distribution<int> pick(0, 7);
  for (int k = 0; k < wrong; ++k) {
    const int s = pick(rng), t = pick(rng);
    p.source.push_back(p.source[static_cast<size_t>(s)]);
    p.source_ids.push_back(s);
    if (k % 2 == 0) {
      p.target.push_back(p.target[static_cast<size_t>(t)]);  // another true point: a wrong pair of real nodes
      p.target_ids.push_back(t);
    } else {
      p.target.emplace_back(coord(rng), coord(rng), 0.0);
      p.target_ids.push_back(100 + k);
    }
  }
  // Shuffled, so the true pairs are not simply the first ones.
  std::vector<int> order(p.source.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::shuffle(order.begin(), order.end(), rng);
  Pairs out;
  for (int k : order) {
    out.source.push_back(p.source[static_cast<size_t>(k)]);
    out.target.push_back(p.target[static_cast<size_t>(k)]);
    out.source_ids.push_back(p.source_ids[static_cast<size_t>(k)]);
    out.target_ids.push_back(p.target_ids[static_cast<size_t>(k)]);
  }
  return out;
}

TEST(LargestConsistentSet, MatchesBruteForceOnRandomPairs) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    const Pairs p = randomPairs(rng, 2 + trial % 9);  // 10 to 18 pairs
    const std::vector<int> set = largestConsistentSet(p.source, p.target, p.source_ids, p.target_ids, 0.8);
    SCOPED_TRACE(trial);
    EXPECT_TRUE(std::is_sorted(set.begin(), set.end()));
    EXPECT_TRUE(consistent(p, set, 0.8));
    EXPECT_EQ(set.size(), bruteForceLargest(p, 0.8));
    EXPECT_GE(set.size(), 8u);  // the true pairs are one consistent set
  }
}

TEST(LargestConsistentSet, SameInputSameSet) {
  std::mt19937 rng(11);
  const Pairs p = randomPairs(rng, 12);
  const std::vector<int> a = largestConsistentSet(p.source, p.target, p.source_ids, p.target_ids, 0.8);
  const std::vector<int> b = largestConsistentSet(p.source, p.target, p.source_ids, p.target_ids, 0.8);
  EXPECT_EQ(a, b);
}

TEST(LargestConsistentSet, EmptyAndSingle) {
  EXPECT_TRUE(largestConsistentSet({}, {}, {}, {}, 0.8).empty());
  const std::vector<int> one = largestConsistentSet({Eigen::Vector3d::Zero()}, {Eigen::Vector3d::Ones()}, {0}, {0}, 0.8);
  EXPECT_EQ(one, std::vector<int>{0});
}

// --- matchFrames on real nodes --------------------------------------------------------------------------------------

std::vector<Node> scanNodes(const std::string& name) {
  return NodeExtractor({}, {}).extract(test::kittiScan(name)).nodes;
}

/// KITTI 00 frame 52's nodes, and the same nodes moved, with every pole and trunk but four turned into a node of
/// another place: the descriptors (built from the whole graph around each node) then disagree, as they do when a
/// place is seen from the other side, but four of the true nodes are still where the motion puts them.
class ConsistencyPath : public ::testing::Test {
 protected:
  void SetUp() override {
    query_ = scanNodes("000052");
    T_ = rigid(150.0, 0.0, 0.0, Eigen::Vector3d(4.0, -2.0, 0.1));
    match_ = query_;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> shift(-25.0, 25.0);
    for (size_t k = 0; k < match_.size(); ++k) {
      match_[k].centre = apply(T_, match_[k].centre);
      if (k % 3 != 0) match_[k].centre += Eigen::Vector3d(shift(rng), shift(rng), 0.0);
    }
    config_.verification.min_footprint_overlap = 0.0;  // nodes alone have no footprint
  }
  std::vector<Node> query_, match_;
  Eigen::Matrix4d T_;
  Config config_;
};

TEST_F(ConsistencyPath, FindsTheRevisitWhereTheDescriptorsDisagree) {
  const LabeledCloud scan = test::kittiScan("000052");
  const LabelMap labels(Config{}.labels);
  Config config;  // the defaults: footprint check on
  DescribedFrame q = describeFrame(query_, config.graph, config.descriptor);
  DescribedFrame m = describeFrame(match_, config.graph, config.descriptor);
  q.footprint = computeFootprint(scan, labels, config.verification);
  m.footprint = computeFootprint(test::transformed(scan, T_), labels, config.verification);

  Config off = config;
  off.verification.consistency_pairs = 0;
  const MatchResult paper = matchFrames(q, m, off);
  EXPECT_FALSE(isLoop(paper, off.verification)) << paper.inliers.size() << " inliers";

  const MatchResult r = matchFrames(q, m, config);
  ASSERT_TRUE(isLoop(r, config.verification)) << r.inliers.size() << " inliers, rejection " << rejectionName(r.rejection);
  EXPECT_TRUE(r.by_consistency);
  EXPECT_GE(r.footprint.share, config.verification.weak_min_footprint);
  const test::PoseError e = test::poseError(r.T_match_query, T_);
  EXPECT_LT(e.translation_m, 0.05);
  EXPECT_LT(e.rotation_deg, 0.1);
  // Every inlier is a node that the motion moved unchanged (every third), paired with itself.
  for (int k : r.inliers) {
    const NodeMatch& a = r.associations[static_cast<size_t>(k)];
    EXPECT_EQ(a.query, a.match);
    EXPECT_EQ(a.query % 3, 0);
  }
  EXPECT_EQ(r.inliers.size(), (query_.size() + 2) / 3);
}

TEST_F(ConsistencyPath, AMirrorImageIsConsistentButNotALoop) {
  // Frame 52's nodes mirrored (y → −y): every distance is kept, so the pairs of each node with its mirror image
  // are one consistent set, but no rotation maps a scene onto its mirror image: the nearest one is upside down
  // (the upright check) and leaves residuals of metres.
  std::vector<Node> mirrored = query_;
  for (Node& n : mirrored) n.centre.y() = -n.centre.y();
  std::vector<Eigen::Vector3d> a, b;
  std::vector<int> ids;
  for (size_t k = 0; k < query_.size(); ++k) {
    a.push_back(query_[k].centre);
    b.push_back(mirrored[k].centre);
    ids.push_back(static_cast<int>(k));
  }
  EXPECT_EQ(largestConsistentSet(a, b, ids, ids, 0.8).size(), query_.size());
  const LabeledCloud scan = test::kittiScan("000052");
  const Config config;
  DescribedFrame q = describeFrame(query_, config.graph, config.descriptor);
  DescribedFrame m = describeFrame(mirrored, config.graph, config.descriptor);
  q.footprint = computeFootprint(scan, LabelMap(config.labels), config.verification);
  m.footprint = q.footprint;
  const MatchResult r = matchFrames(q, m, config);
  EXPECT_FALSE(isLoop(r, config.verification)) << r.inliers.size() << " inliers";
}

TEST_F(ConsistencyPath, NeedsAFootprintToJudgeIt) {
  const DescribedFrame q = describeFrame(query_, config_.graph, config_.descriptor);
  const DescribedFrame m = describeFrame(match_, config_.graph, config_.descriptor);
  // Without footprints the path does not answer (its chance agreements would go unchecked).
  const MatchResult r = matchFrames(q, m, Config{});
  EXPECT_FALSE(r.by_consistency);
}

TEST_F(ConsistencyPath, HypothesisPairsKeepTheClassAndTheLimit) {
  const DescribedFrame q = describeFrame(query_, config_.graph, config_.descriptor);
  const DescribedFrame m = describeFrame(match_, config_.graph, config_.descriptor);
  for (int per_node : {1, 3, 16}) {
    const std::vector<NodeMatch> pairs = hypothesisPairs(q, m, per_node, config_.association, config_.descriptor);
    std::vector<int> per_query(q.numNodes(), 0);
    for (const NodeMatch& p : pairs) {
      EXPECT_EQ(q.graph.nodes[p.query].label, m.graph.nodes[p.match].label);
      ++per_query[p.query];
    }
    for (int i = 0; i < q.numNodes(); ++i) {
      const int same_class = static_cast<int>(std::count_if(m.graph.nodes.begin(), m.graph.nodes.end(),
          [&](const Node& n) { return n.label == q.graph.nodes[i].label; }));
      EXPECT_EQ(per_query[i], q.graph.isolated[i] ? 0 : std::min(per_node, same_class)) << i;
    }
  }
}

}  // namespace
}  // namespace sgtllc
