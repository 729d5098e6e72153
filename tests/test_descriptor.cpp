// Local descriptors (algorithm §4) and global descriptors (§5): hand-computed slot values and cells, brute-force pooling
// references on random node sets, and rigid-motion invariance on a real KITTI scan.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sgtllc/descriptor.h"
#include "sgtllc/frame.h"
#include "sgtllc/global_descriptor.h"
#include "sgtllc/graph.h"
#include "sgtllc/node_extraction.h"
#include "test_graph_support.h"
#include "test_kitti_support.h"

namespace {

using sgtllc::GlobalMode;
using sgtllc::GraphConfig;
using sgtllc::kNumPaperSlots;
using sgtllc::Node;
using sgtllc::SubVectorOrder;
using namespace sgtllc::test;  // test_graph_support.h, test_support.h

// --- Rigid motions -------------------------------------------------------------------------------------------------

std::vector<Node> transformed(const std::vector<Node>& nodes, const Eigen::Isometry3d& T) {
  std::vector<Node> out = nodes;
  for (Node& n : out) n.centre = T * n.centre;
  return out;
}

/// Yaw anywhere, roll and pitch within ±max_tilt_deg, shift within ±max_shift per axis.
Eigen::Isometry3d randomRigid(std::mt19937& rng, double max_tilt_deg, double max_shift) {
  std::uniform_real_distribution<double> yaw(0.0, 2.0 * M_PI), tilt(-max_tilt_deg, max_tilt_deg),
      shift(-max_shift, max_shift);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw(rng), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(tilt(rng) * M_PI / 180.0, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(tilt(rng) * M_PI / 180.0, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(shift(rng), shift(rng), shift(rng));
  return T;
}

// --- Brute-force references ----------------------------------------------------------------------------------------

/// Des^G from algorithm §5 / global_descriptor.h with the reference paths, in double. G1 pools a_k (the paper's
/// Des[α][2] in its own order) whatever the storage order.
std::vector<double> bruteGlobal(const std::vector<Node>& nodes, const RefGraph& g, GlobalMode mode,
                                SubVectorOrder order) {
  std::vector<double> des(mode == GlobalMode::kG2 ? 343 : 98, 0.0);
  for (size_t i = 0; i < nodes.size(); ++i) {
    for (int a = 0; a < kNumPaperSlots; ++a) {
      const auto [j, k] = g.paths[i][a];
      if (j < 0) continue;
      const int o = nodes[i].label, m = a / 7, n = a % 7, fuzzy = m <= 2 ? 0 : 1;
      const Eigen::Vector3d pi = nodes[i].centre, pj = nodes[j].centre, pk = nodes[k].centre;
      const double cos_k = (pi - pk).dot(pj - pk) / ((pi - pk).norm() * (pj - pk).norm());
      const Eigen::Vector3d t = terms(pi, pj, pk);
      (void)order;  // the storage order must not change Des^G
      const double value = mode == GlobalMode::kG1 ? t[2] : 1.0 - cos_k;
      const int cell = mode == GlobalMode::kG2 ? 49 * o + a : 14 * o + 7 * fuzzy + n;
      des[cell] = std::max(des[cell], value);
    }
  }
  return des;
}

// --- Checks shared by the tests ------------------------------------------------------------------------------------

/// Checks a whole descriptor: the listed cells hold the given values, every other cell is 0.
void expectCells(const std::vector<float>& des, size_t size, const std::map<int, double>& cells) {
  ASSERT_EQ(des.size(), size);
  for (size_t c = 0; c < size; ++c) {
    const auto it = cells.find(static_cast<int>(c));
    EXPECT_NEAR(des[c], it == cells.end() ? 0.0 : it->second, 1e-5) << "cell " << c;
  }
}

/// The bundled scan 000052 (data/kitti/00).
sgtllc::LabeledCloud loadScan52() { return kittiScan("000052"); }

/// Local descriptors (slot by slot, relative 1e-4) and all three global descriptors of two node sets agree; node i
/// of @p a corresponds to node i of @p b.
void expectSameDescriptors(const std::vector<Node>& a, const std::vector<Node>& b) {
  for (GlobalMode mode : {GlobalMode::kG1, GlobalMode::kG2, GlobalMode::kG3}) {
    sgtllc::DescriptorConfig cfg;
    cfg.global_mode = mode;
    const auto fa = sgtllc::describeFrame(a, GraphConfig{}, cfg);
    const auto fb = sgtllc::describeFrame(b, GraphConfig{}, cfg);
    for (size_t i = 0; i < a.size(); ++i) {
      const auto& da = fa.local[i];
      const auto& db = fb.local[i];
      ASSERT_EQ(da.valid, db.valid) << "node " << i;
      for (int s = 0; s < kNumPaperSlots; ++s) {
        const float tol = 1e-4f * std::max(1.0f, da.slots[s].cwiseAbs().maxCoeff());
        ASSERT_LE((da.slots[s] - db.slots[s]).cwiseAbs().maxCoeff(), tol) << "node " << i << " slot " << s;
      }
    }
    ASSERT_EQ(fa.global.size(), fb.global.size());
    for (size_t c = 0; c < fa.global.size(); ++c) {
      EXPECT_NEAR(fa.global[c], fb.global[c], 1e-4 * std::max(1.0f, std::abs(fa.global[c]))) << "cell " << c;
    }
  }
}

// --- (a) Hand-built node set ---------------------------------------------------------------------------------------

TEST(Descriptor, HandBuiltSlotValues) {
  const auto g = sgtllc::buildGraph(handNodes(), GraphConfig{});
  sgtllc::DescriptorConfig paper;
  const auto des = sgtllc::computeLocalDescriptors(g, paper);
  ASSERT_EQ(des.size(), 5u);
  const auto& d0 = des[0];
  // Right triangle i=(0,0,0), j=(3,0,0), k=(0,4,0): a_i = 0, a_j = 9, a_k = 16 (|ij|² = 9, |ik|² = 16, |jk|² = 25).
  EXPECT_EQ(d0.slots[slot(1, 2)], Eigen::Vector3f(0, 9, 16));
  // i=(0,0,0), j=(0,4,0), k=(3,0,0): a_i = 0, a_j = 16, a_k = 9.
  EXPECT_EQ(d0.slots[slot(2, 1)], Eigen::Vector3f(0, 16, 9));
  // Collinear i=0, j=3, k=30 on the x axis: a_i = 3·30 = 90, a_j = (−3)·27 = −81, a_k = (−30)·(−27) = 810.
  EXPECT_EQ(d0.slots[slot(1, 5)], Eigen::Vector3f(90, -81, 810));
  EXPECT_EQ(d0.valid, (uint64_t{1} << slot(1, 2)) | (uint64_t{1} << slot(2, 1)) | (uint64_t{1} << slot(1, 5)));
  EXPECT_EQ(d0.numValid(), 3);
  EXPECT_TRUE(d0.isValid(slot(1, 2)));
  EXPECT_FALSE(d0.isValid(slot(1, 0)));
  EXPECT_EQ(d0.slots[slot(1, 0)], Eigen::Vector3f::Zero());
  const auto flat = d0.flat();
  EXPECT_EQ(flat[3 * slot(1, 2) + 1], 9.0f);
  EXPECT_EQ(flat[3 * slot(1, 5) + 2], 810.0f);
  EXPECT_EQ(des[4].valid, 0u);  // isolated
  EXPECT_EQ(des[4].numValid(), 0);
  for (float v : des[4].flat()) EXPECT_EQ(v, 0.0f);
  EXPECT_EQ(des[3].numValid(), 2);

  sgtllc::DescriptorConfig code;
  code.order = SubVectorOrder::kCode;  // (a_i, a_k, −a_j)
  const auto dc = sgtllc::computeLocalDescriptors(g, code);
  EXPECT_EQ(dc[0].slots[slot(1, 2)], Eigen::Vector3f(0, 16, -9));
  EXPECT_EQ(dc[0].slots[slot(1, 5)], Eigen::Vector3f(90, 810, 81));
  EXPECT_EQ(dc[0].valid, d0.valid);
  EXPECT_EQ(sgtllc::slotTerms(dc[0].slots[slot(1, 5)], SubVectorOrder::kCode), Eigen::Vector3d(90, -81, 810));
  EXPECT_EQ(sgtllc::slotTerms(d0.slots[slot(1, 5)], SubVectorOrder::kPaper), Eigen::Vector3d(90, -81, 810));
  EXPECT_EQ(sgtllc::vjEntry(SubVectorOrder::kPaper), 1);
  EXPECT_EQ(sgtllc::vjEntry(SubVectorOrder::kCode), 2);
}

TEST(Descriptor, KEqualsISlot) {
  GraphConfig allow;
  allow.allow_k_equals_i = true;
  const auto g = sgtllc::buildGraph(handNodes(), allow);
  const auto des = sgtllc::computeLocalDescriptors(g, {});
  // 0→1→0 wins node 0's (fence, building) slot, but the degenerate triangle (a_i = a_k = 0) leaves it empty, as
  // the authors' code never enables it (algorithm §3, §4); the same for 0→2→0.
  EXPECT_EQ(g.paths[0][slot(1, 0)].j, 1);
  EXPECT_EQ(g.paths[0][slot(1, 0)].k, 0);
  EXPECT_FALSE(des[0].isValid(slot(1, 0)));
  EXPECT_EQ(des[0].slots[slot(1, 0)], Eigen::Vector3f(0, 0, 0));
  EXPECT_EQ(des[0].numValid(), 3);
  const auto without = sgtllc::computeLocalDescriptors(sgtllc::buildGraph(handNodes(), GraphConfig{}), {});
  EXPECT_EQ(without[0].numValid(), 3);
  EXPECT_EQ(sgtllc::triangleTerms({0, 0, 0}, {3, 0, 0}, {0, 0, 0}), Eigen::Vector3d(0, 9, 0));
}

TEST(GlobalDescriptor, HandBuilt) {
  // Triangles of handNodes() (i, j, k → a_k, |ik|, |jk|), worked out by hand:
  //   node 0 (building): (fence, veg) 0→1→2: 16, 4, 5 · (veg, fence) 0→2→1: 9, 3, 5 · (fence, pole) 0→1→3: 810, 30, 27
  //   node 1 (fence):    (building, veg) 1→0→2: 16, 5, 4 · (veg, building) 1→2→0: 0, 3, 4
  //   node 2 (veg):      (building, fence) 2→0→1: 9, 5, 3 · (fence, building) 2→1→0: 0, 4, 3
  //                      (fence, pole) 2→1→3: 810, √916, 27
  //   node 3 (pole):     (fence, building) 3→1→0: 90, 30, 3 · (fence, veg) 3→1→2: 106, √916, 5
  const auto g = sgtllc::buildGraph(handNodes(), GraphConfig{});
  const auto des = sgtllc::computeLocalDescriptors(g, {});
  const double r916 = std::sqrt(916.0);
  const double c2 = 1.0 - 810.0 / (r916 * 27.0), c3 = 1.0 - 106.0 / (r916 * 5.0);
  sgtllc::DescriptorConfig cfg;
  // G1: cell 14·o + 7·fuzzy(m) + n, max a_k (cells that only see a_k ≤ 0 stay 0).
  cfg.global_mode = GlobalMode::kG1;
  expectCells(sgtllc::computeGlobalDescriptor(g, cfg), 98,
              {{2, 16}, {1, 9}, {5, 810}, {16, 16}, {29, 9}, {33, 810}, {70, 90}, {72, 106}});
  // G2: cell 49·o + 7·m + n, 1 − cos θ_k.
  cfg.global_mode = GlobalMode::kG2;
  expectCells(sgtllc::computeGlobalDescriptor(g, cfg), 343,
              {{9, 0.2}, {15, 0.4}, {51, 0.2}, {63, 1.0}, {99, 0.4}, {105, 1.0}, {110, c2}, {254, c3}});
  // G3: the G1 cells with the G2 values.
  cfg.global_mode = GlobalMode::kG3;
  expectCells(sgtllc::computeGlobalDescriptor(g, cfg), 98,
              {{2, 0.2}, {1, 0.4}, {16, 0.2}, {14, 1.0}, {29, 0.4}, {28, 1.0}, {33, c2}, {72, c3}});
}

TEST(GlobalDescriptor, DegenerateTriangleNeverUpdates) {
  // A pole centred exactly on the building: the triangle 0→1→2 (building → fence → pole) has |ik| = 0, so there
  // is no angle at k. The slot is a valid triangle (a_i = 0, a_j = 9, a_k = 0), but G2/G3 must not take a value
  // from it and every cell stays finite.
  const std::vector<Node> nodes = {node(0, 0, 0, sgtllc::kBuilding), node(3, 0, 0, sgtllc::kFence), node(0, 0, 0, sgtllc::kPole)};
  const auto g = sgtllc::buildGraph(nodes, GraphConfig{});
  const auto des = sgtllc::computeLocalDescriptors(g, {});
  ASSERT_TRUE(des[0].isValid(slot(sgtllc::kFence, sgtllc::kPole)));
  EXPECT_EQ(des[0].slots[slot(sgtllc::kFence, sgtllc::kPole)], Eigen::Vector3f(0, 9, 0));
  sgtllc::DescriptorConfig cfg;
  cfg.global_mode = GlobalMode::kG2;
  const auto g2 = sgtllc::computeGlobalDescriptor(g, cfg);
  for (float v : g2) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(g2[49 * sgtllc::kBuilding + slot(sgtllc::kFence, sgtllc::kPole)], 0.0f);
  cfg.global_mode = GlobalMode::kG3;
  const auto g3 = sgtllc::computeGlobalDescriptor(g, cfg);
  for (float v : g3) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(g3[14 * sgtllc::kBuilding + 7 * 0 + sgtllc::kPole], 0.0f);
  // With k = i allowed, the path 0→1→0 wins node 0's (fence, building) slot and leaves it empty: no update either.
  GraphConfig allow;
  allow.allow_k_equals_i = true;
  const auto ga = sgtllc::buildGraph(handNodes(), allow);
  const auto da = sgtllc::computeLocalDescriptors(ga, {});
  EXPECT_FALSE(da[0].isValid(slot(sgtllc::kFence, sgtllc::kBuilding)));
  const auto g2a = sgtllc::computeGlobalDescriptor(ga, cfg);
  for (float v : g2a) EXPECT_TRUE(std::isfinite(v));
}

// --- (b) Random node sets against the brute force ------------------------------------------------------------------

TEST(GlobalDescriptor, MatchesBruteForceOnRandomGraph) {
  for (uint32_t seed : {3u, 8u}) {
    const auto nodes = randomNodes(seed, 45, false);
    const RefGraph ref = bruteGraph(nodes, 30.0, false);
    for (GlobalMode mode : {GlobalMode::kG1, GlobalMode::kG2, GlobalMode::kG3}) {
      for (SubVectorOrder order : {SubVectorOrder::kPaper, SubVectorOrder::kCode}) {
        sgtllc::DescriptorConfig cfg;
        cfg.global_mode = mode;
        cfg.order = order;
        const auto frame = sgtllc::describeFrame(nodes, GraphConfig{}, cfg);
        const std::vector<double> want = bruteGlobal(nodes, ref, mode, order);
        ASSERT_EQ(static_cast<int>(frame.global.size()), sgtllc::globalDescriptorSize(mode));
        ASSERT_EQ(frame.global.size(), want.size());
        int nonzero = 0;
        for (size_t c = 0; c < want.size(); ++c) {
          EXPECT_NEAR(frame.global[c], want[c], 2e-5 * std::max(1.0, std::abs(want[c]))) << "cell " << c;
          nonzero += want[c] != 0.0;
        }
        EXPECT_GT(nonzero, 20);
      }
    }
  }
  EXPECT_EQ(sgtllc::globalDescriptorSize(GlobalMode::kG1), 98);
  EXPECT_EQ(sgtllc::globalDescriptorSize(GlobalMode::kG2), 343);
  EXPECT_EQ(sgtllc::globalDescriptorSize(GlobalMode::kG3), 98);
}

// --- (c) Invariance on the real scan 000052 ------------------------------------------------------------------------

TEST(Invariance, NodeLevelRigidMotion) {
  const auto nodes = sgtllc::NodeExtractor({}, {}).extract(loadScan52()).nodes;
  ASSERT_GE(nodes.size(), 15u);
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 3; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto moved = transformed(nodes, randomRigid(rng, 5.0, 20.0));
    const auto ga = sgtllc::buildGraph(nodes, {});
    const auto gb = sgtllc::buildGraph(moved, {});
    EXPECT_EQ(ga.adjacency, gb.adjacency);
    for (size_t i = 0; i < nodes.size(); ++i) {
      for (int s = 0; s < kNumPaperSlots; ++s) {
        ASSERT_EQ(ga.paths[i][s].j, gb.paths[i][s].j);
        ASSERT_EQ(ga.paths[i][s].k, gb.paths[i][s].k);
      }
    }
    expectSameDescriptors(nodes, moved);
  }
}

/// Moves the points of real scan 52 by motions from @p motion, extracts again with @p config and checks that the
/// nodes come back: trunk, pole and sign clusters (not downsampled) exactly; the voxelised classes see a rotated
/// voxel grid, so a cluster may gain or lose voxels or cross its minimum size (algorithm §11). So: most nodes must
/// have a counterpart within 2 cm, and the descriptors of the graph made of the nodes that came back exactly
/// (< 10 µm: float rounding only) must be unchanged.
template <typename Motion>
void expectNodesMoveWithThePoints(const sgtllc::ClusterConfig& config, Motion motion) {
  const sgtllc::LabeledCloud scan = loadScan52();
  const sgtllc::NodeExtractor extractor(config, {});
  const auto nodes = extractor.extract(scan).nodes;
  std::mt19937 rng(77);
  for (int trial = 0; trial < 2; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Eigen::Isometry3d T = motion(rng);
    sgtllc::LabeledCloud moved = scan;
    for (auto& p : moved.points) p = (T * p.cast<double>()).cast<float>();
    const auto moved_nodes = extractor.extract(moved).nodes;
    int within_2cm = 0;
    std::vector<Node> exact_a, exact_b;
    for (const Node& nd : nodes) {
      double best = 1e9;
      int best_k = -1;
      for (size_t k = 0; k < moved_nodes.size(); ++k) {
        const double d = (moved_nodes[k].centre - T * nd.centre).norm();
        if (moved_nodes[k].label == nd.label && d < best) {
          best = d;
          best_k = static_cast<int>(k);
        }
      }
      within_2cm += best < 0.02;
      if (best < 1e-5) {
        exact_a.push_back(nd);
        exact_b.push_back(moved_nodes[best_k]);
      }
    }
    std::cout << "[ point-level ] trial " << trial << ": " << nodes.size() << " nodes, " << moved_nodes.size()
              << " after the motion, " << within_2cm << " within 2 cm, " << exact_a.size() << " within 10 µm\n";
    EXPECT_GE(within_2cm, static_cast<int>(std::ceil(0.9 * nodes.size())));
    EXPECT_GE(within_2cm, static_cast<int>(std::ceil(0.9 * moved_nodes.size())));
    ASSERT_GE(exact_a.size(), 0.8 * nodes.size());
    expectSameDescriptors(exact_a, exact_b);
  }
}

TEST(Invariance, PointLevelRigidMotion) {
  // Any rigid motion, with every node at its points' mean height.
  sgtllc::ClusterConfig config;
  for (auto& c : config.classes) c.centre_height = sgtllc::CentreHeight::kPoints;
  expectNodesMoveWithThePoints(config, [](std::mt19937& rng) { return randomRigid(rng, 4.0, 10.0); });
}

TEST(Invariance, PointLevelMotionOfTheGroundPlane) {
  // The defaults put upright objects' nodes at the sensor's height (algorithm §2), which a turn about the vertical
  // and a shift along the ground keep: what two upright scans of one place differ by.
  expectNodesMoveWithThePoints({}, [](std::mt19937& rng) {
    Eigen::Isometry3d T = randomRigid(rng, 0.0, 10.0);
    T.translation().z() = 0.0;
    return T;
  });
}

}  // namespace
