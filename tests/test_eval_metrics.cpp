// Evaluation metrics against hand-computed PR tables (algorithm §9), including the edge cases, pose errors and
// pair-list parsing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "sgtllc/eval/pair_eval.h"
#include "sgtllc/eval/refinement_stats.h"
#include "test_support.h"

namespace sgtllc::eval {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::vector<ScoredSample> samples(std::initializer_list<std::pair<double, bool>> list) {
  std::vector<ScoredSample> out;
  for (const auto& [score, positive] : list) out.push_back({score, positive});
  return out;
}

TEST(PrCurve, HandComputedTable) {
  // Scores 0.9 T, 0.8 F, 0.7 T, 0.6 T, 0.5 F, 0.4 F (3 positives), deliberately shuffled.
  const PrCurve c = precisionRecallCurve(
      samples({{0.5, false}, {0.9, true}, {0.6, true}, {0.4, false}, {0.8, false}, {0.7, true}}));
  EXPECT_THAT(c.thresholds, ElementsAre(0.9, 0.8, 0.7, 0.6, 0.5, 0.4));
  EXPECT_THAT(c.precision, ElementsAre(1.0, 0.5, 2.0 / 3.0, 0.75, 0.6, 0.5, 1.0));
  EXPECT_THAT(c.recall, ElementsAre(1.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0, 1.0, 1.0, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(f1Max(c), 2 * 0.75 / 1.75);  // at threshold 0.6
  EXPECT_DOUBLE_EQ(recallAt100Precision(c), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(extendedPrecision(c), 0.5 * (1.0 + 1.0 / 3.0));  // top sample is a positive
}

TEST(PrCurve, TiedScoresFormOneThreshold) {
  const PrCurve c = precisionRecallCurve(samples({{0.5, true}, {0.5, false}, {0.3, true}}));
  EXPECT_THAT(c.thresholds, ElementsAre(0.5, 0.3));
  EXPECT_THAT(c.precision, ElementsAre(0.5, 2.0 / 3.0, 1.0));
  EXPECT_THAT(c.recall, ElementsAre(0.5, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(f1Max(c), 0.8);
  EXPECT_DOUBLE_EQ(recallAt100Precision(c), 0.0);  // only the appended point has precision 1
  EXPECT_DOUBLE_EQ(extendedPrecision(c), 0.5);     // the top group holds a positive: P_Rmin = 1
}

TEST(PrCurve, TopGroupWithoutPositiveGivesZeroPrecisionAtMinimalRecall) {
  const PrCurve c = precisionRecallCurve(samples({{0.9, false}, {0.5, true}, {0.2, true}}));
  EXPECT_DOUBLE_EQ(recallAt100Precision(c), 0.0);
  EXPECT_DOUBLE_EQ(extendedPrecision(c), 0.0);
  EXPECT_DOUBLE_EQ(f1Max(c), 0.8);  // threshold 0.2: P 2/3, R 1
}

TEST(PrCurve, NoPositivesAndAllPositives) {
  const PrCurve none = precisionRecallCurve(samples({{0.9, false}, {0.1, false}}));
  EXPECT_EQ(none.positives, 0);
  EXPECT_DOUBLE_EQ(f1Max(none), 0.0);
  EXPECT_DOUBLE_EQ(extendedPrecision(none), 0.0);
  EXPECT_DOUBLE_EQ(recallAt100Precision(none), 0.0);
  const PrCurve all = precisionRecallCurve(samples({{0.9, true}, {0.1, true}, {0.1, true}}));
  EXPECT_DOUBLE_EQ(f1Max(all), 1.0);
  EXPECT_DOUBLE_EQ(extendedPrecision(all), 1.0);
  EXPECT_DOUBLE_EQ(recallAt100Precision(all), 1.0);
  const PrCurve empty = precisionRecallCurve({});
  EXPECT_THAT(empty.precision, ElementsAre(1.0));
  EXPECT_DOUBLE_EQ(f1Max(empty), 0.0);
}

TEST(PrCurve, RecallDenominatorOverride) {
  // Top-1 protocol: 2 predictions, but 4 queries have a true revisit.
  const PrCurve c = precisionRecallCurve(samples({{0.9, true}, {0.1, false}}), 4);
  EXPECT_EQ(c.positives, 4);
  EXPECT_THAT(c.recall, ElementsAre(0.25, 0.25, 0.0));
  EXPECT_DOUBLE_EQ(f1Max(c), 0.4);
}

TEST(PoseMetrics, AnalyticErrors) {
  Eigen::Matrix4d gt = test::rigid(30.0, 0.0, 0.0, Eigen::Vector3d(1, 2, 3));
  Eigen::Matrix4d est = gt * test::rigid(10.0, 0.0, 0.0, Eigen::Vector3d::Zero());
  est.topRightCorner<3, 1>() += Eigen::Vector3d(3, 4, 0);
  const PoseError e = poseError(est, gt);
  EXPECT_NEAR(e.translation_m, 5.0, 1e-12);
  EXPECT_NEAR(e.rotation_deg, 10.0, 1e-9);
  EXPECT_NEAR(poseError(gt, gt).rotation_deg, 0.0, 1e-6);

  const PoseSummary s = summarisePoses({{0.5, 1.0}, {1.5, 3.0}, {2.5, 1.0}, {0.1, 6.0}});
  EXPECT_EQ(s.evaluated, 4);
  EXPECT_EQ(s.successes, 2);
  EXPECT_DOUBLE_EQ(s.success_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.rte_mean, 1.0);
  EXPECT_DOUBLE_EQ(s.rre_mean, 2.0);
  EXPECT_EQ(summarisePoses({}).success_rate, 0.0);
}

TEST(PairList, ParsesAndRejectsMalformedLines) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sgtllc_pairs_" + std::to_string(::getpid()) + ".txt")).string();
  std::ofstream(path) << "# query candidate label\n004501 000052 1\n\n000850 000088 0\r\n";
  const auto pairs = readPairList(path);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].query, 4501);
  EXPECT_EQ(pairs[0].candidate, 52);
  EXPECT_TRUE(pairs[0].loop);
  EXPECT_FALSE(pairs[1].loop);
  for (const char* bad : {"1 2 3\n", "1 2\n", "a 2 1\n", "1 2 1 9\n", "-1 2 1\n"}) {
    std::ofstream(path) << "0 1 0\n" << bad;
    try {
      readPairList(path);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr(path + ":2:"));
    }
  }
  std::filesystem::remove(path);
  EXPECT_THROW(readPairList(path), Error);
}

TEST(RefinementStats, CountsEveryStatusTheFallbacksTheTimeAndTheStore) {
  using S = RefinementStatus;
  // Six frames: four refined loops (two used, two fallbacks), two frames without a refined loop.
  const std::vector<std::optional<S>> statuses = {S::kConverged, std::nullopt, S::kMovedTooFar,
                                                  S::kMaxIterations, std::nullopt, S::kLowFitness};
  const std::vector<double> ms = {4.0, 1.0, 6.0, 5.0, 2.0, 3.0};
  const RefinementStats s = refinementStats(true, statuses, ms, 6 * 1000);
  EXPECT_EQ(s.refined, 4);
  EXPECT_EQ(s.used, 2);
  EXPECT_EQ(s.fallbacks(), 2);
  EXPECT_THAT(s.by_status, ElementsAre(1, 1, 0, 0, 1, 1));
  EXPECT_DOUBLE_EQ(s.ms_per_frame_mean, 3.5);
  EXPECT_DOUBLE_EQ(s.ms_per_frame_median, 4.0);  // nearest rank of 1..6 at q = 0.5: index 3 (0.5 · 5 + 0.5)
  EXPECT_DOUBLE_EQ(s.cloud_bytes_per_frame, 1000.0);
  EXPECT_EQ(refinementLine(s),
            "refinement: 4 loops refined, 2 used (converged 1, max_iterations 1); kept the SVD pose 2 "
            "(too_few_points 0, degenerate 0, low_fitness 1, moved_too_far 1); 4.00 ms per frame median (mean 3.50); "
            "cloud store 1000 bytes per frame\n");
  EXPECT_EQ(refinementLine(refinementStats(false, {}, {}, 0)), "refinement: off (registration.online: false)\n");
}

}  // namespace
}  // namespace sgtllc::eval
