// Graph (algorithm §3): hand-computed adjacency, paths and ties, and brute-force path references on random node sets
// (local descriptors checked along the reference paths).
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/descriptor.h"
#include "sgtllc/graph.h"
#include "test_graph_support.h"

namespace {

using sgtllc::GraphConfig;
using sgtllc::kNumPaperSlots;
using sgtllc::Node;
using ::testing::HasSubstr;
using namespace sgtllc::test;  // test_graph_support.h

// --- Checks shared by the tests ------------------------------------------------------------------------------------

void expectGraphMatches(const std::vector<Node>& nodes, const GraphConfig& cfg) {
  const auto g = sgtllc::buildGraph(nodes, cfg);
  const RefGraph ref = bruteGraph(nodes, cfg.sigma_d, cfg.allow_k_equals_i);
  const int n = static_cast<int>(nodes.size());
  ASSERT_EQ(g.size(), n);
  for (int a = 0; a < n; ++a) {
    ASSERT_EQ(g.isolated[a] != 0, ref.isolated[a]) << "node " << a;
    for (int b = 0; b < n; ++b) ASSERT_EQ(g.adjacent(a, b), ref.adj[a][b]) << a << "," << b;
    for (int s = 0; s < kNumPaperSlots; ++s) {
      ASSERT_EQ(std::make_pair(g.paths[a][s].j, g.paths[a][s].k), ref.paths[a][s]) << "node " << a << " slot " << s;
    }
  }
  // Local descriptors follow the reference paths (paper order); a k = i winner leaves its slot empty.
  const auto des = sgtllc::computeLocalDescriptors(g, {});
  for (int i = 0; i < n; ++i) {
    for (int s = 0; s < kNumPaperSlots; ++s) {
      const auto [j, k] = ref.paths[i][s];
      const bool triangle = j >= 0 && k != i;
      ASSERT_EQ(des[i].isValid(s), triangle);
      const Eigen::Vector3f want =
          !triangle ? Eigen::Vector3f::Zero()
                : terms(nodes[i].centre, nodes[j].centre, nodes[k].centre).cast<float>().eval();
      ASSERT_EQ(des[i].slots[s], want) << "node " << i << " slot " << s;
    }
  }
}

// --- (a) Hand-built graphs -----------------------------------------------------------------------------------------

TEST(Graph, HandBuiltAdjacency) {
  const auto g = sgtllc::buildGraph(handNodes(), GraphConfig{});
  ASSERT_EQ(g.size(), 5);
  EXPECT_EQ(g.edges(), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}, {1, 3}}));
  EXPECT_DOUBLE_EQ(g.distance(0, 3), 30.0);
  EXPECT_FALSE(g.adjacent(0, 3));  // exactly σ_d: strict <
  EXPECT_FALSE(g.adjacent(3, 0));
  EXPECT_TRUE(g.adjacent(3, 1));
  EXPECT_FALSE(g.adjacent(2, 2));
  EXPECT_DOUBLE_EQ(g.distance(1, 2), 5.0);
  EXPECT_EQ(g.isolated, (std::vector<uint8_t>{0, 0, 0, 0, 1}));
  GraphConfig wider;
  wider.sigma_d = 30.000001;
  EXPECT_TRUE(sgtllc::buildGraph(handNodes(), wider).adjacent(0, 3));
}

TEST(Graph, HandBuiltPaths) {
  const auto g = sgtllc::buildGraph(handNodes(), GraphConfig{});
  using sgtllc::kBuilding, sgtllc::kFence, sgtllc::kVegetation, sgtllc::kPole;
  const auto& t0 = g.paths[0];
  EXPECT_EQ(t0[slot(kFence, kVegetation)].j, 1);
  EXPECT_EQ(t0[slot(kFence, kVegetation)].k, 2);
  EXPECT_EQ(t0[slot(kFence, kPole)].j, 1);
  EXPECT_EQ(t0[slot(kFence, kPole)].k, 3);
  EXPECT_EQ(t0[slot(kVegetation, kFence)].j, 2);
  EXPECT_EQ(t0[slot(kVegetation, kFence)].k, 1);
  EXPECT_FALSE(t0[slot(kFence, kBuilding)].exists());  // only 0→1→0, k = i
  EXPECT_FALSE(t0[slot(kFence, kFence)].exists());
  int count = 0;
  for (const auto& p : t0) count += p.exists();
  EXPECT_EQ(count, 3);
  // Node 3 (pole) reaches only node 1.
  EXPECT_EQ(g.paths[3][slot(kFence, kBuilding)].k, 0);
  EXPECT_EQ(g.paths[3][slot(kFence, kVegetation)].k, 2);
  EXPECT_FALSE(g.paths[3][slot(kFence, kPole)].exists());
  for (const auto& p : g.paths[4]) EXPECT_FALSE(p.exists());

  GraphConfig allow;
  allow.allow_k_equals_i = true;
  const auto ga = sgtllc::buildGraph(handNodes(), allow);
  EXPECT_EQ(ga.paths[0][slot(kFence, kBuilding)].j, 1);
  EXPECT_EQ(ga.paths[0][slot(kFence, kBuilding)].k, 0);
  EXPECT_EQ(ga.paths[3][slot(kFence, kPole)].k, 3);
}

