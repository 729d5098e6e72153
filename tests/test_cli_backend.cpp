// `sgtllc optimize`, `run --odometry` and `eval --odometry`: the loop closed on a drive with a known answer and on
// the bundled KITTI scans, outputs that parse back, the false-loop test, and the same bytes at any thread count.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sgtllc/eval/trajectory_error.h"
#include "sgtllc/io/g2o.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "test_cli_backend_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::CliRun;
using test::run;

class Optimize : public test::CliBackend {
 protected:
  void SetUp() override {
    CliBackend::SetUp();
    truth_ = test::circleDrive();
    write("gt.txt", test::tumText(truth_));
    write("odo.txt", test::tumText(test::driftedOdometry(truth_)));
    write("loops.csv", io::loopsCsvText(test::exactLoops(truth_)));
  }
  std::string base() const {
    return "optimize --odometry " + path("odo.txt") + " --loops " + path("loops.csv") + " --ground-truth " +
           path("gt.txt");
  }
  std::vector<Eigen::Isometry3d> truth_;
};

TEST_F(Optimize, ExactLoopsPullTheDriftedLapOntoTheTruth) {
  const CliRun r = run(base() + " --out-trajectory " + path("corrected.txt") + " --out-graph " + path("graph.g2o") +
                       " --out-loops " + path("loops.g2o"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("back end: 10 loops, 10 accepted, 0 rejected"));
  EXPECT_THAT(r.out, HasSubstr("10 loops without their own information use the nominal model"));
  const io::Trajectory odometry = io::readTrajectory(path("odo.txt"));
  const io::Trajectory corrected = io::readTrajectory(path("corrected.txt"));
  ASSERT_EQ(corrected.format, io::TrajectoryFormat::kTum);
  EXPECT_EQ(corrected.stamps, odometry.stamps);
  const double before = eval::absoluteTrajectoryError(truth_, odometry.poses).aligned.rmse;
  const double after = eval::absoluteTrajectoryError(truth_, corrected.poses).aligned.rmse;
  EXPECT_GT(before, 0.5);
  EXPECT_LT(after, 0.1 * before);
  // The second lap lies on the first again: frame 400 back at frame 23's place.
  EXPECT_LT((corrected.poses[400].translation() - corrected.poses[400 - test::kLap].translation()).norm(), 0.05);

  const backend::PoseGraph graph = io::readG2o(path("graph.g2o"));
  ASSERT_EQ(graph.poses.size(), 420u);
  EXPECT_EQ(graph.edges.size(), 419u + 10u);
  EXPECT_LT((graph.poses[400].translation() - corrected.poses[400].translation()).norm(), 1e-9);
  const backend::PoseGraph list = io::readG2o(path("loops.g2o"));
  ASSERT_EQ(list.edges.size(), 10u);
  EXPECT_EQ(list.edges[0].from, 3);
  EXPECT_EQ(list.edges[0].to, 380);
}

TEST_F(Optimize, JsonAndReportCarryBothTrajectories) {
  const CliRun r = run(base() + " --json --report " + path("report"), false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* t : {"odometry", "corrected"}) {
    for (const char* key : {"ate_aligned_rmse", "ate_aligned_mean", "ate_aligned_median", "ate_aligned_max",
                            "ate_unaligned_rmse", "ate_unaligned_max", "rpe_translation_rmse_m",
                            "rpe_rotation_rmse_deg", "kitti_translation_percent", "kitti_rotation_deg_per_100m"}) {
      EXPECT_TRUE(j["trajectory"][t].contains(key)) << t << " " << key;
    }
  }
  EXPECT_LT(j["trajectory"]["corrected"]["ate_aligned_rmse"].get<double>(),
            0.1 * j["trajectory"]["odometry"]["ate_aligned_rmse"].get<double>());
  EXPECT_EQ(j["backend"]["accepted"].get<int>(), 10);
  for (const char* f : {"report.md", "metrics.json", "trajectory_topview.png", "corrected_trajectory.txt"}) {
    EXPECT_TRUE(fs::exists(path("report/") + f)) << f;
  }
  EXPECT_THAT(read("report/report.md"), HasSubstr("| ATE aligned RMSE (m) |"));
  EXPECT_EQ(nlohmann::json::parse(read("report/metrics.json")), j);
  // A report folder holding any file the report would write is refused without --force.
  fs::remove(path("report/report.md"));
  const CliRun again = run(base() + " --report " + path("report"));
  EXPECT_EQ(again.status, 1);
  EXPECT_THAT(again.out, HasSubstr("metrics.json: file exists"));
  EXPECT_EQ(run(base() + " --force --report " + path("report")).status, 0);
}

TEST_F(Optimize, InjectedFalseLoopsAreRejectedAndTheResultHolds) {
  const CliRun clean = run(base() + " --json", false);
  const CliRun noisy = run(base() + " --json --add-false-loops 0.3 --seed 7", false);
  ASSERT_EQ(clean.status, 0) << clean.out;
  ASSERT_EQ(noisy.status, 0) << noisy.out;
  const auto a = nlohmann::json::parse(clean.out), b = nlohmann::json::parse(noisy.out);
  EXPECT_EQ(b["backend"]["injected_false_loops"].get<int>(), 3);
  EXPECT_EQ(b["backend"]["injected_rejected"].get<int>(), 3);
  EXPECT_EQ(b["backend"]["accepted"].get<int>(), 10);
  const double ate = a["trajectory"]["corrected"]["ate_aligned_rmse"].get<double>();
  EXPECT_NEAR(b["trajectory"]["corrected"]["ate_aligned_rmse"].get<double>(), ate, 0.1 * ate);
  // The injected loops join frames more than 50 m apart.
  for (const auto& l : b["backend"]["loop_list"]) {
    if (!l["injected"].get<bool>()) continue;
    const int q = std::stoi(l["query"].get<std::string>()), m = std::stoi(l["match"].get<std::string>());
    EXPECT_GT((truth_[q].translation() - truth_[m].translation()).norm(), 40.0);
  }
  const CliRun text = run(base() + " --add-false-loops 0.3 --seed 7 --out-loops " + path("all.g2o"));
  EXPECT_THAT(text.out, HasSubstr("injected false loops: 3, rejected 3, accepted 0"));
  EXPECT_THAT(text.out, HasSubstr("13 loops, 10 accepted, 3 rejected"));
  EXPECT_EQ(io::readG2o(path("all.g2o")).edges.size(), 13u);
  EXPECT_THAT(read("all.g2o"), HasSubstr("# injected false loop, rejected (inconsistent)"));
}

TEST_F(Optimize, SameBytesAtAnyThreadCountAndOnReRun) {
  std::vector<std::string> outputs;
  for (const char* threads : {"1", "2", "1"}) {
    const std::string tag = std::to_string(outputs.size());
    const CliRun r = run(base() + " --add-false-loops 0.2 --threads " + threads + " --out-trajectory " +
                         path("t" + tag) + " --out-graph " + path("g" + tag) + " --out-loops " + path("l" + tag));
    ASSERT_EQ(r.status, 0) << r.out;
    outputs.push_back(read("t" + tag) + read("g" + tag) + read("l" + tag));
  }
  EXPECT_EQ(outputs[0], outputs[1]);
  EXPECT_EQ(outputs[0], outputs[2]);
}

}  // namespace
}  // namespace sgtllc
