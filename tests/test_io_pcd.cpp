// PCD reading and node export: every encoding and field type through a test-side writer, files PCL itself wrote,
// and the node export read back.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/pcd.h"
#include "test_pcd_support.h"

namespace {

using namespace sgtllc::test;  // the test PCD writer
using sgtllc::Error;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;


void expectCloud(const sgtllc::LabeledCloud& got, const TestCloud& want, size_t x_elem, size_t label_elem) {
  ASSERT_EQ(got.points.size(), want.rows.size());
  ASSERT_EQ(got.labels.size(), want.rows.size());
  for (size_t i = 0; i < want.rows.size(); ++i) {
    const auto& row = want.rows[i];
    const Eigen::Vector3f p(static_cast<float>(row[x_elem]), static_cast<float>(row[x_elem + 1]),
                            static_cast<float>(row[x_elem + 4]));
    ASSERT_EQ(got.points[i], p) << "point " << i;
    ASSERT_EQ(got.labels[i], expectedLabel(row[label_elem])) << "point " << i;
  }
}

class PcdIoRoundTrip : public PcdIo, public ::testing::WithParamInterface<std::tuple<std::string, TestField>> {};

TEST_P(PcdIoRoundTrip, ReadsCoordinatesAndLabelSkippingOtherFields) {
  const auto& [data, label] = GetParam();
  const TestCloud cloud = randomCloud(label, 300, 7);
  const std::string p = write("cloud.pcd", encode(cloud, data));
  const sgtllc::LabeledCloud read = sgtllc::io::readPcd(p, label.name);
  expectCloud(read, cloud, 1, 6);
  // The points-only read skips the label field like the others and gives the same points.
  EXPECT_EQ(sgtllc::io::readPcdPoints(p), read.points);
}

std::string roundTripName(const ::testing::TestParamInfo<PcdIoRoundTrip::ParamType>& info) {
  const TestField& f = std::get<1>(info.param);
  return std::get<0>(info.param) + "_" + f.type + std::to_string(f.size);
}

INSTANTIATE_TEST_SUITE_P(
    DataAndLabelTypes, PcdIoRoundTrip,
    ::testing::Combine(::testing::Values("ascii", "binary", "binary_compressed"),
                       ::testing::Values(TestField{"label", 'U', 1, 1}, TestField{"label", 'U', 2, 1},
                                         TestField{"label", 'U', 4, 1}, TestField{"label", 'I', 1, 1},
                                         TestField{"label", 'I', 2, 1}, TestField{"label", 'I', 4, 1},
                                         TestField{"label", 'F', 4, 1}, TestField{"label", 'F', 8, 1})),
    roundTripName);

TEST_F(PcdIo, PointsOnlyReadsAFileWithoutALabelField) {
  // A raw scan as most drivers write it (x y z intensity): readPcd needs the label field and says so, readPcdPoints
  // reads it in every encoding; a missing coordinate is still an error naming the file.
  TestCloud c;
  c.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"intensity", 'F', 4, 1}};
  c.rows = {{1.5, -2, 3, 0.2}, {4, 5.25, -6, 0.9}, {-7, 8, 9.125, 0.5}};
  const std::vector<Eigen::Vector3f> want = {{1.5f, -2, 3}, {4, 5.25f, -6}, {-7, 8, 9.125f}};
  for (const std::string data : {"ascii", "binary", "binary_compressed"}) {
    const std::string p = write("raw_" + data + ".pcd", encode(c, data));
    EXPECT_EQ(sgtllc::io::readPcdPoints(p), want) << data;
    EXPECT_THAT([&] { sgtllc::io::readPcd(p); },
                ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("no field 'label'")))) << data;
  }
  TestCloud flat;
  flat.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"intensity", 'F', 4, 1}};
  flat.rows = {{1, 2, 3}};
  const std::string p = write("flat.pcd", encode(flat, "binary"));
  EXPECT_THAT([&] { sgtllc::io::readPcdPoints(p); }, ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("'z'"))));
  EXPECT_THAT([&] { sgtllc::io::readPcd(p, ""); }, ThrowsMessage<Error>(HasSubstr("no label field name")));
}

