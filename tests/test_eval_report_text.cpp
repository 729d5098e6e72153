// What the evaluation outputs say, checked on the planted KITTI sequence and hand-built records: undefined metrics
// are n/a / null with a reason (never 0), every frame column holds frame names, PR curves are drawn as steps,
// report.md names its software, date and machine and is otherwise the same on a re-run, and the progress bar
// shows rate and time left on a terminal only.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "eval/report_plots.h"
#include "sgtllc/eval/metric_text.h"
#include "sgtllc/eval/report.h"
#include "test_cli_support.h"
#include "test_kitti_support.h"

namespace sgtllc::eval {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The lines of @p text without those that may differ between two runs: the date, the machine and the measured
/// times.
std::string withoutRunLines(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind("- Date: ", 0) == 0 || line.rfind("- Machine: ", 0) == 0 ||
        line.rfind("| ms per frame", 0) == 0) {
      continue;
    }
    out += line + "\n";
  }
  return out;
}

class ReportText : public test::CliTempDirTest {
 protected:
  ReportText() : CliTempDirTest("report_text") {}
};

TEST_F(ReportText, ASequenceWithoutRevisitsHasNullMetricsWithAReason) {
  // The planted sequence without its last frame (scan 4501, the revisit of frame 0): no positives at all.
  const std::string seq = path("seq");
  test::makePlantedSequence(seq);
  fs::remove(seq + "/velodyne/000053.bin");
  fs::remove(seq + "/labels/000053.label");
  const test::CliRun r = test::run("eval " + seq + " --json --report " + path("report"), false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["n_revisit_queries"], 0);
  EXPECT_EQ(j["n_positive"], 0);
  for (const char* key : {"f1_max", "ep", "recall_at_100_precision", "retrieval_recall_at_15", "success_rate",
                          "rte_mean", "rre_mean"}) {
    EXPECT_TRUE(j[key].is_null()) << key << " = " << j[key];
  }
  EXPECT_TRUE(j["top1"]["f1_max"].is_null());
  EXPECT_TRUE(j["distance_test"][0]["ep"].is_null());
  EXPECT_TRUE(j["poses"]["success_rate"].is_null());
  EXPECT_GT(j["n_negative"].get<int>(), 0);  // the counts stay numbers
  ASSERT_EQ(j["null_reasons"].size(), 3u);
  EXPECT_EQ(j["null_reasons"][0],
            "f1_max, ep, recall_at_100_precision: no positives in this sequence: no scored pair is closer than 3 m");
  EXPECT_EQ(nlohmann::json::parse(readFile(path("report/metrics.json"))), j);

  const std::string md = readFile(path("report/report.md"));
  EXPECT_THAT(md, HasSubstr("| F1max (pairwise, positive < 3 m) | n/a |\n| EP | n/a |\n"));
  EXPECT_THAT(md, HasSubstr("| retrieval recall at 15 | n/a |"));
  EXPECT_THAT(md, HasSubstr("| pose success rate of loops within 4 m (RTE < 2 m, RRE < 5°) | n/a (0 of 0) |"));
  EXPECT_THAT(md, HasSubstr("- n/a: f1_max, ep, recall_at_100_precision: no positives in this sequence"));
  EXPECT_THAT(md, HasSubstr("| 3 m | n/a | n/a | 0 |"));

  const test::CliRun text = test::run("eval " + seq, false);
  ASSERT_EQ(text.status, 0) << text.out;
  EXPECT_THAT(text.out, HasSubstr("F1max n/a, EP n/a, recall@100%precision n/a, retrieval recall@15 n/a\n"));
  EXPECT_THAT(text.out, HasSubstr("pose success n/a (0 of 0), mean RTE n/a m, RRE n/a deg\n"));
  EXPECT_THAT(text.out, HasSubstr("n/a: success_rate, rte_mean, rre_mean: no detected true loop had its pose"));
  EXPECT_THAT(text.out, Not(HasSubstr("F1max 0.0000")));
}

