// One-byte label files and the nuScenes preset on the real nuScenes-lidarseg frames in data/nuscenes (data/README.md):
// the counts below were computed independently with numpy (np.fromfile(PATH, np.uint8), np.unique).
#include <array>
#include <cstring>
#include <filesystem>
#include <map>

#include <Eigen/LU>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/detector.h"
#include "sgtllc/io/config_yaml.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/labels.h"
#include "sgtllc/map/map.h"
#include "test_io_support.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using sgtllc::Error;
using sgtllc::LabelFormat;
using ::testing::AllOf;
using ::testing::HasSubstr;

const fs::path kNuScenes = fs::path(SGTLLC_DATA_DIR) / "nuscenes";

std::string scan(const std::string& scene, const std::string& frame) {
  return (kNuScenes / scene / "velodyne" / (frame + ".bin")).string();
}
std::string labels(const std::string& scene, const std::string& frame) {
  return (kNuScenes / scene / "labels" / (frame + ".label")).string();
}

sgtllc::Config nuScenesConfig() {
  sgtllc::Config c;
  c.labels.preset = sgtllc::LabelPreset::kNuScenes;
  return c;
}

std::map<uint32_t, size_t> histogram(const std::vector<uint32_t>& ids) {
  std::map<uint32_t, size_t> h;
  for (uint32_t id : ids) ++h[id];
  return h;
}

TEST(NuScenesLabels, RealOneByteFileHasOneIdAPointAndTheNumpyHistogram) {
  const sgtllc::LabeledCloud cloud = sgtllc::io::readLabeledScan(scan("0001", "000000"), labels("0001", "000000"));
  ASSERT_EQ(cloud.points.size(), 34720u);  // 555,520 bytes / 16
  ASSERT_EQ(cloud.labels.size(), 34720u);  // 34,720 bytes: one a point
  const std::map<uint32_t, size_t> want = {{0, 3},      {2, 3},     {4, 17},    {12, 9},    {17, 123},
                                           {23, 232},   {24, 13624}, {25, 3},   {26, 853},  {27, 3960},
                                           {28, 2792},  {30, 2934}, {31, 9866}, {32, 301}};
  EXPECT_EQ(histogram(cloud.labels), want);
  // The same file read with the format given, and through a sequence folder.
  EXPECT_EQ(sgtllc::io::readLabelFile(labels("0001", "000000"), 34720, LabelFormat::kUint8), cloud.labels);
  const sgtllc::io::SequenceDir seq((kNuScenes / "0001").string());
  ASSERT_EQ(seq.size(), 2u);
  EXPECT_EQ(seq.load(0).labels, cloud.labels);
  EXPECT_EQ(seq.load(1).labels.size(), 34752u);
}

TEST(NuScenesLabels, PresetKeepsManmadeBarrierVegetationTerrain) {
  const sgtllc::LabelMap map(nuScenesConfig().labels);
  // Scene 0006 frame 0 has every kept class: 885 manmade, 2512 barrier, 6809 vegetation, 9318 terrain (numpy).
  const sgtllc::LabeledCloud cloud = sgtllc::io::readLabeledScan(scan("0006", "000000"), labels("0006", "000000"));
  ASSERT_EQ(cloud.labels.size(), 34720u);
  std::array<size_t, sgtllc::kNumPaperClasses> per_class{};
  size_t dropped = 0;
  for (uint32_t id : cloud.labels) {
    ASSERT_TRUE(map.isKnown(id)) << id;  // ids 0..39 only, 39 a moving pedestrian
    const int c = map.classOf(id);
    c == sgtllc::kDropped ? ++dropped : ++per_class[static_cast<size_t>(c)];
  }
  const std::array<size_t, sgtllc::kNumPaperClasses> want = {885, 2512, 6809, 0, 9318, 0, 0};
  EXPECT_EQ(per_class, want);
  EXPECT_EQ(dropped, 15196u);
}

TEST(NuScenesLabels, RealFramesGiveNodesOfThePresentClassesOnly) {
  // Trunk, pole and traffic-sign never occur: the graph and descriptors must work with those classes absent.
  const sgtllc::Config config = nuScenesConfig();
  const sgtllc::LabeledCloud a = sgtllc::io::readLabeledScan(scan("0006", "000000"), labels("0006", "000000"));
  const Eigen::Matrix4d T = sgtllc::test::rigid(35.0, 0.0, 0.0, Eigen::Vector3d(1.5, -2.0, 0.1));
  const sgtllc::PairResult r = sgtllc::comparePair(sgtllc::test::transformed(a, T.inverse()), a, config);
  ASSERT_GE(r.query_nodes.size(), 5u);
  std::array<int, sgtllc::kNumPaperClasses> nodes{};
  for (const sgtllc::Node& n : r.match_nodes) ++nodes[static_cast<size_t>(n.label)];
  EXPECT_GT(nodes[sgtllc::kFence], 0);
  EXPECT_GT(nodes[sgtllc::kVegetation], 0);
  EXPECT_EQ(nodes[sgtllc::kTrunk] + nodes[sgtllc::kPole] + nodes[sgtllc::kTrafficSign], 0);
  ASSERT_TRUE(r.is_loop);
  // The query is the scan moved by T⁻¹, so the match-from-query pose is T.
  const Eigen::Matrix4d err = T.inverse() * r.match.T_match_query;
  EXPECT_LT((err.topRightCorner<3, 1>().norm()), 0.05);
}

