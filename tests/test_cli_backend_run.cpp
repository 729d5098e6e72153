// `sgtllc run --odometry` and `sgtllc eval --odometry` on the planted sequence of the bundled KITTI scans (frame 53
// revisits frame 0): the loop edge corrects a drifted odometry, batch and online agree, run's CSV feeds optimize.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sgtllc/eval/trajectory_error.h"
#include "sgtllc/io/g2o.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "test_cli_backend_support.h"
#include "test_trajectory_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::CliRun;
using test::run;

class RunOdometry : public test::CliBackend {
 protected:
  void SetUp() override {
    CliBackend::SetUp();
    test::makePlantedSequence(path("seq"));
    // KITTI cam0 odometry: the true poses, with frame 53 (the revisit) 1.5 m and 3° off.
    std::vector<Eigen::Matrix4d> poses = io::readKittiPoses(path("seq/poses.txt"));
    Eigen::Isometry3d error = Eigen::Translation3d(1.5, 0.0, 0.5) * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY());
    poses[53] = poses[53] * error.matrix();
    io::writeKittiPoses(path("odo.txt"), poses);
  }
  std::string seq() const { return "run " + path("seq") + " --odometry " + path("odo.txt"); }
};

TEST_F(RunOdometry, TheLoopEdgeMovesTheRevisitBackOntoItsTruePose) {
  const CliRun r = run(seq() + " --out " + path("loops.csv") + " --out-trajectory " + path("corrected.txt") +
                       " --out-graph " + path("graph.g2o") + " --out-loops " + path("loops.g2o"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop 000053 -> 000000"));
  EXPECT_THAT(r.out, HasSubstr("back end: 1 loops, 1 accepted, 0 rejected"));
  // The corrected trajectory is KITTI cam0 again (converted through the sequence's calib.txt and back).
  const std::string calib = path("seq/calib.txt");
  const io::Trajectory truth = io::readTrajectory(path("seq/poses.txt"), calib);
  const io::Trajectory odometry = io::readTrajectory(path("odo.txt"), calib);
  const io::Trajectory corrected = io::readTrajectory(path("corrected.txt"), calib);
  ASSERT_EQ(corrected.poses.size(), 54u);
  const double before = (odometry.poses[53].translation() - truth.poses[53].translation()).norm();
  const double after = (corrected.poses[53].translation() - truth.poses[53].translation()).norm();
  EXPECT_GT(before, 1.5);
  EXPECT_LT(after, 0.3);
  // The CSV carries the loop's information; the g2o graph and loop list parse back.
  std::ifstream csv(path("loops.csv"));
  std::string header, line;
  std::getline(csv, header);
  std::getline(csv, line);
  EXPECT_THAT(header, HasSubstr(",tz,i11,i12,"));
  EXPECT_EQ(std::count(line.begin(), line.end(), ','), 36);
  const backend::PoseGraph graph = io::readG2o(path("graph.g2o"));
  EXPECT_EQ(graph.poses.size(), 54u);
  EXPECT_EQ(graph.edges.size(), 54u);
  const backend::PoseGraph list = io::readG2o(path("loops.g2o"));
  ASSERT_EQ(list.edges.size(), 1u);
  EXPECT_EQ(list.edges[0].from, 0);
  EXPECT_EQ(list.edges[0].to, 53);

  // optimize on run's CSV (frame names from the sequence folder) gives the same corrected trajectory, up to the
  // CSV's six decimals of the loop pose (1e-6 rad: mm at the padding frames, which lie up to 7 km away).
  const CliRun o = run("optimize --odometry " + path("odo.txt") + " --calib " + calib + " --loops " +
                       path("loops.csv") + " --frames " + path("seq") + " --out-trajectory " + path("again.txt"));
  ASSERT_EQ(o.status, 0) << o.out;
  test::expectPosesNear(io::readTrajectory(path("again.txt"), calib).poses, corrected.poses, 1e-2);
}

TEST_F(RunOdometry, OnlineAgreesWithBatchAndOutputIsTheSameAtAnyThreadCount) {
  std::vector<std::string> outputs;
  for (const char* threads : {"1", "2", "1"}) {
    const std::string t = path("t" + std::to_string(outputs.size()));
    const CliRun r = run(seq() + " --threads " + threads + " --out-trajectory " + t);
    ASSERT_EQ(r.status, 0) << r.out;
    outputs.push_back(read(fs::path(t).filename().string()));
  }
  EXPECT_EQ(outputs[0], outputs[1]);
  EXPECT_EQ(outputs[0], outputs[2]);
  const CliRun online = run(seq() + " --online --out-trajectory " + path("online.txt"));
  ASSERT_EQ(online.status, 0) << online.out;
  EXPECT_THAT(online.out, HasSubstr("  back end: accepted (consistent with 0 other loops"));
  const std::string calib = path("seq/calib.txt");
  test::expectPosesNear(io::readTrajectory(path("online.txt"), calib).poses,
                        io::readTrajectory(path("t0"), calib).poses, 1e-4);
}

// --online --json reports the CPU time of each re-solve and how far the final full solve moved the frames from the
// online estimate: here one loop, one re-solve, and a shift for each of the 54 frames.
TEST_F(RunOdometry, OnlineJsonReportsTheReSolves) {
  const CliRun r = run(seq() + " --online --json", false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto b = nlohmann::json::parse(r.out)["backend"];
  ASSERT_TRUE(b.contains("online_solve_ms")) << b.dump();
  EXPECT_EQ(b["online_solve_ms"]["count"].get<int>(), 1);
  const double median = b["online_solve_ms"]["median"].get<double>();
  EXPECT_GE(median, 0.0);
  EXPECT_EQ(b["online_solve_ms"]["max"].get<double>(), median);  // one value
  EXPECT_EQ(b["online_final_shift_m"]["count"].get<int>(), 54);
  EXPECT_GE(b["online_final_shift_m"]["max"].get<double>(), b["online_final_shift_m"]["p99"].get<double>());
  EXPECT_GE(b["online_final_shift_m"]["p99"].get<double>(), b["online_final_shift_m"]["median"].get<double>());
  EXPECT_THAT(run(seq() + " --online", false).out, HasSubstr("  online re-solves: 1, CPU median "));
  EXPECT_FALSE(nlohmann::json::parse(run(seq() + " --json", false).out)["backend"].contains("online_solve_ms"));
}

TEST_F(RunOdometry, EvalReportsTheTrajectoryErrorsOfBoth) {
  const CliRun r = run("eval " + path("seq") + " --odometry " + path("odo.txt") + " --json --report " +
                       path("report"), false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.contains("f1_max"));
  EXPECT_EQ(j["backend"]["accepted"].get<int>(), 1);
  // The numbers are those of the written trajectories against poses.txt (both in the LiDAR frame).
  const std::string calib = path("seq/calib.txt");
  const io::Trajectory truth = io::readTrajectory(path("seq/poses.txt"), calib);
  const io::Trajectory corrected = io::readTrajectory(path("report/corrected_trajectory.txt"), calib);
  const io::Trajectory odometry = io::readTrajectory(path("odo.txt"), calib);
  const eval::AteResult ate_odometry = eval::absoluteTrajectoryError(truth.poses, odometry.poses);
  const eval::AteResult ate_corrected = eval::absoluteTrajectoryError(truth.poses, corrected.poses);
  EXPECT_NEAR(j["trajectory"]["odometry"]["ate_unaligned_max"].get<double>(), ate_odometry.unaligned.max, 1e-9);
  EXPECT_NEAR(j["trajectory"]["odometry"]["ate_aligned_rmse"].get<double>(), ate_odometry.aligned.rmse, 1e-9);
  EXPECT_NEAR(j["trajectory"]["corrected"]["ate_aligned_rmse"].get<double>(), ate_corrected.aligned.rmse, 1e-6);
  EXPECT_NEAR(j["trajectory"]["odometry"]["ate_unaligned_max"].get<double>(), 1.568, 0.01);  // frame 53's error
  for (const char* f : {"report.md", "metrics.json", "trajectory_topview.png", "corrected_trajectory.txt"}) {
    EXPECT_TRUE(fs::exists(path("report/") + f)) << f;
  }
  EXPECT_THAT(read("report/report.md"), HasSubstr("## Trajectory error"));
  EXPECT_EQ(nlohmann::json::parse(read("report/metrics.json"))["trajectory"], j["trajectory"]);
  // Without --odometry the evaluation's output has no back-end keys.
  const CliRun plain = run("eval " + path("seq") + " --json", false);
  ASSERT_EQ(plain.status, 0) << plain.out;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("trajectory"));
}

}  // namespace
}  // namespace sgtllc
