// The Table IV ablation switches: sub-vector kinds, dropped entries, RANSAC off; and the global descriptor's
// independence from how local slots are stored.
#include <gtest/gtest.h>

#include "sgtllc/association.h"
#include "sgtllc/detector.h"
#include "sgtllc/global_descriptor.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

// A right triangle i = (0,0,0), j = (3,0,0), k = (0,4,0): a = (0, 9, 16); angles cos = (0, 0.6, 0.8);
// opposite sides (5, 4, 3). Node 0's (fence, vegetation) slot is exactly this triangle 0 → 1 → 2.
std::vector<Node> rightTriangleNodes() {
  return {Node{{0, 0, 0}, kBuilding}, Node{{3, 0, 0}, kFence}, Node{{0, 4, 0}, kVegetation}};
}

Eigen::Vector3f slotOf(SubVectorKind kind, SubVectorOrder order = SubVectorOrder::kPaper) {
  DescriptorConfig dc;
  dc.kind = kind;
  dc.order = order;
  const DescribedFrame f = describeFrame(rightTriangleNodes(), GraphConfig{}, dc);
  EXPECT_TRUE(f.local[0].isValid(kNumPaperClasses * kFence + kVegetation));
  return f.local[0].slots[kNumPaperClasses * kFence + kVegetation];
}

TEST(SubVectorKind, HandComputedEntries) {
  EXPECT_TRUE(slotOf(SubVectorKind::kDotProducts).isApprox(Eigen::Vector3f(0, 9, 16)));
  EXPECT_TRUE(slotOf(SubVectorKind::kAngles).isApprox(Eigen::Vector3f(0, 0.6f, 0.8f)));
  EXPECT_TRUE(slotOf(SubVectorKind::kLengths).isApprox(Eigen::Vector3f(5, 4, 3)));
  // The code order stores (e_i, e_k, −e_j) for every kind.
  EXPECT_TRUE(slotOf(SubVectorKind::kAngles, SubVectorOrder::kCode).isApprox(Eigen::Vector3f(0, 0.8f, -0.6f)));
  EXPECT_TRUE(slotOf(SubVectorKind::kLengths, SubVectorOrder::kCode).isApprox(Eigen::Vector3f(5, 3, -4)));
}

TEST(GlobalDescriptor, IndependentOfSlotKindAndOrder) {
  const std::vector<Node> nodes = NodeExtractor({}, {}).extract(test::kittiScan("000088")).nodes;
  for (GlobalMode mode : {GlobalMode::kG1, GlobalMode::kG2, GlobalMode::kG3}) {
    DescriptorConfig base;
    base.global_mode = mode;
    const std::vector<float> reference = describeFrame(nodes, GraphConfig{}, base).global;
    for (SubVectorKind kind : {SubVectorKind::kAngles, SubVectorKind::kLengths}) {
      for (SubVectorOrder order : {SubVectorOrder::kPaper, SubVectorOrder::kCode}) {
        DescriptorConfig dc = base;
        dc.kind = kind;
        dc.order = order;
        EXPECT_EQ(describeFrame(nodes, GraphConfig{}, dc).global, reference);
      }
    }
  }
}

LocalDescriptor oneSlot(const Eigen::Vector3f& v) {
  LocalDescriptor d;
  d.slots[0] = v;
  d.valid = 1;
  return d;
}

TEST(AssociationEntries, DroppingAnEntryIgnoresIt) {
  // u and v agree on the i and j entries and differ only in k: cos over all three is 1/√2 < 0.9.
  const LocalDescriptor u = oneSlot({1, 0, 0}), v = oneSlot({1, 0, 1});
  AssociationConfig ac;
  const DescriptorConfig paper;
  EXPECT_EQ(nodeSimilarity(u, v, ac, paper), 0.0);
  ac.entries = 0b011;  // i, j
  EXPECT_EQ(nodeSimilarity(u, v, ac, paper), 1.0);
  ac.entries = 0b101;  // i, k
  EXPECT_EQ(nodeSimilarity(u, v, ac, paper), 0.0);
  // In the code order the v_k entry is stored second: dropping k must drop index 1.
  DescriptorConfig code;
  code.order = SubVectorOrder::kCode;
  const LocalDescriptor uc = oneSlot({1, 0, 0}), vc = oneSlot({1, 1, 0});
  ac.entries = 0b011;
  EXPECT_EQ(nodeSimilarity(uc, vc, ac, code), 1.0);
  ac.entries = 0b111;
  EXPECT_EQ(nodeSimilarity(uc, vc, ac, code), 0.0);
}

TEST(AssociationEntries, DeltaAjTestOnlyForDotProductsWithTheJEntry) {
  // Same direction, a_j differs by 200 m²: rejected by |Δa_j| < 100 only when it applies.
  const LocalDescriptor u = oneSlot({100, 100, 100}), v = oneSlot({300, 300, 300});
  AssociationConfig ac;
  DescriptorConfig dc;
  EXPECT_EQ(nodeSimilarity(u, v, ac, dc), 0.0);
  ac.entries = 0b101;  // v_j dropped
  EXPECT_EQ(nodeSimilarity(u, v, ac, dc), 1.0);
  ac.entries = 0b111;
  dc.kind = SubVectorKind::kLengths;
  EXPECT_EQ(nodeSimilarity(u, v, ac, dc), 1.0);
}

TEST(WithoutRansac, ScoreIsScoreCAndEveryAssociationFitsThePose) {
  Config config;
  config.verification.use_ransac = false;
  config.association.sigma_2 = 0.3;  // the paper's, as in its Table IV: the default 0.2 leaves outliers to RANSAC
  const PairResult r = comparePair(test::kittiScan("004501"), test::kittiScan("000052"), config);
  ASSERT_EQ(r.match.rejection, Rejection::kNone);
  EXPECT_DOUBLE_EQ(r.match.score, r.match.score_c);
  EXPECT_EQ(r.match.inliers.size(), r.match.associations.size());
  EXPECT_TRUE(r.is_loop);
  // Outliers pull the all-association fit away from the reference, but not far on this pair.
  EXPECT_LT(test::poseError(r.match.T_match_query, test::referencePose4501To52()).translation_m, 1.0);
  // The gates still apply.
  EXPECT_FALSE(comparePair(test::kittiScan("000850"), test::kittiScan("000088"), config).is_loop);
}

}  // namespace
}  // namespace sgtllc
