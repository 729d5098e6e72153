// Bad input to `sgtllc optimize` and `run --odometry`: a message naming the file, the line and the problem, exit 1,
// and no output touched, even with --force.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_cli_backend_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;
using test::CliRun;
using test::run;

class BadInput : public test::CliBackend {
 protected:
  void SetUp() override {
    CliBackend::SetUp();
    truth_ = test::circleDrive(100);
    odometry_ = test::tumText(truth_);
    write("odo.txt", odometry_);
    write("loops.csv", "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n"
                       "000090,000010,0.5,0.6,1,0,0,0,0,1,0,0,0,0,1,0\n");
    write("corrected.txt", "keep me\n");
    write("graph.g2o", "keep me too\n");
  }
  /// optimize with --force onto the existing outputs; they must survive the failure.
  CliRun optimize(const std::string& extra = "") const {
    return run("optimize --odometry " + path("odo.txt") + " --loops " + path("loops.csv") + " --force " +
               "--out-trajectory " + path("corrected.txt") + " --out-graph " + path("graph.g2o") + " " + extra);
  }
  void expectFailure(const CliRun& r, const std::string& where, const std::string& problem) const {
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_THAT(r.out, HasSubstr(where)) << r.out;
    EXPECT_THAT(r.out, HasSubstr(problem)) << r.out;
    EXPECT_EQ(read("corrected.txt"), "keep me\n");
    EXPECT_EQ(read("graph.g2o"), "keep me too\n");
  }
  std::vector<Eigen::Isometry3d> truth_;
  std::string odometry_;
};

TEST_F(BadInput, GoodInputRuns) {
  // The control: the same files and options work, and then they do replace the outputs.
  const CliRun r = optimize();
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(read("corrected.txt"), "keep me\n");
}

TEST_F(BadInput, MalformedOrNonFinitePoses) {
  std::string bad = odometry_;
  bad.insert(bad.find('\n') + 1, "0.1 1 2 3\n");
  write("odo.txt", bad);
  expectFailure(optimize(), path("odo.txt") + ":2", "4 columns");
  bad = odometry_;
  bad.replace(bad.find('\n') + 1, 3, "nan");
  write("odo.txt", bad);
  expectFailure(optimize(), path("odo.txt") + ":2", "'nan' is not a finite number");
}

TEST_F(BadInput, OdometryWithOtherThanOnePosePerFrame) {
  // Against a frame list (--frames: a node folder of 101 frames).
  std::filesystem::create_directories(path("nodes"));
  for (size_t i = 0; i < 101; ++i) write("nodes/" + test::frameName(i) + ".txt", "1 2 3 50\n");
  expectFailure(optimize("--frames " + path("nodes")), path("odo.txt") + ": 100 poses but the sequence has 101 frames",
                "one pose per frame");
  // run against a sequence folder: one pose too many.
  test::makePlantedSequence(path("seq"));
  write("odo55.txt", test::tumText(test::circleDrive(55)));
  const CliRun r = run("run " + path("seq") + " --odometry " + path("odo55.txt") + " --force --out-trajectory " +
                       path("corrected.txt"));
  expectFailure(r, path("odo55.txt") + ": 55 poses but the sequence has 54 frames", "");
  EXPECT_THAT(r.out, ::testing::Not(HasSubstr("loop 000053")));  // checked before the sequence is processed
}

TEST_F(BadInput, LoopsNamingUnknownFramesOrWithBadColumns) {
  write("loops.csv", "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n"
                     "000090,000010,0.5,0.6,1,0,0,0,0,1,0,0,0,0,1,0\n"
                     "000190,000010,0.5,0.6,1,0,0,0,0,1,0,0,0,0,1,0\n");
  expectFailure(optimize(), path("loops.csv") + ":3", "unknown query frame '000190'");
  write("loops.csv", "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n000090,000010,0.5\n");
  expectFailure(optimize(), path("loops.csv") + ":2", "3 columns, expected 16");
  write("loops.csv", "query,match,score\n");
  expectFailure(optimize(), path("loops.csv") + ":1", "is not the loops CSV header");
  // The information form: all 21 entries or none.
  std::string header = "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz";
  for (const std::string& c : io::loopsCsvInformationColumns()) header += "," + c;
  write("loops.csv", header + "\n000090,000010,0.5,0.6,1,0,0,0,0,1,0,0,0,0,1,0,1" + std::string(20, ',') + "\n");
  expectFailure(optimize(), path("loops.csv") + ":2", "column i12");
}

TEST_F(BadInput, CalibWithoutTr) {
  write("calib.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n");
  std::string kitti;
  for (size_t i = 0; i < truth_.size(); ++i) kitti += "1 0 0 " + std::to_string(i) + " 0 1 0 0 0 0 1 0\n";
  write("odo.txt", kitti);
  expectFailure(optimize("--calib " + path("calib.txt")), path("calib.txt"), "Tr");
}

TEST_F(BadInput, OutputsAreCheckedBeforeAnyWork) {
  const CliRun r = run("optimize --odometry " + path("odo.txt") + " --loops " + path("loops.csv") +
                       " --out-trajectory " + path("corrected.txt"));
  expectFailure(r, path("corrected.txt"), "file exists");
  expectFailure(optimize("--out-loops " + path("no/such/folder/l.g2o")), "does not exist", "");
  EXPECT_EQ(run("run " + path("seq") + " --out-graph " + path("g.g2o")).status, 2);  // needs --odometry
}

}  // namespace
}  // namespace sgtllc
