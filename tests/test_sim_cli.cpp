// `sgtllc simulate`: writes a readable sequence, and refuses bad values and non-empty folders with a clear message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <Eigen/LU>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/sequence.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct CliResult {
  int status = -1;
  std::string out;  // stdout and stderr together
};

/// Runs `sgtllc simulate ARGS`, capturing its output in a file of this process.
CliResult simulate(const std::string& args) {
  const fs::path log = fs::temp_directory_path() / ("sgtllc_sim_cli_" + std::to_string(::getpid()) + ".log");
  const int st = std::system((std::string(SGTLLC_CLI) + " simulate " + args + " > " + log.string() + " 2>&1").c_str());
  std::ifstream in(log);
  CliResult r{WIFEXITED(st) ? WEXITSTATUS(st) : -1, std::string(std::istreambuf_iterator<char>(in), {})};
  fs::remove(log);
  return r;
}

class SimCli : public ::testing::Test {
 protected:
  void SetUp() override {
    // The process id keeps two concurrent runs of the suite (two build trees on one machine) apart.
    dir_ = fs::temp_directory_path() /
           ("sgtllc_sim_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(SimCli, WritesAReadableSequenceAndASummary) {
  const CliResult r = simulate("--out " + path("seq") + " --frames 3 --seed 4 --threads 2 --no-preview");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("wrote 3 frames"));
  EXPECT_THAT(r.out, HasSubstr("points per frame"));
  const io::SequenceDir seq(path("seq"));
  EXPECT_EQ(seq.size(), 3u);
  EXPECT_GT(seq.load(2).points.size(), 90000u);
  EXPECT_FALSE(fs::exists(path("seq/preview_scan.png")));
}

TEST_F(SimCli, WarnsWhenThePlannedRevisitsDoNotFit) {
  // Three frames (a few metres) cannot hold the one planned revisit (at least 80 m after 150 m of road).
  const CliResult r = simulate("--out " + path("seq") + " --frames 3 --seed 4 --no-preview");
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string head = "warning: only 0 of the 1 planned revisit fit in 3 frames; --frames ";
  const size_t at = r.out.find(head);
  ASSERT_NE(at, std::string::npos) << r.out;
  const int needed = std::atoi(r.out.c_str() + at + head.size());
  EXPECT_GT(needed, 300);  // 80 m of revisit at 30 % of the route and ~8.5 m/s
  EXPECT_LT(needed, 1000);
  EXPECT_THAT(r.out, HasSubstr(" would hold it (without a revisit the sequence has no loops to find)\n"));
  // No revisit planned: nothing to warn about.
  const CliResult none = simulate("--out " + path("none") + " --frames 3 --seed 4 --revisits 0 --no-preview");
  ASSERT_EQ(none.status, 0) << none.out;
  EXPECT_THAT(none.out, Not(HasSubstr("warning")));
}

TEST_F(SimCli, BadValuesExitWithUsageErrors) {
  for (const char* args : {"--frames 3 --seed 1 --scene downtown", "--frames 0 --seed 1",
                           "--frames 3 --seed 1 --label-noise 2", "--frames 3 --seed 1 --sensor vlp16",
                           "--frames 3 --seed 1 --accumulate 0", "--frames 3 --seed 1 --threads 0", "--frames 3"}) {
    const CliResult r = simulate("--out " + path("seq") + " " + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(path("seq"))) << args;
  }
  const CliResult r = simulate("--out " + path("seq") + " --frames 3 --seed 1 --scene downtown");
  EXPECT_THAT(r.out, HasSubstr("downtown"));
}

TEST_F(SimCli, RefusesANonEmptyFolderWithoutForce) {
  fs::create_directories(path("seq"));
  std::ofstream(path("seq/keep.txt")) << "mine";
  CliResult r = simulate("--out " + path("seq") + " --frames 2 --seed 1 --no-preview");
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("not empty"));
  EXPECT_THAT(r.out, HasSubstr("--force"));
  EXPECT_FALSE(fs::exists(path("seq/velodyne")));
  r = simulate("--out " + path("seq") + " --frames 2 --seed 1 --no-preview --force");
  EXPECT_EQ(r.status, 0) << r.out;
  std::ifstream in(path("seq/keep.txt"));
  std::string kept;
  in >> kept;
  EXPECT_EQ(kept, "mine");
  // A longer earlier run leaves frames behind: --force never deletes them, but says so.
  std::ofstream(path("seq/velodyne/000009.bin")) << "";
  r = simulate("--out " + path("seq") + " --frames 2 --seed 1 --no-preview --force");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("warning"));
  EXPECT_TRUE(fs::exists(path("seq/velodyne/000009.bin")));
}

