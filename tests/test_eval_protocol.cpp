// The evaluation protocols end to end on a planted sequence of real KITTI scans with real poses, the pair-list
// protocol on the bundled scans with the real SSC-style labels, and the eval command's report.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "sgtllc/eval/pair_eval.h"
#include "sgtllc/eval/report.h"
#include "test_node_files_support.h"
#include "test_kitti_support.h"

namespace sgtllc::eval {
namespace {

using pipeline::FrameSource;

namespace fs = std::filesystem;

class PlantedSequence : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // CTest runs each test in its own process, possibly at the same time: one folder per process.
    dir = (fs::temp_directory_path() / ("sgtllc_eval_planted_" + std::to_string(::getpid()))).string();
    fs::remove_all(dir);
    test::makePlantedSequence(dir);
  }
  static void TearDownTestSuite() { fs::remove_all(dir); }
  static std::string dir;
};
std::string PlantedSequence::dir;

TEST_F(PlantedSequence, ProtocolCountsTheOneRevisit) {
  const Config config;
  const FrameSource source = FrameSource::semanticKitti(dir, config);
  const GroundTruth truth = GroundTruth::fromKitti(dir + "/poses.txt", dir + "/calib.txt");
  EvalOptions options;
  const SequenceRun run = runSequenceEvaluation(source, truth, config, options);
  ASSERT_EQ(run.frames.size(), 54u);
  EXPECT_TRUE(run.contiguous);
  const SequenceMetrics m = computeSequenceMetrics(run, options);
  EXPECT_EQ(m.n_frames, 54);
  EXPECT_EQ(m.n_queries, 4);          // frames 50..53 see frames up to 3 with a gap of 50
  EXPECT_EQ(m.n_revisit_queries, 1);  // frame 53 (scan 4501) revisits frame 0 (scan 52), 2.96 m
  EXPECT_DOUBLE_EQ(m.retrieval_recall, 1.0);
  EXPECT_EQ(m.loops_detected, 1);
  EXPECT_EQ(m.loops_true, 1);
  EXPECT_EQ(m.loops_false, 0);
  const CurveMetrics& main = m.pairwise.at(0);
  EXPECT_EQ(main.n_positive, 1);
  EXPECT_GT(main.n_negative, 4);
  EXPECT_DOUBLE_EQ(main.f1_max, 1.0);
  EXPECT_DOUBLE_EQ(main.ep, 1.0);
  EXPECT_DOUBLE_EQ(m.top1.f1_max, 1.0);
  // The distance test widens positives: 88 and 52 are 60+ m apart, so still one positive at 15 m.
  ASSERT_EQ(m.pairwise.size(), 4u);
  EXPECT_EQ(m.pairwise[3].n_positive, 1);
  // The pose against KITTI GT, which is itself ~0.25 m off here (mostly vertical).
  ASSERT_EQ(m.poses.evaluated, 1);
  EXPECT_EQ(m.poses.successes, 1);
  EXPECT_LT(m.poses.rte_mean, 0.4);
  EXPECT_LT(m.poses.rre_mean, 1.0);
  EXPECT_GT(m.db_bytes_per_frame, 0.0);
  EXPECT_LT(m.db_bytes_per_frame, 16384.0);

  // Same numbers at two threads.
  options.threads = 2;
  const SequenceMetrics two = computeSequenceMetrics(runSequenceEvaluation(source, truth, config, options), options);
  EXPECT_EQ(two.loops_detected, m.loops_detected);
  EXPECT_EQ(two.poses.rte_mean, m.poses.rte_mean);
  EXPECT_EQ(two.pairwise[0].curve.precision, m.pairwise[0].curve.precision);
  EXPECT_EQ(two.pairwise[0].curve.thresholds, m.pairwise[0].curve.thresholds);
}

TEST_F(PlantedSequence, ReportFolderHasEveryFile) {
  const Config config;
  const FrameSource source = FrameSource::semanticKitti(dir, config);
  const GroundTruth truth = GroundTruth::fromKitti(dir + "/poses.txt", dir + "/calib.txt");
  const EvalOptions options;
  const SequenceRun run = runSequenceEvaluation(source, truth, config, options);
  const std::string out = dir + "_report";
  fs::remove_all(out);
  ReportInfo info;
  info.input = dir;
  info.command = "test";
  writeSequenceReport(out, run, computeSequenceMetrics(run, options), options, info);
  for (const char* f : {"report.md", "metrics.json", "pr_curve.csv", "frames.csv", "candidates.csv", "pr_curves.png",
                        "timing.png",
                        "memory.png", "trajectory.png"}) {
    EXPECT_TRUE(fs::exists(fs::path(out) / f)) << f;
    EXPECT_GT(fs::file_size(fs::path(out) / f), 100u) << f;
  }
  fs::remove_all(out);
}

