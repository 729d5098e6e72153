// The 32-beam sensor on the command line: `pair` on two consecutive real nuScenes-lidarseg keyframes (one byte of
// label per point, data/nuscenes) with configs/nuscenes.yaml, and a label file of the wrong size.
#include <array>
#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_cli_support.h"

namespace sgtllc::test {
namespace {

const std::string kData = SGTLLC_DATA_DIR;
const std::string kScene = kData + "/nuscenes/0001/";
const std::string kConfig = kData + "/../configs/nuscenes.yaml";

/// Nodes printed on the `query` or `match` line of `sgtllc pair`, or −1.
int nodesOn(const std::string& out, const std::string& which, const std::string& points) {
  const std::regex line(which + " +\\S+ +\\(" + points + " points, ([0-9]+) nodes\\)");
  std::smatch m;
  return std::regex_search(out, m, line) ? std::stoi(m[1]) : -1;
}

TEST(CliNuScenes, PairOfConsecutiveKeyframesReportsNodes) {
  const CliRun r = run("pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --config " + kConfig);
  ASSERT_EQ(r.status, 0) << r.out;
  // 34,752 and 34,720 points (file sizes / 16); the nodes are of building, fence, vegetation and terrain only.
  EXPECT_GT(nodesOn(r.out, "query", "34752"), 0) << r.out;
  EXPECT_GT(nodesOn(r.out, "match", "34720"), 0) << r.out;
  EXPECT_EQ(r.out.find("ignored"), std::string::npos) << r.out;  // every id 0..39 is in the preset's label space
}

TEST(CliNuScenes, HybridSplitsPolesAndTrunksOffTheLabels) {
  // nuScenes folds poles into static.manmade: with its labels alone the two keyframes (2.1 m apart) have 3 nodes
  // each and no association; the config's hybrid source splits off the poles and trunks and the pair verifies.
  const std::string pair = "pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --config " + kConfig;
  const CliRun hybrid = run(pair);
  ASSERT_EQ(hybrid.status, 0) << hybrid.out;
  EXPECT_EQ(nodesOn(hybrid.out, "query", "34752"), 7) << hybrid.out;
  EXPECT_EQ(nodesOn(hybrid.out, "match", "34720"), 7) << hybrid.out;
  EXPECT_NE(hybrid.out.find("loop: YES"), std::string::npos) << hybrid.out;
  const CliRun file = run(pair + " --labeller file");
  ASSERT_EQ(file.status, 0) << file.out;
  EXPECT_EQ(nodesOn(file.out, "query", "34752"), 3) << file.out;
  EXPECT_NE(file.out.find("loop: no"), std::string::npos) << file.out;
}

TEST(CliNuScenes, LabelFreePairVerifiesByConsistency) {
  // From the scans alone the two keyframes have 5 nodes each; the descriptors' 4 pairs hold no rigid set of 3, so
  // RANSAC fails, but 3 of the nodes agree in their distances and the consistency path (algorithm §7.8) verifies
  // them. Reference: the scene's poses, T_0_1 = (−0.272, 2.072, 0.002) m, yaw 9.10°.
  const std::string pair = "pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --labeller geometric";
  const CliRun r = run(pair + " --config " + kConfig);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("loop: YES"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pairs chosen by geometric consistency"), std::string::npos) << r.out;
  const std::regex row("\\[ +(\\S+) +(\\S+) +\\S+ +(\\S+) \\]");
  std::vector<std::array<double, 3>> rows;
  for (std::sregex_iterator it(r.out.begin(), r.out.end(), row), end; it != end && rows.size() < 2; ++it) {
    rows.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  }
  ASSERT_EQ(rows.size(), 2u) << r.out;
  EXPECT_NEAR(rows[0][2], -0.272, 0.3) << r.out;  // x
  EXPECT_NEAR(rows[1][2], 2.072, 0.3) << r.out;   // y
  EXPECT_NEAR(std::atan2(rows[1][0], rows[0][0]) * 180.0 / M_PI, 9.10, 2.0) << r.out;  // yaw

  const std::string off = testing::TempDir() + "/consistency_off.yaml";
  std::ofstream(off) << "labels:\n  preset: nuscenes\nverification:\n  consistency_pairs: 0\n";
  const CliRun paper = run(pair + " --config " + off);
  ASSERT_EQ(paper.status, 0) << paper.out;
  EXPECT_NE(paper.out.find("loop: no"), std::string::npos) << paper.out;
  EXPECT_NE(paper.out.find("rejected: ransac_failed"), std::string::npos) << paper.out;
}

TEST(CliNuScenes, WithoutThePresetTheIdsAreReadAsSemanticKitti) {
  // The one-byte file is still read (labels.format auto), but as SemanticKITTI ids: most are not in that label set.
  const CliRun r = run("pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("ignored 21721 points whose label id is not in the configured label set"), std::string::npos)
      << r.out;
}

TEST(CliNuScenes, LabelFileOfAnotherScanIsAnErrorNamingBothSizes) {
  const std::string wrong = kData + "/nuscenes/0006/labels/000000.label";  // 34,720 bytes
  CliRun r = run("pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --labels-query " + wrong);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("000001.bin has 34752 points but " + wrong +
                       " has 34720 bytes, neither 139008 (uint32 labels, 4 bytes a point) nor 34752 (uint8 labels"),
            std::string::npos)
      << r.out;
  r = run("pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --labels-query " + wrong +
          " --config " + kConfig);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("has 34720 bytes, not 34752 (uint8 labels, 1 byte a point)"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sgtllc::test