TEST_F(PcdIo, NegativeIntegerLabelWrapsAndFloatLabelRounds) {
  TestCloud c;
  c.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"i", 'I', 2, 1}, {"f", 'F', 4, 1}};
  c.rows = {{1, 2, 3, -1, 49.6}, {4, 5, 6, 70, 70.4}};
  const std::string p = write("c.pcd", binaryPcd(c));
  EXPECT_EQ(sgtllc::io::readPcd(p, "i").labels, (std::vector<uint32_t>{0xFFFFFFFFu, 70}));
  EXPECT_EQ(sgtllc::io::readPcd(p, "f").labels, (std::vector<uint32_t>{50, 70}));
}

TEST_F(PcdIo, DoubleCoordinatesAreNarrowedToFloat) {
  TestCloud c;
  c.fields = {{"x", 'F', 8, 1}, {"y", 'F', 8, 1}, {"z", 'F', 8, 1}, {"label", 'U', 4, 1}};
  c.rows = {{0.1, -1e5 / 3, 123.456789012345, 50}, {1e-9, 2, 3, 81}};
  for (const char* data : {"ascii", "binary", "binary_compressed"}) {
    const auto got = sgtllc::io::readPcd(write(std::string(data) + ".pcd", encode(c, data)));
    ASSERT_EQ(got.points.size(), 2u) << data;
    EXPECT_EQ(got.points[0], Eigen::Vector3f(0.1f, static_cast<float>(-1e5 / 3), 123.456789012345f)) << data;
    EXPECT_EQ(got.labels, (std::vector<uint32_t>{50, 81})) << data;
  }
}

TEST_F(PcdIo, NanCoordinatesAreKept) {
  TestCloud c;
  c.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"label", 'U', 4, 1}};
  c.rows = {{std::nan(""), 1, 2, 10}};
  for (const char* data : {"ascii", "binary"}) {
    const auto got = sgtllc::io::readPcd(write(std::string(data) + ".pcd", encode(c, data)));
    ASSERT_EQ(got.points.size(), 1u);
    EXPECT_TRUE(std::isnan(got.points[0].x())) << data;
  }
}

TEST_F(PcdIo, OrganisedCloudAndVersion06HeaderWithoutViewpointOrCount) {
  TestCloud c;  // without COUNT every field has one element
  c.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"semantic", 'U', 2, 1}, {"rgb", 'F', 4, 1}};
  c.width = 5;
  c.height = 4;
  for (int i = 0; i < 20; ++i) c.rows.push_back({i * 0.5, -i * 1.0, 2.0, 40.0 + i, 1e-3});
  const std::string text = header(c, "binary", "0.6", false);
  ASSERT_EQ(text.find("VIEWPOINT"), std::string::npos);
  ASSERT_EQ(text.find("COUNT"), std::string::npos);
  const std::string body = binaryPcd(c).substr(header(c, "binary").size());
  const auto got = sgtllc::io::readPcd(write("organised.pcd", text + body), "semantic");
  ASSERT_EQ(got.points.size(), 20u);
  for (size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(got.points[i], Eigen::Vector3f(i * 0.5f, -1.0f * i, 2.f));
    EXPECT_EQ(got.labels[i], 40u + i);
  }
}

TEST_F(PcdIo, EmptyCloudsInEveryEncoding) {
  TestCloud c;
  c.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"label", 'U', 4, 1}};
  for (const char* data : {"ascii", "binary", "binary_compressed"}) {
    const auto got = sgtllc::io::readPcd(write(std::string(data) + ".pcd", encode(c, data)));
    EXPECT_TRUE(got.points.empty()) << data;
    EXPECT_TRUE(got.labels.empty()) << data;
  }
}

// ------------------------------------------------------------------------------------------------------------------
// Node export