TEST(NuScenesLabels, BundledConfigAndYamlKeys) {
  const sgtllc::Config c = sgtllc::io::loadConfig(std::string(SGTLLC_DATA_DIR) + "/../configs/nuscenes.yaml");
  EXPECT_EQ(c.labels.preset, sgtllc::LabelPreset::kNuScenes);
  EXPECT_EQ(c.labels.format, LabelFormat::kUint8);
  EXPECT_EQ(c.labeller.source, sgtllc::LabelSource::kHybrid);  // nuScenes has no pole or trunk class
  EXPECT_EQ(sgtllc::io::parseConfig("labels:\n  format: uint32\n").labels.format, LabelFormat::kUint32);
  EXPECT_EQ(sgtllc::Config().labels.format, LabelFormat::kAuto);
  // Printed and read back.
  const std::string text = sgtllc::io::configToYaml(c);
  EXPECT_NE(text.find("preset: nuscenes"), std::string::npos);
  EXPECT_NE(text.find("format: uint8"), std::string::npos);
  EXPECT_EQ(sgtllc::io::parseConfig(text).labels.format, LabelFormat::kUint8);
  EXPECT_THAT([] { sgtllc::io::parseConfig("labels:\n  format: uint16\n"); },
              ::testing::ThrowsMessage<Error>(HasSubstr("expected one of auto | uint32 | uint8")));
}

TEST(NuScenesLabels, LabelFormatIsNotAMapField) {
  // How label files hold the ids changes no node: maps built before the key existed stay loadable.
  sgtllc::Config uint8 = nuScenesConfig();
  uint8.labels.format = LabelFormat::kUint8;
  EXPECT_EQ(sgtllc::map::mapConfig(uint8), sgtllc::map::mapConfig(nuScenesConfig()));
  for (const auto& [key, value] : sgtllc::map::mapConfig(uint8)) EXPECT_NE(key, "labels.format");
  EXPECT_NE(sgtllc::map::mapConfig(nuScenesConfig()), sgtllc::map::mapConfig(sgtllc::Config()));  // the preset is
}

class OneByteLabels : public sgtllc::test::TempDirTest {
 protected:
  std::string points(const std::string& name, size_t n) const { return write(name, std::string(16 * n, '\0')); }
};

TEST_F(OneByteLabels, AutoTellsTheFormatsApartBySize) {
  const std::string b = points("s.bin", 3);
  // uint32: 12 bytes; ids above 255 and instance bits survive.
  const uint32_t words[3] = {50, (7u << 16) | 70u, 300};
  std::string bytes(12, '\0');
  std::memcpy(bytes.data(), words, 12);  // the test host is little-endian, like the format
  EXPECT_EQ(sgtllc::io::readLabeledScan(b, write("w.label", bytes)).labels,
            (std::vector<uint32_t>{50, (7u << 16) | 70u, 300}));
  // uint8: 3 bytes; a byte above 127 is an id, not a negative number.
  const std::string l8 = write("b.label", std::string("\x1c\xff\x09", 3));
  EXPECT_EQ(sgtllc::io::readLabeledScan(b, l8).labels, (std::vector<uint32_t>{28, 255, 9}));
  EXPECT_EQ(sgtllc::io::readLabeledScan(b, l8, LabelFormat::kUint8).labels, (std::vector<uint32_t>{28, 255, 9}));
  // An empty scan has an empty label file in either format.
  EXPECT_TRUE(sgtllc::io::readLabeledScan(points("e.bin", 0), write("e.label", "")).labels.empty());
}

TEST_F(OneByteLabels, WrongSizeNamesTheFileBothSizesAndThePointCount) {
  const std::string b = points("s.bin", 5);
  const std::string l = write("bad.label", std::string(17, '\0'));
  EXPECT_THAT([&] { sgtllc::io::readLabeledScan(b, l); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(b + " has 5 points"), HasSubstr(l + " has 17 bytes"),
                                                    HasSubstr("neither 20 (uint32"), HasSubstr("nor 5 (uint8"))));
  EXPECT_THAT([&] { sgtllc::io::readLabelFile(l, 5); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr("the scan has 5 points"), HasSubstr(l))));
  // A format set in the config accepts only its own size.
  const std::string l8 = write("five.label", std::string(5, '\x1c'));
  EXPECT_THAT([&] { sgtllc::io::readLabeledScan(b, l8, LabelFormat::kUint32); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(l8 + " has 5 bytes"), HasSubstr("not 20 (uint32"))));
  const std::string l32 = write("twenty.label", std::string(20, '\0'));
  EXPECT_THAT([&] { sgtllc::io::readLabeledScan(b, l32, LabelFormat::kUint8); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(l32 + " has 20 bytes"), HasSubstr("not 5 (uint8"))));
  // The real nuScenes file is not a uint32 file.
  EXPECT_THAT([&] { sgtllc::io::readLabeledScan(scan("0001", "000000"), labels("0001", "000000"), LabelFormat::kUint32); },
              ::testing::ThrowsMessage<Error>(HasSubstr("has 34720 bytes, not 138880 (uint32")));
}

TEST_F(OneByteLabels, SequenceFolderReadsTheConfiguredFormat) {
  fs::create_directories(dir_ / "seq" / "velodyne");
  fs::create_directories(dir_ / "seq" / "labels");
  write("seq/velodyne/000000.bin", std::string(16 * 4, '\0'));
  write("seq/labels/000000.label", std::string(4, '\x1e'));
  const std::string seq = (dir_ / "seq").string();
  EXPECT_EQ(sgtllc::io::SequenceDir(seq).load(0).labels, (std::vector<uint32_t>(4, 30)));
  const sgtllc::io::SequenceDir uint32(seq, sgtllc::io::SequenceLabels{true, "", LabelFormat::kUint32});
  EXPECT_THAT([&] { uint32.load(0); }, ::testing::ThrowsMessage<Error>(HasSubstr("not 16 (uint32")));
}

}  // namespace
