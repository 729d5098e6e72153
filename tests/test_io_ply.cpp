// Graph PLY export: the file is parsed back line by line and checked against the PLY header grammar.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/ply.h"
#include "test_io_support.h"

namespace {

namespace fs = std::filesystem;
using sgtllc::Error;
using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class PlyIo : public sgtllc::test::TempDirTest {};

std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<double> numbers(const std::string& line) {
  std::istringstream in(line);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

sgtllc::Node node(double x, double y, double z, int label) {
  sgtllc::Node n;
  n.centre = Eigen::Vector3d(x, y, z);
  n.label = label;
  return n;
}

TEST(PlyIoClassColor, IsSemanticKittiPaletteInRgbAndDistinct) {
  // semantic-kitti.yaml color_map lists BGR: building 50 = [0, 200, 255], pole 80 = [150, 240, 255].
  EXPECT_EQ(sgtllc::io::classColor(sgtllc::kBuilding), (std::array<uint8_t, 3>{255, 200, 0}));
  EXPECT_EQ(sgtllc::io::classColor(sgtllc::kVegetation), (std::array<uint8_t, 3>{0, 175, 0}));
  EXPECT_EQ(sgtllc::io::classColor(sgtllc::kPole), (std::array<uint8_t, 3>{255, 240, 150}));
  EXPECT_EQ(sgtllc::io::classColor(sgtllc::kTrafficSign), (std::array<uint8_t, 3>{255, 0, 0}));
  std::set<std::array<uint8_t, 3>> distinct;
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) distinct.insert(sgtllc::io::classColor(c));
  EXPECT_EQ(distinct.size(), static_cast<size_t>(sgtllc::kNumPaperClasses));
  EXPECT_THROW(sgtllc::io::classColor(-1), Error);
  EXPECT_THROW(sgtllc::io::classColor(sgtllc::kNumPaperClasses), Error);
}

TEST_F(PlyIo, WritesHeaderVerticesAndEdgesThatParseBack) {
  const std::vector<sgtllc::Node> nodes = {node(1.5, -2.25, 0.125, sgtllc::kBuilding),
                                           node(10, 20, 30, sgtllc::kTrunk),
                                           node(-0.1, 0, 1e3, sgtllc::kTrafficSign)};
  sgtllc::io::PlyEdge grey;  // keeps the default colour
  grey.a = 2;
  grey.b = 0;
  const std::vector<sgtllc::io::PlyEdge> edges = {{0, 1, {1, 2, 3}}, grey};
  const std::string p = path("graph.ply");
  sgtllc::io::writeGraphPly(p, nodes, edges);
  const std::vector<std::string> text = lines(p);
  ASSERT_EQ(text.size(), 18u + nodes.size() + edges.size());
  EXPECT_EQ(text[0], "ply");
  EXPECT_EQ(text[1], "format ascii 1.0");
  EXPECT_THAT(text[2], ::testing::StartsWith("comment "));
  EXPECT_THAT(std::vector<std::string>(text.begin() + 3, text.begin() + 18),
              ElementsAre("element vertex 3", "property float x", "property float y", "property float z",
                          "property uchar red", "property uchar green", "property uchar blue", "property uchar label",
                          "element edge 2", "property int vertex1", "property int vertex2", "property uchar red",
                          "property uchar green", "property uchar blue", "end_header"));
  EXPECT_THAT(numbers(text[18]), ElementsAre(1.5, -2.25, 0.125, 255, 200, 0, 0));
  EXPECT_THAT(numbers(text[19]), ElementsAre(10, 20, 30, 135, 60, 0, 3));
  const std::vector<double> v2 = numbers(text[20]);
  ASSERT_EQ(v2.size(), 7u);
  EXPECT_EQ(static_cast<float>(v2[0]), -0.1f);  // written as float, exactly round-tripping
  EXPECT_EQ(v2[6], 6);
  EXPECT_THAT(numbers(text[21]), ElementsAre(0, 1, 1, 2, 3));
  EXPECT_THAT(numbers(text[22]), ElementsAre(2, 0, 128, 128, 128));  // PlyEdge's default grey
}

TEST_F(PlyIo, EmptyGraphIsValid) {
  const std::string p = path("empty.ply");
  sgtllc::io::writeGraphPly(p, {}, {});
  const std::vector<std::string> text = lines(p);
  ASSERT_EQ(text.size(), 18u);
  EXPECT_EQ(text[3], "element vertex 0");
  EXPECT_EQ(text[11], "element edge 0");
  EXPECT_EQ(text.back(), "end_header");
}

TEST_F(PlyIo, InvalidEdgeOrLabelIsAnErrorNamingTheFile) {
  const std::vector<sgtllc::Node> nodes = {node(0, 0, 0, 0), node(1, 1, 1, 1)};
  const std::string p = path("bad.ply");
  EXPECT_THAT([&] { sgtllc::io::writeGraphPly(p, nodes, {{0, 1, {}}, {1, 2, {}}}); },
              ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("edge 1 joins vertices 1 and 2 but there are 2"))));
  EXPECT_THAT([&] { sgtllc::io::writeGraphPly(p, nodes, {{-1, 0, {}}}); },
              ThrowsMessage<Error>(HasSubstr("edge 0 joins vertices -1 and 0")));
  EXPECT_THAT([&] { sgtllc::io::writeGraphPly(p, {node(0, 0, 0, 9)}, {}); },
              ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("node 0 has label 9"))));
  EXPECT_FALSE(fs::exists(p));  // validation happens before the file is created
}

TEST_F(PlyIo, UnwritablePathIsAnError) {
  const std::string p = path("missing_dir/graph.ply");
  EXPECT_THAT([&] { sgtllc::io::writeGraphPly(p, {}, {}); },
              ThrowsMessage<Error>(HasSubstr("cannot write " + p + ": No such file or directory")));
}

}  // namespace
