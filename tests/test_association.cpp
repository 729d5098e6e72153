// Node association (algorithm §6): node similarity and the association of hand-built descriptors.
#include <algorithm>
#include <tuple>

#include <gtest/gtest.h>

#include "sgtllc/association.h"
#include "sgtllc/frame.h"
#include "test_support.h"

namespace {

using sgtllc::AssociationConfig;
using sgtllc::DescribedFrame;
using sgtllc::LocalDescriptor;
using sgtllc::Node;
using sgtllc::SubVectorOrder;

LocalDescriptor des(const std::vector<std::pair<int, Eigen::Vector3f>>& slots) {
  LocalDescriptor d;
  for (auto& s : d.slots) s.setZero();
  for (const auto& [alpha, v] : slots) {
    d.slots[alpha] = v;
    d.valid |= uint64_t{1} << alpha;
  }
  return d;
}

double similarity(const LocalDescriptor& q, const LocalDescriptor& m, double sigma_1 = 0.9,
                  SubVectorOrder order = SubVectorOrder::kPaper, sgtllc::NodeScore score = sgtllc::NodeScore::kRatio) {
  AssociationConfig cfg;
  cfg.sigma_1 = sigma_1;
  cfg.score = score;
  sgtllc::DescriptorConfig descriptor;
  descriptor.order = order;
  return sgtllc::nodeSimilarity(q, m, cfg, descriptor);
}

DescribedFrame frameOf(const std::vector<std::pair<int, LocalDescriptor>>& nodes, const std::vector<int>& isolated) {
  DescribedFrame f;
  for (size_t i = 0; i < nodes.size(); ++i) {
    f.graph.nodes.push_back(Node{Eigen::Vector3d(static_cast<double>(i), 0, 0), nodes[i].first});
    f.local.push_back(nodes[i].second);
    f.graph.isolated.push_back(std::count(isolated.begin(), isolated.end(), static_cast<int>(i)) ? 1 : 0);
  }
  return f;
}

std::vector<std::tuple<int, int, double>> tuples(const std::vector<sgtllc::NodeMatch>& la) {
  std::vector<std::tuple<int, int, double>> out;
  for (const auto& m : la) out.emplace_back(m.query, m.match, m.similarity);
  return out;
}

// --- (c) nodeSimilarity / associateNodes on hand-built descriptors -------------------------------------------------

TEST(NodeSimilarity, RatioAndCountOverValidQuerySlots) {
  const LocalDescriptor q = des({{0, {1, 2, 3}}, {1, {10, 0, 0}}, {2, {0, 5, 0}}, {3, {3, 4, 0}}});
  LocalDescriptor m = des({{0, {2, 4, 6}},      // same direction, |Δa_j| = 2: match
                           {1, {0, 10, 0}},     // orthogonal: no match
                           {2, {0, 5, 0.1f}},   // match
                           {4, {1, 1, 1}}});    // valid only in the match: ignored
  m.slots[3] = {3, 4, 0};                       // identical values but not valid in the match: no match
  EXPECT_DOUBLE_EQ(similarity(q, m), 0.5);      // 2 of the 4 valid query slots
  EXPECT_DOUBLE_EQ(similarity(q, m, 0.9, SubVectorOrder::kPaper, sgtllc::NodeScore::kCount), 2.0);
  EXPECT_DOUBLE_EQ(similarity(des({}), m), 0.0);
  EXPECT_DOUBLE_EQ(similarity(q, q), 1.0);
}

TEST(NodeSimilarity, CosineThresholdIsStrict) {
  const LocalDescriptor u = des({{5, {3, 4, 0}}});
  EXPECT_DOUBLE_EQ(similarity(u, u, 0.999), 1.0);
  EXPECT_DOUBLE_EQ(similarity(u, u, 1.0), 0.0);  // cos = 1 exactly, not > 1
  const LocalDescriptor v = des({{5, {4, 3, 0}}});  // cos = 24 / 25 = 0.96
  EXPECT_DOUBLE_EQ(similarity(u, v, 0.95), 1.0);
  EXPECT_DOUBLE_EQ(similarity(u, v, 0.97), 0.0);
  EXPECT_DOUBLE_EQ(similarity(u, des({{5, {-3, -4, 0}}}), -0.9), 0.0);  // cos = −1 is not > −0.9
}

TEST(NodeSimilarity, DeltaAjIsStrictAndFollowsTheOrder) {
  // Paper order: a_j is entry 1. Code order: entry 2 holds −a_j.
  const LocalDescriptor u = des({{7, {1, 100, 0}}});
  EXPECT_DOUBLE_EQ(similarity(u, des({{7, {1, 200, 0}}})), 0.0);    // |Δ| = 100, not < 100
  EXPECT_DOUBLE_EQ(similarity(u, des({{7, {1, 199.5f, 0}}})), 1.0);
  EXPECT_DOUBLE_EQ(similarity(u, des({{7, {1, 200, 0}}}), 0.9, SubVectorOrder::kCode), 1.0);  // entry 2 equal
  const LocalDescriptor w = des({{7, {1, 0, -100}}});
  EXPECT_DOUBLE_EQ(similarity(w, des({{7, {1, 0, -200}}}), 0.9, SubVectorOrder::kCode), 0.0);
  EXPECT_DOUBLE_EQ(similarity(w, des({{7, {1, 0, -199.5f}}}), 0.9, SubVectorOrder::kCode), 1.0);
  EXPECT_DOUBLE_EQ(similarity(w, des({{7, {1, 0, -200}}})), 1.0);  // paper order: entry 1 equal
}

TEST(AssociateNodes, SameLabelBestMatchTiesAndThreshold) {
  using sgtllc::kBuilding, sgtllc::kPole, sgtllc::kTrunk, sgtllc::kVegetation;
  const LocalDescriptor a = des({{0, {1, 2, 3}}, {9, {4, 1, 2}}, {20, {2, 2, 7}}, {33, {5, 1, 1}}});
  const LocalDescriptor half = des({{0, {1, 2, 3}}, {9, {4, 1, 2}}, {20, {-7, 0, 2}}, {33, {-1, 5, 0}}});
  const LocalDescriptor quarter = des({{0, {1, 2, 3}}});
  const DescribedFrame query = frameOf(
      {{kBuilding, a}, {kBuilding, a}, {kPole, a}, {kBuilding, a}, {kVegetation, a}}, /*isolated=*/{1});
  const DescribedFrame match =
      frameOf({{kTrunk, a}, {kBuilding, half}, {kBuilding, a}, {kBuilding, a}, {kPole, quarter}}, {});
  AssociationConfig cfg;
  cfg.sigma_2 = 0.3;  // the paper's value: q2's 0.25 falls below it
  // q0 → m2 (m0 is identical but a trunk; m2 and m3 tie: lowest j); q1 isolated; q2's best is 0.25 < σ_2; q3 shares
  // m2 with q0; q4 has no vegetation candidate.
  using T3 = std::vector<std::tuple<int, int, double>>;
  EXPECT_EQ(tuples(sgtllc::associateNodes(query, match, cfg, sgtllc::DescriptorConfig{})), (T3{{0, 2, 1.0}, {3, 2, 1.0}}));
  cfg.sigma_2 = 0.25;  // S ≥ σ_2 accepts equality
  EXPECT_EQ(tuples(sgtllc::associateNodes(query, match, cfg, sgtllc::DescriptorConfig{})),
            (T3{{0, 2, 1.0}, {2, 4, 0.25}, {3, 2, 1.0}}));
  cfg.sigma_2 = 0.3;
  cfg.score = sgtllc::NodeScore::kCount;
  EXPECT_EQ(tuples(sgtllc::associateNodes(query, match, cfg, sgtllc::DescriptorConfig{})),
            (T3{{0, 2, 4.0}, {2, 4, 1.0}, {3, 2, 4.0}}));
  // A zero similarity never makes an association, even with σ_2 = 0 (the best starts at 0, strict >).
  cfg.score = sgtllc::NodeScore::kRatio;
  cfg.sigma_2 = 0.0;
  const DescribedFrame zero = frameOf({{kBuilding, des({{40, {0, 0, 9}}})}}, {});
  EXPECT_TRUE(sgtllc::associateNodes(zero, match, cfg, sgtllc::DescriptorConfig{}).empty());
}

}  // namespace
