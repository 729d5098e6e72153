// The 32-beam sensor on the command line: `pair` on two consecutive real nuScenes-lidarseg keyframes (one byte of
// label per point, data/nuscenes) with configs/nuscenes.yaml, and a label file of the wrong size.
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
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

/// configs/nuscenes.yaml written to @p path with @p setting joined to its verification section.
void writeConfigWith(const std::string& path, const std::string& setting) {
  std::ifstream config(kConfig);
  std::string text((std::istreambuf_iterator<char>(config)), std::istreambuf_iterator<char>());
  const std::string section = "\nverification:\n";
  const size_t at = text.find(section);
  ASSERT_NE(at, std::string::npos) << kConfig;
  text.insert(at + section.size(), "  " + setting + "\n");
  std::ofstream(path) << text;
}

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
  EXPECT_EQ(nodesOn(hybrid.out, "query", "34752"), 8) << hybrid.out;
  EXPECT_EQ(nodesOn(hybrid.out, "match", "34720"), 7) << hybrid.out;
  EXPECT_NE(hybrid.out.find("loop: YES"), std::string::npos) << hybrid.out;
  const CliRun file = run(pair + " --labeller file");
  ASSERT_EQ(file.status, 0) << file.out;
  EXPECT_EQ(nodesOn(file.out, "query", "34752"), 3) << file.out;
  EXPECT_NE(file.out.find("loop: no"), std::string::npos) << file.out;
}

/// The translation (x, y) and yaw (degrees) of the first T_match_query `sgtllc pair` prints.
std::array<double, 3> printedPose(const std::string& out) {
  const std::regex row("\\[ +(\\S+) +(\\S+) +\\S+ +(\\S+) \\]");
  std::vector<std::array<double, 3>> rows;
  for (std::sregex_iterator it(out.begin(), out.end(), row), end; it != end && rows.size() < 2; ++it) {
    rows.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  }
  if (rows.size() < 2) return {NAN, NAN, NAN};
  return {rows[0][2], rows[1][2], std::atan2(rows[1][0], rows[0][0]) * 180.0 / M_PI};
}

/// The pose `sgtllc pair` printed for keyframe 1 against 0 is the scene's: T_0_1 = (−0.272, 2.072, 0.002) m, yaw
/// 9.10° (the scene's poses), within 0.3 m and 2°.
void expectTheScenesPose(const std::string& out) {
  const std::array<double, 3> pose = printedPose(out);
  EXPECT_NEAR(pose[0], -0.272, 0.3) << out;
  EXPECT_NEAR(pose[1], 2.072, 0.3) << out;
  EXPECT_NEAR(pose[2], 9.10, 2.0) << out;
}

TEST(CliNuScenes, LabelFreePairVerifies) {
  // From the scans alone, with the config (poles and trunks of 15 points, their nodes at the sensor's height), the
  // two keyframes have 6 and 5 nodes; the descriptors' 5 pairs hold no rigid set of 3 (checked last), but 4 of the
  // nodes agree in their distances: the consistency path (algorithm §7.8) verifies them at the scene's own pose.
  const std::string pair = "pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --labeller geometric";
  const CliRun r = run(pair + " --config " + kConfig);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(nodesOn(r.out, "query", "34752"), 6) << r.out;
  EXPECT_EQ(nodesOn(r.out, "match", "34720"), 5) << r.out;
  EXPECT_NE(r.out.find("loop: YES"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("associations 4, inliers 4   (pairs chosen by geometric consistency"), std::string::npos)
      << r.out;
  expectTheScenesPose(r.out);

  const std::string without = testing::TempDir() + "/nuscenes_without_consistency.yaml";
  writeConfigWith(without, "consistency_pairs: 0");
  const CliRun paper = run(pair + " --config " + without);
  ASSERT_EQ(paper.status, 0) << paper.out;
  EXPECT_NE(paper.out.find("associations 5, inliers 0   (rejected: ransac_failed)"), std::string::npos) << paper.out;
}

TEST(CliNuScenes, LabelFreePairVerifiesByConsistency) {
  // With 20-point poles and trunks at their points' mean height (the defaults before "Upright objects at the
  // sensor's height", BENCHMARKS.md) the keyframes have 5 nodes each; the descriptors' 4 pairs hold no rigid set of
  // 3, so RANSAC fails, but 3 of the nodes agree in their distances and the consistency path (algorithm §7.8)
  // verifies them.
  const std::string pair = "pair " + kScene + "velodyne/000001.bin " + kScene + "velodyne/000000.bin --labeller geometric";
  const std::string mean_height = testing::TempDir() + "/upright_at_mean_height.yaml";
  std::ofstream(mean_height) << "labels:\n  preset: nuscenes\ncluster:\n  trunk: {centre_height: points}\n"
                                "  pole: {centre_height: points}\n  traffic-sign: {centre_height: points}\n";
  const CliRun r = run(pair + " --config " + mean_height);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(nodesOn(r.out, "query", "34752"), 5) << r.out;
  EXPECT_NE(r.out.find("loop: YES"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pairs chosen by geometric consistency"), std::string::npos) << r.out;
  expectTheScenesPose(r.out);

  std::ofstream(mean_height, std::ios::app) << "verification:\n  consistency_pairs: 0\n";
  const CliRun paper = run(pair + " --config " + mean_height);
  ASSERT_EQ(paper.status, 0) << paper.out;
  EXPECT_NE(paper.out.find("loop: no"), std::string::npos) << paper.out;
  EXPECT_NE(paper.out.find("rejected: ransac_failed"), std::string::npos) << paper.out;
}

TEST(CliNuScenes, TheFootprintSearchFindsTheMetresTheNodesMissedAlongAStreet) {
  // Scene 0006, keyframe 2 against 0: 9.70 m along a straight street (T_0_2 = (0.059, 9.699, 0.714) m, yaw −0.24°,
  // the scene's poses). With the dataset's labels the 4 inliers are fences and ground, segments centred on the
  // part each scan sees, and their pose 0.5 m long; the footprint check passes it (0.68) and ICP stays near zero.
  // The footprint search (algorithm §7.9) moves it 10 m along the street, where the structure agrees (0.86), the
  // nodes that pose pairs refine it to 9.49 m, and ICP from there to 9.71 m.
  const std::string scene = kData + "/nuscenes/0006/";
  const std::string pair =
      "pair " + scene + "velodyne/000002.bin " + scene + "velodyne/000000.bin --labeller file --config ";
  const CliRun r = run(pair + kConfig);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("loop: YES"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("footprint search: the nodes' pose moved by (0.00, 10.00) m"), std::string::npos) << r.out;
  std::array<double, 3> pose = printedPose(r.out);
  EXPECT_NEAR(pose[0], 0.059, 0.3) << r.out;
  EXPECT_NEAR(pose[1], 9.699, 0.3) << r.out;
  EXPECT_NEAR(pose[2], -0.24, 2.0) << r.out;

  const std::string off = testing::TempDir() + "/nuscenes_without_footprint_search.yaml";
  writeConfigWith(off, "footprint_search: 0");
  const CliRun before = run(pair + off);
  ASSERT_EQ(before.status, 0) << before.out;
  EXPECT_NE(before.out.find("loop: YES"), std::string::npos) << before.out;  // the same decision ...
  EXPECT_EQ(before.out.find("footprint search"), std::string::npos) << before.out;
  pose = printedPose(before.out);
  EXPECT_LT(pose[1], 1.0) << before.out;  // ... with a pose metres short
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
