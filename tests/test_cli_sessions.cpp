// `sgtllc run SEQ --odometry O --map A.sgtmap` (docs/sessions.md): a second session of the synthetic circular world
// as node files, its odometry in a frame of its own, merged into the first session's map; the refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sgtllc/io/kitti_write.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/trajectory.h"
#include "test_cli_support.h"
#include "test_map_support.h"

namespace sgtllc {
namespace {

class CliSessions : public test::CliTempDirTest {
 protected:
  CliSessions() : CliTempDirTest("sessions") {}
  void SetUp() override {
    CliTempDirTest::SetUp();
    first_ = test::circleSequence(110);
    second_ = test::circleSequence(40, 2.0, 0.9, /*seed=*/99);
    write(first_, path("s1"));
    write(second_, path("s2"));
    // Every frame joins the map here (thinning: tests/test_pipeline_sessions.cpp).
    std::ofstream(path("config.yaml")) << "retrieval:\n  exclude_recent: 20\nbackend:\n  sessions:\n    keep_distance_m: 0\n";
    const auto r = test::run("run --nodes " + path("s1/nodes") + " --odometry " + path("s1/odometry.txt") + " --calib " +
                             path("s1/calib.txt") + " --config " + path("config.yaml") + " --save-map " + path("m.sgtmap"));
    ASSERT_EQ(r.status, 0) << r.out;
  }
  /// DIR/nodes/NAME.txt node files, DIR/odometry.txt (exact motion from the identity at the first frame: the
  /// session's own frame; KITTI cam0 = LiDAR here, calib Tr is the identity) and calib.txt.
  static void write(const test::NodeSequence& s, const std::string& dir) {
    std::filesystem::create_directories(dir + "/nodes");
    std::vector<Eigen::Matrix4d> odometry;
    for (size_t i = 0; i < s.frames.size(); ++i) {
      io::writeNodesTxt(dir + "/nodes/" + s.names[i] + ".txt", s.frames[i]);
      odometry.push_back(s.poses.front().inverse() * s.poses[i]);
    }
    io::writeKittiPoses(dir + "/odometry.txt", odometry);
    std::ofstream(dir + "/calib.txt") << "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  }
  std::string session(const std::string& extra, const std::string& map = "m.sgtmap") const {
    return "run --nodes " + path("s2/nodes") + " --odometry " + path("s2/odometry.txt") + " --calib " +
           path("s2/calib.txt") + " --config " + path("config.yaml") + " --map " + path(map) + " " + extra;
  }
  test::NodeSequence first_, second_;
};

TEST_F(CliSessions, MergesASecondSessionIntoTheMapsFrame) {
  const auto r = test::run(session("--session-name east --out-trajectory " + path("t1.txt") + " --save-map " +
                                   path("m2.sgtmap") + " --out " + path("loops1.csv") + " --threads 1"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("frames 40 against a map of 110; inter-session loops "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("session 'east' placed in the map's frame"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("inter-session loop east/000005 -> "), std::string::npos) << r.out;
  // The trajectory: the second session's true poses in the map's world, the first session's odometry frame (its
  // first frame; its odometry is exact here).
  const io::Trajectory t = io::readTrajectory(path("t1.txt"), path("s2/calib.txt"), io::PoseFrame::kCam0).trajectory;
  ASSERT_EQ(t.poses.size(), 40u);
  for (size_t i = 0; i < t.poses.size(); ++i) {
    const Eigen::Matrix4d truth = first_.poses.front().inverse() * second_.poses[i];
    EXPECT_LT((t.poses[i].translation() - truth.topRightCorner<3, 1>()).norm(), 0.1) << i;
  }
  const auto info = test::run("map info " + path("m2.sgtmap"));
  ASSERT_EQ(info.status, 0) << info.out;
  EXPECT_NE(info.out.find("frames 150 (with poses), first 000000, last east/000039"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("sessions 2:\n  m: 110 frames (000000 .. 000109)\n  east: 40 frames (east/000000 .. "
                          "east/000039)"),
            std::string::npos)
      << info.out;
  EXPECT_NE(info.out.find("  SESS v1  "), std::string::npos) << info.out;
  // The same at three threads, byte for byte.
  const auto again = test::run(session("--session-name east --out-trajectory " + path("t3.txt") + " --save-map " +
                                       path("m3.sgtmap") + " --out " + path("loops3.csv") + " --threads 3"));
  ASSERT_EQ(again.status, 0) << again.out;
  EXPECT_EQ(test::fileBytes(path("t1.txt")), test::fileBytes(path("t3.txt")));
  EXPECT_EQ(test::fileBytes(path("m2.sgtmap")), test::fileBytes(path("m3.sgtmap")));
  EXPECT_EQ(test::fileBytes(path("loops1.csv")), test::fileBytes(path("loops3.csv")));
  // A session of the same name cannot join again; the map given is kept as it was.
  const std::string before = test::fileBytes(path("m2.sgtmap"));
  const auto twice = test::run(session("--session-name east --save-map " + path("m2.sgtmap") + " --force", "m2.sgtmap"));
  EXPECT_NE(twice.status, 0);
  EXPECT_NE(twice.out.find("already has a session named 'east'"), std::string::npos) << twice.out;
  EXPECT_EQ(test::fileBytes(path("m2.sgtmap")), before);
}

TEST_F(CliSessions, ADriveTheMapHeldEverywhereAddsNoFrameAndIsListed) {
  // The first drive again, with thinning on (the default): every frame is recognised beside a map frame, none is
  // added, and `map info` lists the session with no frame range (it used to fail on the empty range).
  std::ofstream(path("thin.yaml")) << "retrieval:\n  exclude_recent: 20\n";
  const auto r = test::run("run --nodes " + path("s1/nodes") + " --odometry " + path("s1/odometry.txt") + " --calib " +
                           path("s1/calib.txt") + " --config " + path("thin.yaml") + " --map " + path("m.sgtmap") +
                           " --session-name again --save-map " + path("again.sgtmap"));
  ASSERT_EQ(r.status, 0) << r.out;
  const auto info = test::run("map info " + path("again.sgtmap"));
  ASSERT_EQ(info.status, 0) << info.out;
  EXPECT_NE(info.out.find("sessions 2:\n  m: 110 frames (000000 .. 000109)\n  again: 0 frames\n"), std::string::npos)
      << info.out;
  const auto json = test::run("map info " + path("again.sgtmap") + " --json");
  ASSERT_EQ(json.status, 0) << json.out;
  EXPECT_NE(json.out.find("\"frames\": 0"), std::string::npos) << json.out;
}

TEST_F(CliSessions, FalseInterSessionLoopsAreAllRejected) {
  // The robustness test of docs/sessions.md: false inter-session loops (a session frame tied to a map frame more
  // than 50 m from where it is, at a random pose) must all be rejected and leave the session where it was.
  const auto clean = test::run(session("--json --out-trajectory " + path("t0.txt") + " --out " + path("l0.csv")), false);
  ASSERT_EQ(clean.status, 0) << clean.out;
  const auto noisy = test::run(session("--json --add-false-loops 0.5 --seed 3 --out-trajectory " + path("t1.txt") +
                                       " --out " + path("l1.csv")),
                               false);
  ASSERT_EQ(noisy.status, 0) << noisy.out;
  const auto a = nlohmann::json::parse(clean.out), b = nlohmann::json::parse(noisy.out);
  const int found = a["inter_session_loops"].get<int>();
  ASSERT_GE(found, 30);
  EXPECT_FALSE(a.contains("injected_false_loops"));
  EXPECT_EQ(b["inter_session_loops"].get<int>(), found);  // the loops found; the injected ones counted apart
  EXPECT_EQ(b["injected_false_loops"].get<int>(), (found + 1) / 2);
  EXPECT_EQ(b["injected_rejected"].get<int>(), (found + 1) / 2);
  EXPECT_EQ(b["inter_session_accepted"], a["inter_session_accepted"]);
  int listed = 0;
  for (const auto& l : b["loop_list"]) {
    if (!l["injected"].get<bool>()) continue;
    ++listed;
    EXPECT_NE(l["decision"].get<std::string>(), "accepted") << l.dump();
  }
  EXPECT_EQ(listed, (found + 1) / 2);
  EXPECT_EQ(test::fileBytes(path("t1.txt")), test::fileBytes(path("t0.txt")));
  EXPECT_EQ(test::fileBytes(path("l1.csv")), test::fileBytes(path("l0.csv")));  // the loops found, not the test's
}

TEST_F(CliSessions, EvalScoresAMergeAgainstTheTruth) {
  // The second session's truth in the map's world (the first session's odometry frame, its first frame).
  std::vector<Eigen::Matrix4d> truth;
  for (const Eigen::Matrix4d& T : second_.poses) truth.push_back(first_.poses.front().inverse() * T);
  io::writeKittiPoses(path("s2/poses.txt"), truth);
  const std::string args = " --nodes " + path("s2/nodes") + " --odometry " + path("s2/odometry.txt") + " --calib " +
                           path("s2/calib.txt") + " --config " + path("config.yaml") + " --map " + path("m.sgtmap");
  const auto r = test::run("eval " + path("s2") + args + " --json", false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["placed"].get<bool>());
  const auto& inter = j["inter_session_loops"];
  EXPECT_GE(inter["found"].get<int>(), 30);
  EXPECT_EQ(inter["correct"], inter["found"]);  // exact odometry, node noise of 3 cm: every pose within 1 m / 5 deg
  EXPECT_EQ(inter["accepted_wrong"].get<int>(), 0);
  EXPECT_EQ(j["intra_session_loops"]["found"].get<int>(), 0);  // 40 frames of a 100-frame lap
  EXPECT_LT(j["ate_merged_m"]["unaligned_rmse"].get<double>(), 0.1);  // in the map's frame
  EXPECT_LT(j["ate_merged_m"]["aligned_rmse"].get<double>(), 0.1);
  EXPECT_EQ(j["map_frames_before"].get<int>(), 110);
  EXPECT_EQ(j["map_frames_after"].get<int>(), 150);  // keep_distance_m 0: every frame joins
  EXPECT_EQ(j["map_frames_unthinned"].get<int>(), 150);
  const auto text = test::run("eval " + path("s2") + args);
  ASSERT_EQ(text.status, 0) << text.out;
  EXPECT_NE(text.out.find("placed in the map's frame"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("map frames: 110 before, 150 after the merge (150 if every frame were kept)"),
            std::string::npos)
      << text.out;
  // Without the session's truth there is nothing to score.
  std::filesystem::remove(path("s2/poses.txt"));
  const auto missing = test::run("eval " + path("s2") + args);
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.out.find("poses.txt: missing (evaluating a merge"), std::string::npos) << missing.out;
}

TEST_F(CliSessions, RefusesWhatASessionCannotDo) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"run --nodes " + path("s2/nodes") + " --map " + path("m.sgtmap"), "--map needs the session's --odometry"},
      {session("--online"), "do not work with --map yet"},
      {session("--out-graph " + path("g.g2o")), "do not work with --map yet"},
      {"run --nodes " + path("s2/nodes") + " --session-name x", "--session-name and --add-false-loops go with --map"},
      {"run --nodes " + path("s2/nodes") + " --add-false-loops 0.1", "--session-name and --add-false-loops go with --map"},
      {session("", "none.sgtmap"), "none.sgtmap"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = test::run(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.out.find(message), std::string::npos) << args << "\n" << r.out;
  }
  // Another world (the classes changed): no inter-session loop, so nothing is placed and nothing written.
  test::NodeSequence other = second_;
  for (auto& frame : other.frames) {
    for (Node& n : frame) n.label = (n.label + 1) % kNumPaperClasses;
  }
  write(other, path("s3"));
  const auto r = test::run("run --nodes " + path("s3/nodes") + " --odometry " + path("s3/odometry.txt") + " --calib " +
                           path("s3/calib.txt") + " --config " + path("config.yaml") + " --map " + path("m.sgtmap") +
                           " --out-trajectory " + path("t.txt") + " --save-map " + path("x.sgtmap"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("not placed in " + path("m.sgtmap")), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(path("t.txt")));
  EXPECT_FALSE(std::filesystem::exists(path("x.sgtmap")));
}

}  // namespace
}  // namespace sgtllc
