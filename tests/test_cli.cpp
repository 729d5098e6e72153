// The sgtllc command: results on the bundled scans, JSON keys, sequences, and a clear message with a non-zero
// exit code for every kind of bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sgtllc/io/pcd.h"
#include "test_cli_support.h"
#include "test_node_files_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

using test::CliRun;
using test::run;

std::string scan(const std::string& frame) { return test::dataPath("kitti/00/velodyne/" + frame + ".bin"); }

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("sgtllc_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void writeBytes(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
  }
  template <typename T>
  void writeArray(const std::string& name, const std::vector<T>& v) const {
    std::ofstream(path(name), std::ios::binary)
        .write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
  }

  fs::path dir_;
};

TEST_F(Cli, PairReportsTheRevisitAndItsPose) {
  const CliRun r = run("pair " + scan("004501") + " " + scan("000052"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop: YES"));
  EXPECT_THAT(r.out, HasSubstr("T_match_query"));
  const CliRun n = run("pair " + scan("000850") + " " + scan("000088"));
  EXPECT_EQ(n.status, 0) << n.out;
  EXPECT_THAT(n.out, HasSubstr("loop: no"));
}

TEST_F(Cli, PairJsonHasTheDocumentedKeys) {
  const CliRun r = run("pair --json " + scan("004501") + " " + scan("000052"), false);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"loop", "score", "score_c", "nodes_query", "nodes_match", "associations", "inliers",
                          "T_match_query", "timing_ms"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(j["loop"].get<bool>());
  EXPECT_EQ(j["T_match_query"].size(), 4u);
  EXPECT_EQ(j["T_match_query"][0].size(), 4u);
  EXPECT_NEAR(j["T_match_query"][0][3].get<double>(), 2.988, 0.15);
  EXPECT_GT(j["score"].get<double>(), 0.3);
  EXPECT_EQ(j["inliers"].get<int>() <= j["associations"].get<int>(), true);
  for (const char* stage : {"load", "extraction", "description", "verification", "total"}) {
    EXPECT_TRUE(j["timing_ms"].contains(stage)) << stage;
  }
}

TEST_F(Cli, ExportedNodeFilesGiveTheSameResult) {
  const CliRun r = run("pair --json --export " + path("out") + " " + scan("004501") + " " + scan("000052"), false);
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* f : {"query.ply", "match.ply", "matches.ply", "query_nodes.txt", "match_nodes.txt",
                        "query_nodes.pcd", "match_nodes.pcd"}) {
    EXPECT_TRUE(fs::exists(path("out/") + f)) << f;
  }
  // The ASCII PCD of the nodes the README promises: one point per node, at the node file's coordinates.
  const LabeledCloud pcd = io::readPcd(path("out/query_nodes.pcd"));
  ASSERT_EQ(pcd.points.size(), 23u);
  std::ifstream pcd_text(path("out/query_nodes.pcd"));
  EXPECT_THAT(std::string(std::istreambuf_iterator<char>(pcd_text), {}), HasSubstr("\nDATA ascii\n"));
  std::ifstream nodes_txt(path("out/query_nodes.txt"));
  std::string line;
  while (std::getline(nodes_txt, line) && (line.empty() || line[0] == '#')) {
  }
  double x = 0, y = 0, z = 0;
  std::istringstream(line) >> x >> y >> z;
  EXPECT_NEAR(pcd.points[0].x(), x, 1e-5);
  EXPECT_NEAR(pcd.points[0].z(), z, 1e-5);
  EXPECT_NEAR(pcd.points[0].y(), y, 1e-5);
  EXPECT_EQ(nlohmann::json::parse(r.out)["score_t"], nlohmann::json::parse(r.out)["score"]);  // the old name, kept
  std::ifstream ply(path("out/matches.ply"));
  const std::string text(std::istreambuf_iterator<char>(ply), {});
  EXPECT_THAT(text, HasSubstr("element vertex 48\n"));  // 25 match + 23 query nodes
  EXPECT_THAT(text, HasSubstr("element edge 22\n"));    // one per association
  const CliRun n = run("pair --json " + path("out/query_nodes.txt") + " " + path("out/match_nodes.txt"), false);
  ASSERT_EQ(n.status, 0) << n.out;
  const auto a = nlohmann::json::parse(r.out), b = nlohmann::json::parse(n.out);
  for (const char* key : {"loop", "score", "score_c", "nodes_query", "nodes_match", "associations", "inliers"}) {
    EXPECT_EQ(a[key], b[key]) << key;
  }
  // Node files carry no points: their pose is the object-level SVD pose that the scans' ICP started from.
  EXPECT_EQ(a["refinement"]["T_match_query_svd"], b["T_match_query"]);
  EXPECT_TRUE(b["refinement"].is_null());
  EXPECT_EQ(a["refinement"]["status"], "converged");
  // A second export into the same folder keeps the files unless --force.
  const CliRun again = run("pair --export " + path("out") + " " + scan("004501") + " " + scan("000052"));
  EXPECT_EQ(again.status, 1);
  EXPECT_THAT(again.out, HasSubstr("--force"));
}

TEST_F(Cli, MissingFileIsNamed) {
  const CliRun r = run("pair " + path("nope.bin") + " " + scan("000052"));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr(path("nope.bin")));
}