TEST_F(PcdIo, WriteNodesPcdIoRoundTripsThroughReadPcd) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-100, 100);
  std::vector<sgtllc::Node> nodes(25);
  for (size_t i = 0; i < nodes.size(); ++i) {
    nodes[i].centre = Eigen::Vector3d(coord(rng), coord(rng), coord(rng));
    nodes[i].label = static_cast<int>(i % sgtllc::kNumPaperClasses);
  }
  const std::string p = (dir_ / "nodes.pcd").string();
  sgtllc::io::writeNodesPcd(p, nodes);
  const auto cloud = sgtllc::io::readPcd(p);
  ASSERT_EQ(cloud.points.size(), nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_EQ(cloud.points[i], nodes[i].centre.cast<float>());
    EXPECT_EQ(cloud.labels[i], static_cast<uint32_t>(nodes[i].label));
  }
  std::ifstream in(p);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("\nFIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 25\n"));
  EXPECT_THAT(text, HasSubstr("\nPOINTS 25\nDATA ascii\n"));
}

TEST_F(PcdIo, WriteNodesPcdErrors) {
  std::vector<sgtllc::Node> nodes(2);
  nodes[1].label = 7;
  const std::string p = (dir_ / "nodes.pcd").string();
  EXPECT_THAT([&] { sgtllc::io::writeNodesPcd(p, nodes); },
              ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("node 1 has label 7"))));
  const std::string q = (dir_ / "no_dir" / "nodes.pcd").string();
  EXPECT_THAT([&] { sgtllc::io::writeNodesPcd(q, {}); },
              ThrowsMessage<Error>(HasSubstr("cannot write " + q + ": No such file or directory")));
}

}  // namespace

// ------------------------------------------------------------------------------------------------------------------
// Files written by PCL itself (data/pcd: every 100th point of KITTI scan 000052, re-encoded by PCL 1.13's writer).

namespace {

/// Every 100th point and label word of the bundled scan 000052, read straight from the KITTI files.
std::pair<std::vector<Eigen::Vector3f>, std::vector<uint32_t>> everyHundredthOf52() {
  const std::string dir = std::string(SGTLLC_DATA_DIR) + "/kitti/00/";
  std::ifstream bin(dir + "velodyne/000052.bin", std::ios::binary);
  std::ifstream lab(dir + "labels/000052.label", std::ios::binary);
  std::vector<Eigen::Vector3f> points;
  std::vector<uint32_t> labels;
  float xyzi[4];
  uint32_t label = 0;
  for (size_t i = 0; bin.read(reinterpret_cast<char*>(xyzi), sizeof xyzi) &&
                     lab.read(reinterpret_cast<char*>(&label), sizeof label);
       ++i) {
    if (i % 100 != 0) continue;
    points.emplace_back(xyzi[0], xyzi[1], xyzi[2]);
    labels.push_back(label);
  }
  return {points, labels};
}

TEST(PcdWrittenByPcl, EveryEncodingReadsTheScanPoints) {
  const auto [points, labels] = everyHundredthOf52();
  ASSERT_EQ(points.size(), 1208u);
  for (const char* kind : {"binary", "binary_compressed", "ascii"}) {
    SCOPED_TRACE(kind);
    const std::string path = std::string(SGTLLC_DATA_DIR) + "/pcd/000052_every100th_" + kind + ".pcd";
    const sgtllc::LabeledCloud cloud = sgtllc::io::readPcd(path);
    ASSERT_EQ(cloud.points.size(), points.size());
    EXPECT_EQ(cloud.labels, labels);
    // PCL writes binary floats bit for bit, ASCII floats with 7 significant digits (≤ 5e-6 m at these ranges).
    const float tolerance = std::string(kind) == "ascii" ? 5e-5f : 0.0f;
    float worst = 0.0f;
    for (size_t i = 0; i < points.size(); ++i) {
      worst = std::max(worst, (cloud.points[i] - points[i]).cwiseAbs().maxCoeff());
    }
    EXPECT_LE(worst, tolerance);
  }
}

}  // namespace
