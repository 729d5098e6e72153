// The top-1 choice among verified candidates (selection.h): hand-built match results with known scores and
// translations, so each case has one right answer.
#include <gtest/gtest.h>

#include "sgtllc/selection.h"

namespace sgtllc {
namespace {

MatchResult verified(double score, double tx, double ty = 0.0) {
  MatchResult m;
  m.rejection = Rejection::kNone;
  m.score = score;
  m.T_match_query(0, 3) = tx;
  m.T_match_query(1, 3) = ty;
  return m;
}

MatchResult rejected(double score_c) {
  MatchResult m;
  m.rejection = Rejection::kFewAssociations;
  m.score_c = score_c;
  return m;
}

int select(const std::vector<MatchResult>& ms, double margin, double sigma_4 = 0.3) {
  VerificationConfig config;
  config.select_margin = margin;
  config.sigma_4 = sigma_4;
  std::vector<const MatchResult*> p;
  for (const MatchResult& m : ms) p.push_back(&m);
  return selectCandidate(p, config);
}

TEST(SelectCandidate, NoVerifiedCandidateSelectsNone) {
  EXPECT_EQ(select({}, 0.1), -1);
  EXPECT_EQ(select({rejected(0.9), rejected(0.2)}, 0.1), -1);
}

TEST(SelectCandidate, ZeroMarginIsTheHighestScoreWithTiesToTheLaterCandidate) {
  // The lateral neighbour (6 m) scores 0.62, the revisit (0.5 m) 0.58: the score alone picks the neighbour.
  const std::vector<MatchResult> ms = {verified(0.58, 0.5), verified(0.62, 6.0), rejected(0.9)};
  EXPECT_EQ(select(ms, 0.0), 1);
  EXPECT_EQ(select({verified(0.5, 1.0), verified(0.5, 9.0)}, 0.0), 1);  // tie: the later one, as the authors' >=
}

TEST(SelectCandidate, WithinTheMarginTheSmallestTranslationWins) {
  const std::vector<MatchResult> ms = {verified(0.58, 0.3, 0.4), verified(0.62, 6.0), verified(0.45, 0.1)};
  EXPECT_EQ(select(ms, 0.05), 0);  // 0.58 ≥ 0.62 − 0.05 and ‖t‖ = 0.5 m < 6 m; 0.45 is outside the margin
  EXPECT_EQ(select(ms, 0.2), 2);   // now 0.45 ≥ 0.42 too, and 0.1 m is the smallest
  EXPECT_EQ(select(ms, 0.03), 1);  // 0.58 < 0.59: only the best is eligible
}

TEST(SelectCandidate, NeverTurnsALoopIntoNoLoop) {
  // Best 0.35 is a loop (> σ_4 = 0.3); 0.28 is within the margin and closer but not a loop, so it is not chosen.
  const std::vector<MatchResult> ms = {verified(0.28, 0.2), verified(0.35, 5.0)};
  EXPECT_EQ(select(ms, 0.1), 1);
  // Below σ_4 nothing is a loop, and the closer candidate within the margin wins.
  EXPECT_EQ(select({verified(0.18, 0.2), verified(0.25, 5.0)}, 0.1), 0);
}

TEST(IsLateral, TheEstimatedOffsetAgainstTheLateralDistance) {
  VerificationConfig config;  // lateral_distance 3 m
  EXPECT_FALSE(isLateral(verified(0.6, 2.97, 0.17), config));  // KITTI 00 4501 → 52: 2.975 m
  EXPECT_TRUE(isLateral(verified(0.6, 3.0), config));          // on the bound: lateral
  EXPECT_TRUE(isLateral(verified(0.6, 0.0, 6.5), config));     // one lane aside
  EXPECT_FALSE(isLateral(rejected(0.9), config));              // no pose, no claim
  config.lateral_distance = 7.0;
  EXPECT_FALSE(isLateral(verified(0.6, 0.0, 6.5), config));
}

}  // namespace
}  // namespace sgtllc