TEST_F(Cli, TruncatedBinIsNamed) {
  writeBytes("bad.bin", std::string(17, '\0'));
  writeBytes("bad.label", std::string(4, '\0'));
  const CliRun r = run("pair " + path("bad.bin") + " " + scan("000052"));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("bad.bin"));
  EXPECT_THAT(r.out, HasSubstr("multiple of 16"));
}

TEST_F(Cli, LabelCountMismatchIsNamed) {
  writeArray<float>("two.bin", {1, 2, 3, 0, 4, 5, 6, 0});
  writeArray<uint32_t>("two.label", {50, 50, 50});
  const CliRun r = run("pair " + path("two.bin") + " " + scan("000052"));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("two.label"));
  EXPECT_THAT(r.out, HasSubstr("3"));
}

TEST_F(Cli, NonFinitePointsAndUnknownIdsWarnButRun) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  writeArray<float>("odd.bin", {nan, 0, 0, 0, 1, 2, 3, 0, 4, 5, 6, 0});
  writeArray<uint32_t>("odd.label", {50, 777, 40});
  const CliRun r = run("pair " + path("odd.bin") + " " + scan("000052"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("dropped 1 points with NaN or Inf"));
  EXPECT_THAT(r.out, HasSubstr("ignored 1 points whose label id"));
  EXPECT_THAT(r.out, HasSubstr("no graph nodes"));
  EXPECT_THAT(r.out, HasSubstr("loop: no"));
}

TEST_F(Cli, EmptyScanIsNoLoopNotAnError) {
  writeBytes("empty.bin", "");
  writeBytes("empty.label", "");
  const CliRun r = run("pair " + path("empty.bin") + " " + scan("000052"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop: no"));
}

TEST_F(Cli, BadConfigKeysAreNamed) {
  writeBytes("typo.yaml", "verification:\n  sigma4: 0.2\n");
  const CliRun r = run("pair --config " + path("typo.yaml") + " " + scan("004501") + " " + scan("000052"));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("typo.yaml:2"));
  EXPECT_THAT(r.out, HasSubstr("unknown key 'verification.sigma4'"));
  writeBytes("bad.yaml", "graph:\n  sigma_d: thirty\n");
  const CliRun b = run("config --config " + path("bad.yaml"));
  EXPECT_EQ(b.status, 1);
  EXPECT_THAT(b.out, HasSubstr("graph.sigma_d"));
}

TEST_F(Cli, ConfigOutputIsReadBack) {
  const CliRun r = run("config", false);
  ASSERT_EQ(r.status, 0);
  writeBytes("defaults.yaml", r.out);
  const CliRun again = run("config --config " + path("defaults.yaml"), false);
  EXPECT_EQ(again.status, 0);
  EXPECT_EQ(again.out, r.out);
}

TEST_F(Cli, BadCommandLineIsAUsageError) {
  EXPECT_EQ(run("pair " + scan("004501")).status, 2);
  EXPECT_EQ(run("frobnicate").status, 2);
}

TEST_F(Cli, ConfigThatIsAFolderIsAnError) {
  const CliRun r = run("pair --config " + dir_.string() + " " + scan("004501") + " " + scan("000052"));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr(dir_.string()));
  EXPECT_THAT(r.out, HasSubstr("directory"));
}

TEST_F(Cli, HugePcdFieldCountIsAnErrorNotACrash) {
  writeBytes("k.pcd",
             "FIELDS p x q y z label\nSIZE 4 4 4 4 4 4\nTYPE U F U F F U\n"
             "COUNT 2305843009213693952 1 2305843009213693952 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n" +
                 std::string(16, '\0'));
  const CliRun r = run("pair " + path("k.pcd") + " " + path("k.pcd"));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("k.pcd:4"));
  EXPECT_THAT(r.out, HasSubstr("COUNT"));
}

