// Plain-text node files `x y z label`: exact round trip, comments, label mapping and counting, error messages.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/nodes.h"
#include "test_io_support.h"

namespace {

namespace fs = std::filesystem;
using sgtllc::Error;
using sgtllc::LabelMap;
using sgtllc::Node;
using sgtllc::io::NodeFileStats;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class NodesIo : public sgtllc::test::TempDirTest {};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Node node(double x, double y, double z, int label) {
  Node n;
  n.centre = Eigen::Vector3d(x, y, z);
  n.label = label;
  return n;
}

TEST_F(NodesIo, RoundTripIsExactForEveryClassAndAwkwardDoubles) {
  std::vector<Node> nodes;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-200.0, 200.0);
  for (int i = 0; i < 200; ++i) {
    Node n;
    for (int k = 0; k < 3; ++k) n.centre[k] = uniform(rng);  // one draw per statement: a fixed order
    n.label = i % sgtllc::kNumPaperClasses;
    nodes.push_back(n);
  }
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double big = std::numeric_limits<double>::max();
  nodes.push_back(node(0.1, -0.0, 1e-300, sgtllc::kPole));
  nodes.push_back(node(tiny, -big, 123456789.123456789, sgtllc::kTrafficSign));

  const std::string p = path("nodes.txt");
  sgtllc::io::writeNodesTxt(p, nodes);
  NodeFileStats stats;
  const std::vector<Node> back = sgtllc::io::readNodesTxt(p, LabelMap(), &stats);
  ASSERT_EQ(back.size(), nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_EQ(back[i].label, nodes[i].label) << "node " << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(back[i].centre[k], nodes[i].centre[k]) << "node " << i << " axis " << k;  // bit-exact, not near
      EXPECT_EQ(std::signbit(back[i].centre[k]), std::signbit(nodes[i].centre[k])) << "node " << i;
    }
  }
  EXPECT_EQ(stats.rows, nodes.size());
  EXPECT_EQ(stats.dropped_known, 0u);
  EXPECT_EQ(stats.unknown, 0u);
}

TEST_F(NodesIo, WritesHeaderCommentAndSemanticKittiRawIds) {
  const std::string p = path("nodes.txt");
  std::vector<Node> nodes;
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) nodes.push_back(node(c + 0.5, -2.0, 0.1, c));
  sgtllc::io::writeNodesTxt(p, nodes);
  EXPECT_EQ(slurp(p),
            "# x y z label (SemanticKITTI raw id)\n"
            "0.5 -2 0.1 50\n"
            "1.5 -2 0.1 51\n"
            "2.5 -2 0.1 70\n"
            "3.5 -2 0.1 71\n"
            "4.5 -2 0.1 72\n"
            "5.5 -2 0.1 80\n"
            "6.5 -2 0.1 81\n");
}

TEST_F(NodesIo, EmptyNodeListWritesOnlyTheHeaderAndReadsBackEmpty) {
  const std::string p = path("empty.txt");
  sgtllc::io::writeNodesTxt(p, {});
  EXPECT_EQ(slurp(p), "# x y z label (SemanticKITTI raw id)\n");
  NodeFileStats stats{9, 9, 9};
  EXPECT_TRUE(sgtllc::io::readNodesTxt(p, LabelMap(), &stats).empty());
  EXPECT_EQ(stats.rows, 0u);
  EXPECT_EQ(stats.dropped_known, 0u);
  EXPECT_EQ(stats.unknown, 0u);
  EXPECT_TRUE(sgtllc::io::readNodesTxt(write("zero.txt", ""), LabelMap()).empty());
}

