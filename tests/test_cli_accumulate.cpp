// `sgtllc run|eval SEQ --accumulate N` on a simulated, un-accumulated Mid-70 drive: it runs, and a
// missing or short odometry / poses.txt is an error naming the file (exit 1), a bad combination a usage error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_cli_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using test::CliRun;
using test::run;

class CliAccumulate : public test::CliTempDirTest {
 protected:
  CliAccumulate() : CliTempDirTest("accumulate") {}
  void SetUp() override {
    CliTempDirTest::SetUp();
    const CliRun r = run("simulate --out " + path("seq") + " --frames 12 --seed 3 --sensor mid70 --accumulate 1 "
                         "--threads 2 --no-preview");
    ASSERT_EQ(r.status, 0) << r.out;
  }
  /// The first @p lines lines of the sequence's odometry.txt, as @p name.
  std::string truncatedOdometry(int lines, const std::string& name) const {
    std::ifstream in(path("seq/odometry.txt"));
    std::ofstream out(path(name));
    std::string line;
    for (int k = 0; k < lines && std::getline(in, line); ++k) out << line << "\n";
    return path(name);
  }
};

TEST_F(CliAccumulate, RunAndEvalAccumulate) {
  const CliRun plain = run("run " + path("seq"));
  ASSERT_EQ(plain.status, 0) << plain.out;
  EXPECT_THAT(plain.out, Not(HasSubstr("accumulated")));
  const CliRun r = run("run " + path("seq") + " --accumulate 10 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("\"accumulation\""));
  EXPECT_THAT(r.out, HasSubstr("\"scans\": 10"));
  const CliRun odo = run("run " + path("seq") + " --accumulate 10 --odometry " + path("seq/odometry.txt"));
  ASSERT_EQ(odo.status, 0) << odo.out;
  EXPECT_THAT(odo.out, HasSubstr("accumulated 10 scans per frame"));
  const CliRun e = run("eval " + path("seq") + " --accumulate 10 --no-pairs");
  ASSERT_EQ(e.status, 0) << e.out;
  EXPECT_THAT(e.out, HasSubstr("frames 12"));
}

TEST_F(CliAccumulate, MissingOrShortOdometryNamesTheFile) {
  for (const char* command : {"run ", "eval "}) {
    CliRun r = run(command + path("seq") + " --accumulate 10 --odometry " + path("none.txt"));
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_THAT(r.out, HasSubstr("cannot open " + path("none.txt")));
    const std::string short_odometry = truncatedOdometry(7, "short.txt");
    r = run(command + path("seq") + " --accumulate 10 --odometry " + short_odometry);
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_THAT(r.out, HasSubstr(short_odometry + ": 7 poses but the sequence has 12 frames"));
  }
}

TEST_F(CliAccumulate, PosesTxtMustBeThereWholeAndWithItsCalib) {
  fs::rename(path("seq/poses.txt"), path("poses.txt"));
  CliRun r = run("run " + path("seq") + " --accumulate 10");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr((fs::path(path("seq")) / "poses.txt").string() + ": missing; --accumulate needs"));
  // Short: 11 of 12 poses.
  {
    std::ifstream in(path("poses.txt"));
    std::ofstream out(path("seq/poses.txt"));
    std::string line;
    for (int k = 0; k < 11 && std::getline(in, line); ++k) out << line << "\n";
  }
  r = run("run " + path("seq") + " --accumulate 10");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("poses.txt: 11 poses but the sequence has 12 frames"));
  // Whole, but without calib.txt its cam0 poses cannot be brought into the LiDAR frame: the frame rule refuses
  // them, naming --calib (io/trajectory_frame.h); --calib can.
  fs::copy_file(path("poses.txt"), path("seq/poses.txt"), fs::copy_options::overwrite_existing);
  fs::rename(path("seq/calib.txt"), path("calib.txt"));
  r = run("run " + path("seq") + " --accumulate 10");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("poses.txt: these KITTI poses move along their z axis, as KITTI's cam0 poses do"));
  EXPECT_THAT(r.out, HasSubstr("give --calib CALIB.txt"));
  r = run("run " + path("seq") + " --accumulate 10 --calib " + path("calib.txt"));
  EXPECT_EQ(r.status, 0) << r.out;
}

TEST_F(CliAccumulate, BadCombinationsAreUsageErrors) {
  for (const std::string& args : {"run --nodes " + path("seq") + " --accumulate 10",
                                  "eval " + path("seq") + " --nodes " + path("seq") + " --accumulate 10",
                                  "run " + path("seq") + " --accumulate 0", "run " + path("seq") + " --accumulate 1001",
                                  "run " + path("seq") + " --calib " + path("seq/calib.txt")}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
  }
}

}  // namespace
}  // namespace sgtllc
