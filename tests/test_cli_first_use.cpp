// What a new user meets first: a scan folder without labels names the two ways round it, and --quiet leaves only
// the summary on stdout.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_cli_support.h"
#include "test_support.h"

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

}  // namespace
}  // namespace sgtllc::test
