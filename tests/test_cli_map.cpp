// `sgtllc run --save-map`, `sgtllc localize` and `sgtllc map info` (docs/map-format.md): two sessions of one synthetic world
// as node files, and every refusal docs/map-format.md lists (another configuration, a directory, a truncated map, a query
// session that is the map's own, an existing file without --force).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sgtllc/io/kitti_write.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/map/map_format.h"
#include "test_cli_support.h"
#include "test_map_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;

class CliMap : public test::CliTempDirTest {
 protected:
  CliMap() : CliTempDirTest("map") {}
  void SetUp() override {
    CliTempDirTest::SetUp();
    writeSession(test::circleSequence(110), path("s1"));
    second_ = test::circleSequence(20, 3.0, 0.9, /*seed=*/99);
    writeSession(second_, path("s2"));
    std::ofstream(path("config.yaml")) << "retrieval:\n  exclude_recent: 20\n";
  }
  /// DIR/nodes/NAME.txt node files, DIR/poses.txt (KITTI cam0 = LiDAR here: calib Tr is the identity) and calib.txt.
  static void writeSession(const test::NodeSequence& s, const std::string& dir) {
    fs::create_directories(dir + "/nodes");
    for (size_t i = 0; i < s.frames.size(); ++i) io::writeNodesTxt(dir + "/nodes/" + s.names[i] + ".txt", s.frames[i]);
    io::writeKittiPoses(dir + "/poses.txt", s.poses);
    std::ofstream(dir + "/calib.txt") << "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  }
  std::string saveMap(const std::string& map = "m.sgtmap") {
    const auto r = test::run(s1() + " --save-map " + path(map));
    EXPECT_EQ(r.status, 0) << r.out;
    return r.out;
  }
  /// `run` of session 1 with its poses as odometry.
  std::string s1() const {
    return "run --nodes " + path("s1/nodes") + " --odometry " + path("s1/poses.txt") + " --calib " +
           path("s1/calib.txt") + " --config " + path("config.yaml");
  }
  test::NodeSequence second_;
};

TEST_F(CliMap, SavesAMapAndLocalizesASecondSessionInIt) {
  const std::string run_out = saveMap();
  EXPECT_NE(run_out.find("wrote map " + path("m.sgtmap") + " (110 frames; poses: the corrected trajectory of " + path("s1/poses.txt") + ")"),
            std::string::npos)
      << run_out;
  const auto info = test::run("map info " + path("m.sgtmap"));
  ASSERT_EQ(info.status, 0) << info.out;
  EXPECT_NE(info.out.find("format version " + std::to_string(map::kFormatVersion)), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("frames 110 (with poses), first 000000, last 000109"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("retrieval.histogram_bins: 30"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("\nfootprints 0 of 110 frames\n"), std::string::npos) << info.out;  // node files: none
  EXPECT_NE(info.out.find("  KEYS v1  "), std::string::npos) << info.out;

  const std::string args = "localize --map " + path("m.sgtmap") + " --nodes " + path("s2/nodes") + " --config " +
                           path("config.yaml");
  const auto one = test::run(args + " --out " + path("hits1.csv") + " --threads 1");
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_NE(one.out.find("frames 20, localized "), std::string::npos) << one.out;
  const auto three = test::run(args + " --out " + path("hits3.csv") + " --threads 3");
  ASSERT_EQ(three.status, 0) << three.out;
  const std::string csv = test::fileBytes(path("hits1.csv"));
  EXPECT_EQ(csv, test::fileBytes(path("hits3.csv")));

  // Every localized row's map position is the second session's true position.
  std::istringstream rows(csv);
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line.rfind("query,map_frame,localized,score,score_c,lateral,T_mapframe_query_00,", 0), 0u) << line;
  EXPECT_EQ(line.substr(line.size() - std::string(",T_world_query_23,tracked").size()), ",T_world_query_23,tracked");
  int localized = 0;
  for (size_t q = 0; std::getline(rows, line); ++q) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 31u) << line;
    EXPECT_EQ(cells[0], second_.names[q]);
    EXPECT_EQ(cells[30], "0") << line;  // nothing is tracked without --track
    if (cells[2] != "1") continue;
    ++localized;
    const Eigen::Vector3d t(std::stod(cells[21]), std::stod(cells[25]), std::stod(cells[29]));
    EXPECT_LT((t - second_.poses[q].topRightCorner<3, 1>()).norm(), 0.3) << line;
  }
  EXPECT_GE(localized, 18);

  const auto json = test::run(args + " --json", false);
  ASSERT_EQ(json.status, 0);
  EXPECT_NE(json.out.find("\"localized\": " + std::to_string(localized)), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"T_world_query\""), std::string::npos);
}