TEST_F(Cli, FarTranslationsPrintInFull) {
  // The same objects 20 km away: a loop whose translation needs more digits than the usual column width.
  std::ofstream a(path("a.txt")), b(path("b.txt"));
  a.precision(12);
  b.precision(12);
  const int ids[] = {50, 51, 70, 71, 80, 81};
  for (int k = 0; k < 24; ++k) {
    const double x = 7.0 * std::cos(k * 1.3) * (1 + k % 5), y = 6.0 * std::sin(k * 0.7) * (1 + k % 4), z = k % 3;
    a << x << " " << y << " " << z << " " << ids[k % 6] << "\n";
    b << x - 20000.0 << " " << y << " " << z << " " << ids[k % 6] << "\n";
  }
  a.close();
  b.close();
  // By default the offset decay (verification.offset_decay_end = 20 m) scores a pose 20 km away 0; without it,
  // a loop. Either way the translation prints in full.
  const CliRun r = run("pair " + path("a.txt") + " " + path("b.txt"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop: no   score 0.000"));
  EXPECT_THAT(r.out, HasSubstr("score scaled by 0.000 for the estimated offset 20000.00 m"));
  EXPECT_THAT(r.out, HasSubstr("-20000.000000 ]"));
  std::ofstream(path("no-decay.yaml")) << "verification:\n  offset_decay_end: 0\n";
  const CliRun plain = run("pair " + path("a.txt") + " " + path("b.txt") + " --config " + path("no-decay.yaml"));
  ASSERT_EQ(plain.status, 0) << plain.out;
  EXPECT_THAT(plain.out, HasSubstr("loop: YES"));
  EXPECT_THAT(plain.out, Not(HasSubstr("scaled by")));
  EXPECT_THAT(plain.out, HasSubstr("-20000.000000 ]"));
}

void makeSequence(const fs::path& dir) { test::makePlantedSequence(dir.string()); }

TEST_F(Cli, RunFindsThePlantedLoopAndWritesCsv) {
  makeSequence(dir_ / "seq");
  const CliRun r = run("run " + (dir_ / "seq").string() + " --out " + path("loops.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop 000053 -> 000000"));
  EXPECT_THAT(r.out, HasSubstr("frames 54, loops 1"));
  std::ifstream csv(path("loops.csv"));
  std::string header, line, extra;
  std::getline(csv, header);
  std::getline(csv, line);
  EXPECT_FALSE(std::getline(csv, extra));
  EXPECT_EQ(header.substr(0, 26), "query,match,score,score_c,");
  EXPECT_EQ(line.substr(0, 14), "000053,000000,");
  EXPECT_EQ(std::count(line.begin(), line.end(), ','), 36);  // 16 columns and the 21 information entries

  // Same bytes at two threads; the existing file is kept unless --force.
  const CliRun refuse = run("run " + (dir_ / "seq").string() + " --out " + path("loops.csv"));
  EXPECT_EQ(refuse.status, 1);
  EXPECT_THAT(refuse.out, HasSubstr("--force"));
  const CliRun two = run("run " + (dir_ / "seq").string() + " --threads 2 --out " + path("loops2.csv"));
  ASSERT_EQ(two.status, 0) << two.out;
  std::ifstream a(path("loops.csv")), b(path("loops2.csv"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
}

TEST_F(Cli, RunReadsNodeFilesLikeScans) {
  // Users with their own object extraction give one node file per frame; the loops must equal the scans' when the
  // node files hold the nodes those scans give.
  makeSequence(dir_ / "seq");
  const Config config;
  test::writeNodeFiles(pipeline::FrameSource::semanticKitti((dir_ / "seq").string(), config), (dir_ / "nodes").string());
  ASSERT_EQ(run("run " + (dir_ / "seq").string() + " --out " + path("scans.csv")).status, 0);
  const CliRun r = run("run --nodes " + (dir_ / "nodes").string() + " --out " + path("nodes.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop 000053 -> 000000"));
  std::ifstream a(path("scans.csv")), b(path("nodes.csv"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
  // Exactly one of SEQ_DIR and --nodes.
  EXPECT_EQ(run("run").status, 2);
  const CliRun both = run("run " + (dir_ / "seq").string() + " --nodes " + (dir_ / "nodes").string());
  EXPECT_EQ(both.status, 2);
  EXPECT_THAT(both.out, HasSubstr("either SEQ_DIR"));
}

TEST_F(Cli, RunChecksTheOutputPathBeforeWorking) {
  makeSequence(dir_ / "seq");
  const CliRun r = run("run " + (dir_ / "seq").string() + " --out " + path("no/such/folder/loops.csv"));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("does not exist"));
  EXPECT_THAT(r.out, Not(HasSubstr("frames 54")));
  const CliRun d = run("run " + (dir_ / "seq").string() + " --force --out " + (dir_ / "seq").string());
  EXPECT_EQ(d.status, 1);
  EXPECT_THAT(d.out, HasSubstr("is a directory"));
  EXPECT_EQ(run("run " + (dir_ / "seq").string() + " --threads 100000").status, 2);
}

TEST_F(Cli, RunNamesAMissingLabelFile) {
  makeSequence(dir_ / "seq");
  fs::remove(dir_ / "seq" / "labels" / "000010.label");
  const CliRun r = run("run " + (dir_ / "seq").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("000010.label"));
  const CliRun none = run("run " + path("no_such_sequence"));
  EXPECT_EQ(none.status, 1);
  EXPECT_THAT(none.out, HasSubstr("no_such_sequence"));
}

}  // namespace
}  // namespace sgtllc