TEST_F(SimCli, RefusesAFileAsOutput) {
  std::ofstream(path("file")) << "x";
  const CliResult r = simulate("--out " + path("file") + " --frames 2 --seed 1 --force");
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("not a folder"));
}

/// Lines of a text file.
size_t lineCount(const std::string& path) {
  std::ifstream in(path);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST_F(SimCli, SecondSessionThroughAFirstSessionsWorld) {
  CliResult r = simulate("--out " + path("s1") + " --frames 30 --seed 4 --no-preview");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(fs::exists(path("s1/simulation.txt")));
  EXPECT_FALSE(fs::exists(path("s1/cross_session.txt")));
  r = simulate("--out " + path("s2") + " --frames 20 --world-of " + path("s1") + " --no-preview");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("second session in the world of seed 4 (30 frames)"));
  EXPECT_THAT(r.out, HasSubstr("seed 5"));  // the first session's seed + 1
  EXPECT_EQ(lineCount(path("s2/cross_session.txt")), 20u);
  EXPECT_EQ(lineCount(path("s2/poses.txt")), 20u);
  std::ifstream manifest(path("s2/simulation.txt"));
  const std::string text(std::istreambuf_iterator<char>(manifest), {});
  EXPECT_THAT(text, HasSubstr("\nseed 5\n"));
  EXPECT_THAT(text, HasSubstr("\nfirst.seed 4\n"));
  EXPECT_EQ(io::SequenceDir(path("s2")).size(), 20u);
  // The truth is in the first session's frame; the second session's odometry starts at the identity in its own.
  const std::vector<Eigen::Matrix4d> truth = io::readKittiPoses(path("s2/poses.txt"));
  const std::vector<Eigen::Matrix4d> odometry = io::readKittiPoses(path("s2/odometry.txt"));
  ASSERT_EQ(odometry.size(), 20u);
  EXPECT_FALSE(truth.front().isApprox(Eigen::Matrix4d::Identity(), 1e-6));  // the truth is in the first session's frame
  EXPECT_TRUE(odometry.front().isApprox(Eigen::Matrix4d::Identity(), 1e-9)) << odometry.front();
  // Its poses are the true ones relative to its own first frame, up to the drift (a scale error of a few per cent,
  // a heading walk of milliradians).
  const Eigen::Vector3d true_end = (truth.front().inverse() * truth.back()).topRightCorner(3, 1);
  const Eigen::Vector3d odometry_end = odometry.back().topRightCorner(3, 1);
  EXPECT_GT(true_end.norm(), 5.0);
  EXPECT_LT((odometry_end - true_end).norm(), 0.1 * true_end.norm());

  // What cannot be a first session, or a second one.
  struct Case {
    std::string args;
    int status;
    std::string message;
  };
  fs::create_directories(path("plain"));
  const std::vector<Case> cases = {
      {"--world-of " + path("plain"), 1, "has no simulation.txt"},
      {"--world-of " + path("s2"), 1, "is itself a second session"},
      {"--world-of " + path("s1") + " --revisits 2", 2, "plans no revisits of its own"},
      {"--world-of " + path("s1") + " --scene rural", 1, "was simulated in the urban scene"},
      {"--world-of " + path("s1") + " --seed 4", 1, "seed other than its first session's (4)"},
      {"--world-of " + path("missing"), 2, "missing"},
  };
  for (const Case& c : cases) {
    r = simulate("--out " + path("bad") + " --frames 5 --no-preview " + c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.out;
    EXPECT_THAT(r.out, HasSubstr(c.message)) << c.args;
    EXPECT_FALSE(fs::exists(path("bad"))) << c.args;
  }
  // Never into the first session's own folder, not even with --force.
  r = simulate("--out " + path("s1") + " --frames 5 --no-preview --force --world-of " + path("s1"));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("is the first session's folder"));
  EXPECT_EQ(lineCount(path("s1/poses.txt")), 30u);
  // A first session whose poses the rebuilt world does not reproduce (edited, or another simulator version).
  std::ifstream in(path("s1/poses.txt"));
  std::string poses(std::istreambuf_iterator<char>(in), {});
  in.close();
  // Frame 0 gets frame 29's pose, some 20 m away.
  poses = poses.substr(poses.rfind('\n', poses.size() - 2) + 1) + poses.substr(poses.find('\n') + 1);
  std::ofstream(path("s1/poses.txt")) << poses;
  r = simulate("--out " + path("bad") + " --frames 5 --no-preview --world-of " + path("s1"));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("does not match the world rebuilt from its simulation.txt"));
  EXPECT_FALSE(fs::exists(path("bad")));
}

}  // namespace
}  // namespace sgtllc