TEST_F(CliMap, EvalWithAMapScoresTheRelocalizationProtocol) {
  saveMap();
  // A session 1 m beside session 1's circle (second_ runs 3 m beside it: no frame of it is a positive).
  const test::NodeSequence third = test::circleSequence(20, 1.0, 0.9, /*seed=*/77);
  writeSession(third, path("s3"));
  const auto localize = test::run("localize --map " + path("m.sgtmap") + " --nodes " + path("s3/nodes") +
                                  " --config " + path("config.yaml") + " --json", false);
  ASSERT_EQ(localize.status, 0) << localize.out;
  const auto eval = test::run("eval " + path("s3") + " --nodes " + path("s3/nodes") + " --map " + path("m.sgtmap") +
                              " --config " + path("config.yaml") + " --json", false);
  ASSERT_EQ(eval.status, 0) << eval.out;
  const nlohmann::json j = nlohmann::json::parse(eval.out);
  const nlohmann::json hits = nlohmann::json::parse(localize.out);
  // Positives and negatives by brute force over both sessions' poses (map poses: session 1's corrected
  // trajectory, its own poses as odometry).
  const test::NodeSequence first = test::circleSequence(110);
  int positives = 0, negatives = 0;
  for (const Eigen::Matrix4d& q : third.poses) {
    double nearest = 1e9;
    for (const Eigen::Matrix4d& m : first.poses) {
      nearest = std::min(nearest, (m.topRightCorner<3, 1>() - q.topRightCorner<3, 1>()).norm());
    }
    positives += nearest <= 3.0;
    negatives += nearest > 20.0;
  }
  EXPECT_EQ(j["reloc_queries"], 20);
  EXPECT_EQ(j["reloc_positives"], positives);
  EXPECT_EQ(j["reloc_negatives"], negatives);
  EXPECT_EQ(j["reloc_accepted"], hits["localized"]);  // the same answers as `localize`
  ASSERT_GT(positives, 0);
  EXPECT_DOUBLE_EQ(j["reloc_recall_at_1"].get<double>(), j["reloc_accepted_near"].get<double>() / positives);
  EXPECT_GE(j["reloc_pose_success"].get<double>(), 0.9);
  for (const char* key : {"reloc_precision", "reloc_false_rate"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["track"], false);
  EXPECT_GE(j["reloc_accepted_placed"].get<int>(), j["reloc_pose_successes"].get<int>());

  // --track: the same frames as one stream; every answer accepted alone stays accepted, and localize agrees.
  const auto tracked = test::run("eval " + path("s3") + " --nodes " + path("s3/nodes") + " --map " +
                                 path("m.sgtmap") + " --config " + path("config.yaml") + " --json --track", false);
  ASSERT_EQ(tracked.status, 0) << tracked.out;
  const nlohmann::json t = nlohmann::json::parse(tracked.out);
  EXPECT_EQ(t["track"], true);
  EXPECT_GE(t["reloc_accepted"].get<int>(), j["reloc_accepted"].get<int>());
  const auto tracked_hits = test::run("localize --map " + path("m.sgtmap") + " --nodes " + path("s3/nodes") +
                                      " --config " + path("config.yaml") + " --json --track", false);
  ASSERT_EQ(tracked_hits.status, 0) << tracked_hits.out;
  const nlohmann::json tracked_json = nlohmann::json::parse(tracked_hits.out);
  EXPECT_EQ(t["reloc_accepted"], tracked_json["localized"]);
  // hits.csv's last column is the JSON's `tracked`, row by row. This session's answers all score 0.9-1.0, so with
  // sigma_4 = 0.95 the track (started by the first frame's 1.0) takes the frames between 0.2 and 0.95.
  std::ofstream(path("track.yaml")) << "retrieval:\n  exclude_recent: 20\nverification:\n  sigma_4: 0.95\n";
  const std::string track_args = "localize --map " + path("m.sgtmap") + " --nodes " + path("s3/nodes") +
                                 " --config " + path("track.yaml") + " --track";
  const auto track_json = test::run(track_args + " --json", false);
  ASSERT_EQ(track_json.status, 0) << track_json.out;
  const nlohmann::json track_hits = nlohmann::json::parse(track_json.out)["hits"];
  ASSERT_EQ(test::run(track_args + " --out " + path("tracked.csv")).status, 0);
  std::istringstream rows(test::fileBytes(path("tracked.csv")));
  std::string line;
  std::getline(rows, line);
  size_t q = 0;
  int tracked_rows = 0;
  for (; std::getline(rows, line); ++q) {
    ASSERT_LT(q, track_hits.size());
    const nlohmann::json& hit = track_hits[q];
    const bool row_tracked = line.substr(line.rfind(',') + 1) == "1";
    EXPECT_EQ(row_tracked, hit["tracked"].get<bool>()) << line;
    EXPECT_EQ(line.substr(0, line.find(',')), hit["query"].get<std::string>());
    if (row_tracked) {  // a tracked row is a localized one, scoring between weak_sigma and sigma_4
      EXPECT_NE(line.find("," + hit["map_frame"].get<std::string>() + ",1,"), std::string::npos) << line;
      EXPECT_GT(hit["score"].get<double>(), 0.2);
      EXPECT_LE(hit["score"].get<double>(), 0.95);
    }
    tracked_rows += row_tracked;
  }
  EXPECT_EQ(q, track_hits.size());
  EXPECT_GT(tracked_rows, 0);
  EXPECT_EQ(test::run("eval " + path("s3") + " --nodes " + path("s3/nodes") + " --track").status, 2);

  const auto report = test::run("eval " + path("s3") + " --nodes " + path("s3/nodes") + " --map " +
                                path("m.sgtmap") + " --report " + path("r"));
  EXPECT_EQ(report.status, 2) << report.out;  // --map runs the relocalization protocol alone
  EXPECT_FALSE(fs::exists(path("r")));
}

TEST_F(CliMap, SavingAMapChangesNoOtherOutput) {
  const std::string base = s1();
  ASSERT_EQ(test::run(base + " --out " + path("plain.csv")).status, 0);
  ASSERT_EQ(test::run(base + " --out " + path("with.csv") + " --save-map " + path("m.sgtmap")).status, 0);
  EXPECT_EQ(test::fileBytes(path("plain.csv")), test::fileBytes(path("with.csv")));
  // The same run saves the same bytes.
  ASSERT_EQ(test::run(base + " --save-map " + path("again.sgtmap")).status, 0);
  EXPECT_EQ(test::fileBytes(path("m.sgtmap")), test::fileBytes(path("again.sgtmap")));
}

TEST_F(CliMap, RefusesBadMapsWithAMessageNamingTheFile) {
  saveMap();
  const std::string bytes = test::fileBytes(path("m.sgtmap"));
  const std::string query = " --nodes " + path("s2/nodes") + " --config " + path("config.yaml");

  // An existing map is kept without --force.
  const auto again = test::run(s1() + " --save-map " + path("m.sgtmap"));
  EXPECT_EQ(again.status, 1);
  EXPECT_NE(again.out.find(path("m.sgtmap") + ": file exists"), std::string::npos) << again.out;
  EXPECT_EQ(test::fileBytes(path("m.sgtmap")), bytes);

  std::ofstream(path("bins.yaml")) << "retrieval:\n  exclude_recent: 20\n  histogram_bins: 12\n";
  const auto other = test::run("localize --map " + path("m.sgtmap") + " --nodes " + path("s2/nodes") + " --config " +
                               path("bins.yaml") + " --out " + path("hits.csv"));
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.out.find(path("m.sgtmap") + ": the map was built with another configuration: "
                           "retrieval.histogram_bins: the map was built with 30, the configuration has 12"),
            std::string::npos)
      << other.out;
  EXPECT_FALSE(fs::exists(path("hits.csv")));

  const auto dir = test::run("localize --map " + path("s1") + query);
  EXPECT_EQ(dir.status, 1);
  EXPECT_NE(dir.out.find("cannot read map " + path("s1") + ": is a directory"), std::string::npos) << dir.out;
  const auto info_dir = test::run("map info " + path("s1"));
  EXPECT_EQ(info_dir.status, 1);

  std::ofstream(path("cut.sgtmap"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  for (const std::string& cmd : {"localize --map " + path("cut.sgtmap") + query, "map info " + path("cut.sgtmap")}) {
    const auto cut = test::run(cmd);
    EXPECT_EQ(cut.status, 1);
    EXPECT_NE(cut.out.find(path("cut.sgtmap") + ": truncated map file"), std::string::npos) << cut.out;
  }
  const auto missing = test::run("map info " + path("none.sgtmap"));
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find(path("none.sgtmap")), std::string::npos) << missing.out;

  // The map's own session fed back clashes; a session whose names merely repeat the map's (s2: 000000…) does not.
  const auto self = test::run("localize --map " + path("m.sgtmap") + " --nodes " + path("s1/nodes") + " --config " +
                              path("config.yaml") + " --out " + path("self.csv"));
  EXPECT_EQ(self.status, 1);
  EXPECT_NE(self.out.find("frame 000000 is frame 000000 of map " + path("m.sgtmap") +
                          " (same name, same nodes): the query sequence is the map's own session"),
            std::string::npos)
      << self.out;
  EXPECT_FALSE(fs::exists(path("self.csv")));
}

}  // namespace
}  // namespace sgtllc