TEST_F(PlantedSequence, NodeFilesGiveTheSameMetricsAsScans) {
  // The same frames as node files (what a user with their own object extraction provides).
  const Config config;
  const FrameSource scans = FrameSource::semanticKitti(dir, config);
  const std::string nodes_dir = dir + "_nodes";
  test::writeNodeFiles(scans, nodes_dir);
  const GroundTruth truth = GroundTruth::fromKitti(dir + "/poses.txt", dir + "/calib.txt");
  const EvalOptions options;
  const SequenceMetrics a = computeSequenceMetrics(runSequenceEvaluation(scans, truth, config, options), options);
  const SequenceMetrics b = computeSequenceMetrics(
      runSequenceEvaluation(FrameSource::nodeFiles(nodes_dir, config), truth, config, options), options);
  fs::remove_all(nodes_dir);
  EXPECT_EQ(a.pairwise[0].curve.precision, b.pairwise[0].curve.precision);
  EXPECT_EQ(a.pairwise[0].curve.thresholds, b.pairwise[0].curve.thresholds);
  EXPECT_EQ(a.loops_true, b.loops_true);
  EXPECT_EQ(a.poses.rte_mean, b.poses.rte_mean);
  EXPECT_THROW(FrameSource::nodeFiles(nodes_dir, config), Error);  // gone
}

TEST_F(PlantedSequence, FramesWithoutPosesAreAnError) {
  const Config config;
  const FrameSource source = FrameSource::semanticKitti(dir, config);
  const GroundTruth short_truth(std::vector<Eigen::Matrix4d>(10, Eigen::Matrix4d::Identity()));
  try {
    runSequenceEvaluation(source, short_truth, config, EvalOptions{});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("'000010' has no ground-truth pose"));
  }
}

// Loop counts by distance and by pose, on hand-built records: the distance protocol calls a loop 25 m away false,
// the pose check tells whether it is still a right constraint.
TEST(SequenceMetricsCounts, LoopsByDistanceAndByPose) {
  SequenceRun run;
  const auto loopFrame = [&](double distance, double rte, double rre, bool within_pose_distance) {
    FrameRecord f;
    f.frame = static_cast<long>(run.frames.size());
    f.queried = true;
    f.candidates = {CandidateRecord{0, 0.6, 0.8, distance, 1.0, Rejection::kNone, distance}};
    f.best = 0;
    f.is_loop = true;
    f.pose_error = PoseError{rte, rre};
    f.pose_evaluated = within_pose_distance;
    run.frames.push_back(f);
  };
  loopFrame(1.0, 0.1, 0.5, true);     // true loop, right pose
  loopFrame(25.0, 0.3, 1.0, false);   // false by distance, right pose
  loopFrame(30.0, 20.0, 3.0, false);  // false, wrong pose
  loopFrame(10.0, 1.9, 4.9, false);   // 3–20 m, right pose (just inside both bounds)
  loopFrame(12.0, 2.0, 0.1, false);   // 3–20 m, RTE on the bound: wrong
  const SequenceMetrics m = computeSequenceMetrics(run, EvalOptions{});
  EXPECT_EQ(m.n_queries, 5);
  EXPECT_EQ(m.loops_detected, 5);
  EXPECT_EQ(m.loops_true, 1);
  EXPECT_EQ(m.loops_false, 2);
  EXPECT_EQ(m.loops_pose_correct, 3);
  EXPECT_EQ(m.loops_false_pose_correct, 1);
  // The published pose table counts only loops within pose_max_distance.
  EXPECT_EQ(m.poses.evaluated, 1);
  EXPECT_EQ(m.poses.successes, 1);
  EXPECT_DOUBLE_EQ(m.poses.rte_mean, 0.1);
}

TEST(PairListProtocol, RealKittiPairsWithScansGetTheRightAnswer) {
  // The SSC-style list of KITTI 00 holds 004501/000052 (loop) and 000850/000088 (not); only those two have scans.
  const std::string seq = test::dataPath("kitti/00");
  const std::string list =
      (fs::temp_directory_path() / ("sgtllc_pairs_real_" + std::to_string(::getpid()) + ".txt")).string();
  std::ofstream(list) << "004501 000052 1\n000850 000088 0\n000100 000010 0\n";
  const Config config;
  const GroundTruth truth = GroundTruth::fromKitti(seq + "/poses.txt", seq + "/calib.txt");
  const PairListRun run =
      runPairListEvaluation(FrameSource::semanticKitti(seq, config), readPairList(list), truth, config, EvalOptions{});
  fs::remove(list);
  EXPECT_EQ(run.unavailable, 1);
  ASSERT_EQ(run.pairs.size(), 3u);
  EXPECT_TRUE(run.pairs[0].is_loop);
  EXPECT_FALSE(run.pairs[1].is_loop);
  EXPECT_FALSE(run.pairs[2].available);
  const PairListMetrics m = computePairListMetrics(run, EvalOptions{});
  EXPECT_EQ(m.n_available, 2);
  EXPECT_EQ(m.correct, 2);
  EXPECT_DOUBLE_EQ(m.curve.f1_max, 1.0);
  EXPECT_EQ(m.poses.successes, 1);
  EXPECT_LT(m.poses.rte_mean, 0.4);  // KITTI GT is ~0.25 m off at this revisit
}

}  // namespace
}  // namespace sgtllc::eval