TEST(Graph, HandBuiltTies) {
  // j tie: 0→1→3 and 0→2→4 are both 5 + √125 long; the lower j wins.
  const std::vector<Node> jt = {node(0, 0, 0, 0), node(5, 0, 0, 1), node(-5, 0, 0, 1), node(-5, 5, 0, 5),
                                node(5, 5, 0, 5)};
  const auto gj = sgtllc::buildGraph(jt, GraphConfig{});
  EXPECT_EQ(gj.paths[0][slot(1, 5)].j, 1);
  EXPECT_EQ(gj.paths[0][slot(1, 5)].k, 3);
  // k tie: from j = 1 the poles 2 and 3 are both 5 m away; the lower k wins.
  const std::vector<Node> kt = {node(0, 0, 0, 0), node(0, 5, 0, 1), node(3, 9, 0, 5), node(-3, 9, 0, 5)};
  const auto gk = sgtllc::buildGraph(kt, GraphConfig{});
  EXPECT_EQ(gk.paths[0][slot(1, 5)].k, 2);
  EXPECT_EQ(gk.paths[3][slot(1, 5)].k, 2);
  EXPECT_EQ(gk.paths[2][slot(1, 5)].k, 3);  // k = i is skipped
}

// --- (b) Random node sets against the brute force ------------------------------------------------------------------

TEST(Graph, PathsMatchBruteForceOnRandomNodes) {
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    const int n = 5 + static_cast<int>((seed * 37) % 66);  // 5..70
    SCOPED_TRACE("seed " + std::to_string(seed) + " N " + std::to_string(n));
    for (bool lattice : {false, true}) {
      for (bool allow : {false, true}) {
        GraphConfig cfg;
        cfg.allow_k_equals_i = allow;
        expectGraphMatches(randomNodes(seed, n, lattice), cfg);
      }
    }
  }
}

TEST(Graph, LatticeHasDistancesOfExactlySigmaD) {
  // Guards the lattice cases above: they do exercise the strict σ_d boundary.
  int at_sigma = 0;
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    const auto nodes = randomNodes(seed, 5 + static_cast<int>((seed * 37) % 66), true);
    for (size_t a = 0; a < nodes.size(); ++a) {
      for (size_t b = a + 1; b < nodes.size(); ++b) at_sigma += (nodes[a].centre - nodes[b].centre).norm() == 30.0;
    }
  }
  EXPECT_GT(at_sigma, 0);
}

// --- (c) Bounded size ----------------------------------------------------------------------------------------------

TEST(Graph, MaxNodesIsTheLargestGraphBuilt) {
  GraphConfig cfg;
  cfg.max_nodes = 40;
  EXPECT_EQ(sgtllc::buildGraph(randomNodes(3, 40, false), cfg).size(), 40);
  try {
    sgtllc::buildGraph(randomNodes(3, 41, false), cfg);
    FAIL() << "no error";
  } catch (const sgtllc::Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("the frame has 41 nodes, more than graph.max_nodes = 40"));
  }
  // The default is 1,000: far above real frames (20–70 nodes).
  EXPECT_NO_THROW(sgtllc::checkNodeCount(1000, GraphConfig{}, "f.txt"));
  EXPECT_THROW(sgtllc::checkNodeCount(1001, GraphConfig{}, "f.txt"), sgtllc::Error);
}

}  // namespace
