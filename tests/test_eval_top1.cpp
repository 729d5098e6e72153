// The top-1 protocol with its distance bands and the pair-list protocol on stored nodes, on hand-built records
// whose counts and F1 follow by hand, and `sgtllc eval` reporting all three protocols on a folder with a pair list.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "sgtllc/eval/pair_eval.h"
#include "sgtllc/eval/report.h"
#include "sgtllc/pipeline/frame_source.h"
#include "test_cli_support.h"
#include "test_kitti_support.h"

namespace sgtllc::eval {
namespace {

using pipeline::FrameSource;

namespace fs = std::filesystem;

/// A queried frame whose candidates lie at the given (distance, score, verified) and whose top-1 is @p best.
FrameRecord query(bool has_revisit, std::vector<std::tuple<double, double, bool>> candidates, int best) {
  static long next = 100;
  FrameRecord f;
  f.frame = next++;
  f.queried = true;
  f.has_revisit = has_revisit;
  float d2 = 1.0f;
  for (const auto& [distance, score, ok] : candidates) {
    f.candidates.push_back(CandidateRecord{0, ok ? score : 0.0, 0.5, distance, d2,
                                           ok ? Rejection::kNone : Rejection::kFewAssociations, ok ? distance : 0.0});
    d2 += 1.0f;  // the first candidate has the nearest global descriptor
  }
  f.best = best;
  return f;
}

TEST(Top1Protocol, CountsByBandAndF1WithAndWithoutLateralMatches) {
  SequenceRun run;
  run.frames.push_back(query(true, {{1.0, 0.8, true}, {9.0, 0.5, true}}, 0));  // near, 0.8
  run.frames.push_back(query(true, {{8.0, 0.7, true}}, 0));                    // lateral, 0.7
  run.frames.push_back(query(false, {{50.0, 0.4, true}}, 0));                  // far, 0.4
  run.frames.push_back(query(true, {{2.0, 0.0, false}, {40.0, 0.0, false}}, -1));  // none verified: nearest, 2 m
  run.frames.push_back(query(false, {}, -1));                                  // no candidate
  run.frames.push_back(query(true, {{2.0, 0.5, true}}, 0));                    // near, 0.5
  FrameRecord warmup;
  run.frames.push_back(warmup);  // not queried: not counted
  const SequenceMetrics m = computeSequenceMetrics(run, EvalOptions{});
  EXPECT_EQ(m.n_queries, 6);
  EXPECT_EQ(m.n_revisit_queries, 4);
  EXPECT_EQ(m.top1_counts.near, 3);
  EXPECT_EQ(m.top1_counts.lateral, 1);
  EXPECT_EQ(m.top1_counts.far, 1);
  EXPECT_EQ(m.top1_counts.none, 1);
  // Samples 0.8 T, 0.7 F, 0.5 T, 0.4 F, 0 T against 4 revisit queries: the best F1 is at threshold 0, P 3/5,
  // R 3/4 → 2/3; EP = ½ (1 + 1/4).
  EXPECT_EQ(m.top1.n_positive, 3);
  EXPECT_EQ(m.top1.n_negative, 2);
  EXPECT_DOUBLE_EQ(m.top1.f1_max, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.top1.ep, 0.625);
  // Without the lateral 0.7: 0.8 T, 0.5 T, 0.4 F, 0 T → at 0: P 3/4, R 3/4 → 3/4; EP = ½ (1 + 2/4).
  EXPECT_EQ(m.top1_no_lateral.n_negative, 1);
  EXPECT_DOUBLE_EQ(m.top1_no_lateral.f1_max, 0.75);
  EXPECT_DOUBLE_EQ(m.top1_no_lateral.ep, 0.75);
  EXPECT_DOUBLE_EQ(m.top1_score_only.f1_max, m.top1.f1_max);  // nothing reported lateral here
  const Json j = sequenceMetricsJson(m);
  EXPECT_EQ(j["top1"]["near"], 3);
  EXPECT_EQ(j["top1"]["lateral"], 1);
  EXPECT_EQ(j["top1"]["far"], 1);
  EXPECT_EQ(j["top1"]["no_candidate"], 1);
  EXPECT_DOUBLE_EQ(j["top1_no_lateral"]["f1_max"].get<double>(), 0.75);
}

TEST(Top1Protocol, ATop1TheDetectorReportsAsLateralIsNotClaimedAsARevisit) {
  SequenceRun run;
  run.frames.push_back(query(true, {{1.0, 0.8, true}}, 0));
  run.frames.push_back(query(false, {{8.0, 0.7, true}}, 0));  // a neighbour 8 m away, the pose says so
  run.frames.back().lateral = true;
  run.frames.push_back(query(true, {{2.0, 0.5, true}}, 0));
  const SequenceMetrics m = computeSequenceMetrics(run, EvalOptions{});
  EXPECT_EQ(m.top1_counts.lateral, 1);
  // Reported lateral: score 0, so 0.8 T, 0.5 T, 0 F → F1max 1 at 0.5, EP 1.
  EXPECT_DOUBLE_EQ(m.top1.f1_max, 1.0);
  EXPECT_DOUBLE_EQ(m.top1.ep, 1.0);
  // score alone: 0.8 T, 0.7 F, 0.5 T → at 0.5 P 2/3, R 1 → F1 0.8; EP ½ (1 + ½).
  EXPECT_DOUBLE_EQ(m.top1_score_only.f1_max, 0.8);
  EXPECT_DOUBLE_EQ(m.top1_score_only.ep, 0.75);
}

TEST(Top1Protocol, LateralLoopsAreCountedApart) {
  SequenceRun run;
  for (double d : {1.0, 3.0, 12.0, 20.0, 20.5}) {
    FrameRecord f = query(true, {{d, 0.6, true}}, 0);
    f.is_loop = true;
    f.lateral = d >= 12.0;  // the detector's own estimate: here it calls the 12 m, 20 m and 20.5 m ones lateral
    run.frames.push_back(f);
  }
  const SequenceMetrics m = computeSequenceMetrics(run, EvalOptions{});
  EXPECT_EQ(m.loops_true, 1);
  EXPECT_EQ(m.loops_lateral, 3);  // 3 m and 20 m are in the band (a positive is < 3 m, a negative > 20 m)
  EXPECT_EQ(m.loops_false, 1);
  EXPECT_EQ(m.loops_reported_lateral, 3);
  EXPECT_EQ(sequenceMetricsJson(m)["loops"]["lateral"], 3);
  EXPECT_EQ(sequenceMetricsJson(m)["loops"]["reported_lateral"], 3);
}

TEST(PairListProtocol, StoredNodesScoreAsTheScansDo) {
  const std::string seq = test::dataPath("kitti/00");
  const Config config;
  const FrameSource source = FrameSource::semanticKitti(seq, config);
  std::vector<long> numbers;
  std::vector<std::vector<Node>> nodes;
  for (size_t i = 0; i < source.size(); ++i) {
    numbers.push_back(source.number(i));
    nodes.push_back(source.load(i).nodes);
  }
  const std::vector<LoopPairLabel> pairs = {{4501, 52, true}, {850, 88, false}, {4501, 88, false}, {7, 3, false}};
  const GroundTruth truth = GroundTruth::fromKitti(seq + "/poses.txt", seq + "/calib.txt");
  const PairListRun a = runPairListEvaluation(source, pairs, truth, config, EvalOptions{});
  const PairListRun b = runPairListEvaluation(numbers, nodes, pairs, truth, config, EvalOptions{});
  ASSERT_EQ(b.pairs.size(), 4u);
  EXPECT_EQ(b.unavailable, 1);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(a.pairs[k].available, b.pairs[k].available);
    EXPECT_EQ(a.pairs[k].score, b.pairs[k].score);
    EXPECT_EQ(a.pairs[k].is_loop, b.pairs[k].is_loop);
  }
  EXPECT_TRUE(b.pairs[0].is_loop);
  const PairListMetrics m = computePairListMetrics(b, EvalOptions{});
  EXPECT_EQ(m.n_available, 3);
  EXPECT_EQ(m.positives_scored_zero, 0);
  EXPECT_DOUBLE_EQ(m.curve.f1_max, 1.0);
  nodes.pop_back();
  EXPECT_THROW(runPairListEvaluation(numbers, nodes, pairs, truth, config, EvalOptions{}), Error);
}

TEST(PairListProtocol, PositivesScoredZeroAreCounted) {
  PairListRun run;
  const auto add = [&run](LoopPairLabel label, bool available, double score) {
    PairRecord r;
    r.pair = label;
    r.available = available;
    r.score = score;
    r.is_loop = score > 0.3;
    run.pairs.push_back(r);
  };
  add({1, 0, true}, true, 0.0);
  add({2, 0, true}, true, 0.6);
  add({3, 0, false}, true, 0.0);
  add({4, 0, true}, false, 0.0);
  const PairListMetrics m = computePairListMetrics(run, EvalOptions{});
  EXPECT_EQ(m.positives_scored_zero, 1);  // the unavailable one is not scored at all
  EXPECT_EQ(m.correct, 2);
}

class EvalAllProtocols : public test::CliTempDirTest {
 protected:
  EvalAllProtocols() : CliTempDirTest("eval_all") {}
};

TEST_F(EvalAllProtocols, OneCommandReportsTheFoldersPairListToo) {
  const std::string seq = path("seq");
  test::makePlantedSequence(seq);
  // Frame 53 is scan 4501, frame 0 scan 52 (a loop); frame 1 is scan 88.
  std::ofstream(seq + "/loop_pairs.txt") << "53 0 1\n53 1 0\n1 0 0\n";
  const test::CliRun r = test::run("eval " + seq + " --json --report " + path("report"), false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("pair_list"));
  EXPECT_EQ(j["pair_list"]["n_available"], 3);
  EXPECT_EQ(j["pair_list"]["n_positive"], 1);
  EXPECT_EQ(j["pair_list"]["correct"], 3);
  EXPECT_EQ(j["pair_list"]["positives_scored_zero"], 0);
  EXPECT_DOUBLE_EQ(j["pair_list"]["f1_max"].get<double>(), 1.0);
  EXPECT_EQ(j["top1"]["near"], 1);
  std::ifstream md(path("report") + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## Pair list"), std::string::npos);
  EXPECT_NE(text.find("## Top-1 per query"), std::string::npos);
  const test::CliRun skipped = test::run("eval " + seq + " --json --no-pairs", false);
  ASSERT_EQ(skipped.status, 0) << skipped.out;
  EXPECT_FALSE(nlohmann::json::parse(skipped.out).contains("pair_list"));
  const test::CliRun text_run = test::run("eval " + seq, false);
  EXPECT_NE(text_run.out.find("pair list " + seq + "/loop_pairs.txt:"), std::string::npos) << text_run.out;
  EXPECT_NE(text_run.out.find("3 of 3"), std::string::npos) << text_run.out;
}

TEST_F(EvalAllProtocols, AFoldersPairListWithoutPairsIsSkippedButAGivenOneIsAnError) {
  // A simulated sequence without revisits writes a loop_pairs.txt of comments only.
  const std::string seq = path("seq");
  test::makePlantedSequence(seq);
  std::ofstream(seq + "/loop_pairs.txt") << "# query candidate label\n\n";
  const test::CliRun r = test::run("eval " + seq + " --json", false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("pair_list"));
  EXPECT_EQ(j["top1"]["near"], 1);
  const test::CliRun noted = test::run("eval " + seq);
  EXPECT_EQ(noted.status, 0) << noted.out;
  EXPECT_NE(noted.out.find("lists no pairs; the pair-list protocol is skipped"), std::string::npos) << noted.out;
  const test::CliRun given = test::run("eval " + seq + " --pairs " + seq + "/loop_pairs.txt");
  EXPECT_EQ(given.status, 1) << given.out;
  EXPECT_NE(given.out.find("the pair list has no pairs"), std::string::npos) << given.out;
}

}  // namespace
}  // namespace sgtllc::eval