TEST_F(NodesIo, CommentsBlankLinesCrlfAndMixedBlanksAreAccepted) {
  const std::string p = write("mixed.txt",
                              "# my objects\n"
                              "\n"
                              "1 2 3 50\n"
                              "   # an indented comment\n"
                              " \t \n"
                              "\t-1.5e1   +2.25\t0 80\r\n"
                              "#1 1 1 50 (a commented-out row)\n"
                              "4 5 6 81");  // no final newline
  NodeFileStats stats;
  const std::vector<Node> nodes = sgtllc::io::readNodesTxt(p, LabelMap(), &stats);
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_EQ(nodes[0].centre, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(nodes[0].label, sgtllc::kBuilding);
  EXPECT_EQ(nodes[1].centre, Eigen::Vector3d(-15, 2.25, 0));
  EXPECT_EQ(nodes[1].label, sgtllc::kPole);
  EXPECT_EQ(nodes[2].centre, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(nodes[2].label, sgtllc::kTrafficSign);
  EXPECT_EQ(stats.rows, 3u);
  // The stats are optional.
  EXPECT_EQ(sgtllc::io::readNodesTxt(p, LabelMap()).size(), 3u);
}

TEST_F(NodesIo, DroppedAndUnknownIdsAreSkippedAndCountedSeparately) {
  const std::string p = write("ids.txt",
                              "0 0 0 40\n"          // road: known, dropped
                              "1 0 0 0\n"           // unlabeled: known, dropped
                              "2 0 0 12345\n"       // not a SemanticKITTI id
                              "3 0 0 70\n"          // vegetation
                              "4 0 0 458823\n"      // 7 << 16 | 71: instance 7 of trunk (low 16 bits = class)
                              "5 0 0 4294967295\n"  // low half 0xFFFF: unknown
                              "6 0 0 52\n");        // other-structure: known, dropped
  NodeFileStats stats;
  const std::vector<Node> nodes = sgtllc::io::readNodesTxt(p, LabelMap(), &stats);
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_EQ(nodes[0].centre.x(), 3.0);
  EXPECT_EQ(nodes[0].label, sgtllc::kVegetation);
  EXPECT_EQ(nodes[1].centre.x(), 4.0);
  EXPECT_EQ(nodes[1].label, sgtllc::kTrunk);
  EXPECT_EQ(stats.rows, 7u);
  EXPECT_EQ(stats.dropped_known, 3u);
  EXPECT_EQ(stats.unknown, 2u);
}

TEST_F(NodesIo, CustomLabelConfigMapsItsOwnIds) {
  sgtllc::LabelConfig config;
  config.preset = sgtllc::LabelPreset::kCustom;
  config.custom_map = {{7, sgtllc::kPole}, {9, sgtllc::kBuilding}, {3, sgtllc::kDropped}};
  const std::string p = write("custom.txt",
                              "1 1 1 9\n"
                              "2 2 2 7\n"
                              "3 3 3 50\n"   // a SemanticKITTI building id means nothing here
                              "4 4 4 3\n");  // listed, as dropped: known
  NodeFileStats stats;
  const std::vector<Node> nodes = sgtllc::io::readNodesTxt(p, LabelMap(config), &stats);
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_EQ(nodes[0].label, sgtllc::kBuilding);
  EXPECT_EQ(nodes[1].label, sgtllc::kPole);
  EXPECT_EQ(nodes[1].centre, Eigen::Vector3d(2, 2, 2));
  EXPECT_EQ(stats.rows, 4u);
  EXPECT_EQ(stats.dropped_known, 1u);
  EXPECT_EQ(stats.unknown, 1u);

  // The same file with learning ids: 9, 7 and 3 are train ids of dropped classes; 50 is outside 0..19.
  sgtllc::LabelConfig learning;
  learning.preset = sgtllc::LabelPreset::kSemanticKittiLearning;
  EXPECT_TRUE(sgtllc::io::readNodesTxt(p, LabelMap(learning), &stats).empty());
  EXPECT_EQ(stats.dropped_known, 3u);  // 9, 7, 3
  EXPECT_EQ(stats.unknown, 1u);        // 50
}

TEST_F(NodesIo, MalformedRowsAreErrorsWithFileAndLine) {
  struct Case {
    std::string row;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"1 2 3", "expected 4 values (x y z label), found 3"},
      {"1 2 3 50 7", "expected 4 values (x y z label), found 5"},
      {"1 2 3 50 # trailing comment", "expected 4 values (x y z label), found 7"},
      {"a 2 3 50", "x 'a' is not a finite number"},
      {"1 2,5 3 50", "y '2,5' is not a finite number"},
      {"1 2 nan 50", "z 'nan' is not a finite number"},
      {"1 inf 3 50", "y 'inf' is not a finite number"},
      {"1 2 1e999 50", "z '1e999' is not a finite number"},
      {"1 2 3 50.0", "label '50.0' is not an unsigned 32-bit integer id"},
      {"1 2 3 -1", "label '-1' is not an unsigned 32-bit integer id"},
      {"1 2 3 4294967296", "label '4294967296' is not an unsigned 32-bit integer id"},
      {"1 2 3 building", "label 'building' is not an unsigned 32-bit integer id"},
  };
  for (const Case& c : cases) {
    const std::string p = write("bad.txt", "# header\n0 0 0 50\n\n" + c.row + "\n9 9 9 50\n");
    EXPECT_THAT([&] { sgtllc::io::readNodesTxt(p, LabelMap()); },
                ThrowsMessage<Error>(HasSubstr(p + ":4: " + c.message)))
        << c.row;
  }
}

TEST_F(NodesIo, MissingFileOrDirectoryErrorNamesThePath) {
  const std::string missing = path("missing.txt");
  EXPECT_THAT([&] { sgtllc::io::readNodesTxt(missing, LabelMap()); },
              ThrowsMessage<Error>(HasSubstr("cannot open " + missing + ": No such file or directory")));
  EXPECT_THAT([&] { sgtllc::io::readNodesTxt(dir_.string(), LabelMap()); },
              ThrowsMessage<Error>(HasSubstr("cannot open " + dir_.string() + ": is a directory")));
}

TEST_F(NodesIo, WriteErrorsNameTheFileAndCreateNothing) {
  const std::string p = path("out.txt");
  EXPECT_THAT([&] { sgtllc::io::writeNodesTxt(p, {node(0, 0, 0, 1), node(0, 0, 0, 7)}); },
              ThrowsMessage<Error>(AllOf(HasSubstr("cannot write " + p), HasSubstr("node 1 has label 7"))));
  EXPECT_THAT([&] { sgtllc::io::writeNodesTxt(p, {node(0, 0, 0, -1)}); },
              ThrowsMessage<Error>(HasSubstr("node 0 has label -1")));
  EXPECT_THAT([&] { sgtllc::io::writeNodesTxt(p, {node(0, 0, 0, 1), node(0, NAN, 0, 1)}); },
              ThrowsMessage<Error>(AllOf(HasSubstr("cannot write " + p), HasSubstr("node 1 has a non-finite centre"))));
  EXPECT_FALSE(fs::exists(p));
  const std::string q = path("no/such/dir/out.txt");
  EXPECT_THAT([&] { sgtllc::io::writeNodesTxt(q, {node(0, 0, 0, 1)}); },
              ThrowsMessage<Error>(HasSubstr("cannot write " + q + ": No such file or directory")));
}

}  // namespace