TEST_F(ReportText, FrameColumnsHoldNamesAndTheReportIsTheSameOnARerun) {
  const std::string seq = path("seq");
  test::makePlantedSequence(seq);
  const std::string command = "eval " + seq + " --force --report " + path("report");
  ASSERT_EQ(test::run(command).status, 0);
  // Frame 53 (scan 4501) closes the loop with frame 0: its match is named as the frame column names it.
  const std::string frames = readFile(path("report/frames.csv"));
  EXPECT_THAT(frames, HasSubstr("\n000053,"));
  std::istringstream rows(frames);
  std::string row;
  while (std::getline(rows, row) && row.rfind("000053,", 0) != 0) {
  }
  std::vector<std::string> cells;
  std::istringstream cols(row);
  for (std::string cell; std::getline(cols, cell, ',');) cells.push_back(cell);
  ASSERT_GT(cells.size(), 6u) << row;
  EXPECT_EQ(cells[4], "1");       // loop
  EXPECT_EQ(cells[5], "000000");  // match: a name, not the number 0
  EXPECT_THAT(readFile(path("report/candidates.csv")), HasSubstr("\n000053,000000,"));

  const std::string first = readFile(path("report/report.md"));
  const std::string first_candidates = readFile(path("report/candidates.csv"));
  const std::string first_curves = readFile(path("report/pr_curve.csv"));
  EXPECT_THAT(first, HasSubstr("\n- Software: sgtllc 0.1.0, commit "));
  EXPECT_THAT(first, HasSubstr("\n- Date: 20"));
  EXPECT_THAT(first, HasSubstr(" UTC\n- Machine: Linux "));
  EXPECT_THAT(first, HasSubstr(" cores\n"));
  ASSERT_EQ(test::run(command).status, 0);
  // Only the date, machine and time lines may differ (this test leaves them out); the tables stay byte-identical.
  EXPECT_EQ(withoutRunLines(readFile(path("report/report.md"))), withoutRunLines(first));
  EXPECT_EQ(readFile(path("report/candidates.csv")), first_candidates);
  EXPECT_EQ(readFile(path("report/pr_curve.csv")), first_curves);
}

TEST(ReportJson, PairListWithoutPositivesIsNullAndListsScoreT) {
  PairListRun run;
  PairRecord r;
  r.pair = {7, 3, false};
  r.available = true;
  r.score = 0.25;
  run.pairs.push_back(r);
  const PairListMetrics m = computePairListMetrics(run, EvalOptions{});
  const Json j = pairListMetricsJson(m, run);
  EXPECT_TRUE(j["f1_max"].is_null());
  EXPECT_TRUE(j["ep"].is_null());
  EXPECT_TRUE(j["success_rate"].is_null());
  EXPECT_EQ(j["null_reasons"][0], "f1_max, ep, recall_at_100_precision: no positives: no scored pair is labelled a loop");
  ASSERT_EQ(j["pair_results"].size(), 1u);
  EXPECT_EQ(j["pair_results"][0]["score"], 0.25);
  EXPECT_EQ(j["pair_results"][0]["score_t"], 0.25);  // the old name of "score", kept one release
  EXPECT_THAT(pairListSection(m, "pairs.txt", ""), HasSubstr("| F1max | n/a |\n| EP | n/a |"));
}

TEST(MetricText, ValuesOrNa) {
  EXPECT_EQ(metricText(0.98765, true, 4), "0.9877");
  EXPECT_EQ(metricText(0.0, false, 4), "n/a");
  EXPECT_TRUE(metricJson(0.0, false).is_null());
  EXPECT_EQ(metricJson(0.5, true), 0.5);
}

TEST(PrPlot, CurvesAreStepsFromTheAppendedPoint) {
  // Scores 0.9 T, 0.8 F, 0.7 T (2 positives): thresholds 0.9, 0.8, 0.7 give (R, P) = (½, 1), (½, ½), (1, ⅔).
  const PrCurve c = precisionRecallCurve({{0.9, true}, {0.8, false}, {0.7, true}});
  const PrSteps s = prSteps(c);
  // From (0, 1): up to each threshold's precision at the previous recall, then across to its recall.
  EXPECT_THAT(s.recall, ElementsAre(0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 1.0));
  EXPECT_THAT(s.precision, ElementsAre(1.0, 1.0, 1.0, 0.5, 0.5, 2.0 / 3.0, 2.0 / 3.0));
  // Every segment is vertical or horizontal: never a slanted line between two thresholds.
  for (size_t k = 1; k < s.recall.size(); ++k) {
    EXPECT_TRUE(s.recall[k] == s.recall[k - 1] || s.precision[k] == s.precision[k - 1]) << k;
  }
  EXPECT_TRUE(prSteps(PrCurve{}).recall.empty());
}

TEST_F(ReportText, ProgressShowsRateAndTimeLeftOnATerminalOnly) {
  const std::string seq = path("seq");
  test::makePlantedSequence(seq);
  // script(1) gives the command a terminal; what it captures is what the terminal showed.
  const std::string eval = std::string(SGTLLC_CLI) + " eval " + seq + " --no-pairs";
  FILE* pipe = popen(("script -qec '" + eval + "' /dev/null 2>&1").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  test::CliRun tty;
  std::array<char, 4096> buf;
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), pipe)) > 0;) tty.out.append(buf.data(), n);
  tty.status = pclose(pipe);
  ASSERT_EQ(tty.status, 0) << tty.out;
  EXPECT_THAT(tty.out, HasSubstr("frames [##############################] 54/54 100% "));
  EXPECT_THAT(tty.out, HasSubstr(" frames/s, took 0:0"));
  const test::CliRun piped = test::run("eval " + seq + " --no-pairs");
  ASSERT_EQ(piped.status, 0) << piped.out;
  EXPECT_THAT(piped.out, Not(HasSubstr("frames/s")));
}

}  // namespace
}  // namespace sgtllc::eval
