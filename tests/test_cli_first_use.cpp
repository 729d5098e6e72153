// What a new user meets first: a scan folder without labels names the two ways round it, and --quiet leaves only
// the summary on stdout.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_cli_support.h"
#include "test_kitti_support.h"

namespace sgtllc::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::string kData = SGTLLC_DATA_DIR;

class CliFirstUse : public CliTempDirTest {
 protected:
  CliFirstUse() : CliTempDirTest("first_use") {}
};

TEST_F(CliFirstUse, MissingLabelsNameTheGeometricLabellerAndTheLabelsFolder) {
  // data/kitti/07 holds two scans and no labels/.
  for (const std::string command : {"run ", "eval "}) {
    const CliRun r = run(command + kData + "/kitti/07");
    EXPECT_EQ(r.status, 1) << command << r.out;
    EXPECT_THAT(r.out, HasSubstr("missing label file (2 of 2 scans")) << command;
    EXPECT_THAT(r.out, HasSubstr("--labeller geometric")) << command;
    EXPECT_THAT(r.out, HasSubstr("--labels-dir DIR")) << command;
  }
  // With the hint followed, the same folder runs.
  const CliRun fixed = run("run " + kData + "/kitti/07 --labeller geometric");
  EXPECT_EQ(fixed.status, 0) << fixed.out;
  EXPECT_THAT(fixed.out, HasSubstr("frames 2, loops 0"));
}

TEST_F(CliFirstUse, RunHelpSaysLabelsAreOptional) {
  const CliRun r = run("run --help");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("unless --labeller geometric"));
}

TEST_F(CliFirstUse, QuietRunAndLocalizePrintTheSummaryOnly) {
  makePlantedSequence(path("seq"));
  const CliRun loud = run("run " + path("seq") + " --save-map " + path("seq.map"), false);
  ASSERT_EQ(loud.status, 0) << loud.out;
  EXPECT_THAT(loud.out, HasSubstr("loop 000053 -> 000000"));
  const CliRun quiet = run("run " + path("seq") + " --quiet", false);
  ASSERT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_THAT(quiet.out, Not(HasSubstr("loop 000053")));
  EXPECT_EQ(quiet.out.rfind("frames 54, loops 1, ", 0), 0u) << quiet.out;  // the summary is the first line
  EXPECT_EQ(std::count(quiet.out.begin(), quiet.out.end(), '\n'), 1) << quiet.out;

  // The map's own session is refused: the same scans under other names are a second session.
  namespace fs = std::filesystem;
  for (const char* sub : {"velodyne", "labels"}) {
    fs::create_directories(dir_ / "again" / sub);
    for (const fs::directory_entry& e : fs::directory_iterator(dir_ / "seq" / sub)) {
      const std::string name = "1" + e.path().filename().string().substr(1);
      fs::copy_file(e.path(), dir_ / "again" / sub / name);
    }
  }
  const std::string localize = "localize " + path("again") + " --map " + path("seq.map");
  const CliRun hits = run(localize, false);
  ASSERT_EQ(hits.status, 0) << run(localize).out;
  const CliRun summary = run(localize + " --quiet", false);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_EQ(summary.out.rfind("frames 54, localized ", 0), 0u) << summary.out;
  // Every per-frame line is gone (54 of them) and the summary is unchanged but for its timings.
  EXPECT_EQ(std::count(hits.out.begin(), hits.out.end(), '\n'), 55) << hits.out;
  EXPECT_EQ(std::count(summary.out.begin(), summary.out.end(), '\n'), 1) << summary.out;
  const std::string counts = summary.out.substr(0, summary.out.find(", ms per frame"));
  EXPECT_THAT(hits.out, HasSubstr("\n" + counts + ", ms per frame"));
}

}  // namespace
}  // namespace sgtllc::test
