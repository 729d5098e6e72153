// KITTI / SemanticKITTI readers, checked against the real sequence-00 samples in data/kitti/00 (data/README.md).
#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <Eigen/LU>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/kitti.h"
#include "test_io_support.h"

namespace {

namespace fs = std::filesystem;
using sgtllc::Error;
using ::testing::AllOf;
using ::testing::HasSubstr;

const fs::path kSeq00 = fs::path(SGTLLC_DATA_DIR) / "kitti" / "00";

std::string bin(const std::string& name) { return (kSeq00 / "velodyne" / (name + ".bin")).string(); }
std::string label(const std::string& name) { return (kSeq00 / "labels" / (name + ".label")).string(); }

class KittiIo : public sgtllc::test::TempDirTest {
 protected:
  template <typename T>
  std::string writeWords(const std::string& name, const std::vector<T>& words) const {
    std::string bytes(words.size() * sizeof(T), '\0');
    std::memcpy(bytes.data(), words.data(), bytes.size());  // the test host is little-endian, like the format
    return write(name, bytes);
  }
};

/// Reads @p count float32 words at byte @p offset independently of the library.
std::vector<float> rawFloats(const std::string& path, std::streamoff offset, size_t count) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(offset);
  std::vector<float> v(count);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(count * sizeof(float)));
  EXPECT_TRUE(in.good());
  return v;
}

TEST_F(KittiIo, RealScanHasReadmeCountAndFirstAndLastPointBytes) {
  std::vector<float> intensity;
  const auto points = sgtllc::io::readKittiBin(bin("000052"), &intensity);
  ASSERT_EQ(points.size(), 120796u);  // 1932736 bytes / 16
  ASSERT_EQ(intensity.size(), points.size());
  const std::vector<float> first = rawFloats(bin("000052"), 0, 4);
  EXPECT_EQ(points[0].x(), first[0]);
  EXPECT_EQ(points[0].y(), first[1]);
  EXPECT_EQ(points[0].z(), first[2]);
  EXPECT_EQ(intensity[0], first[3]);
  EXPECT_NEAR(points[0].x(), 75.24007f, 1e-4f);  // as printed by `od -t f4`
  const std::vector<float> last = rawFloats(bin("000052"), 16 * 120795, 4);
  EXPECT_EQ(points.back(), Eigen::Vector3f(last[0], last[1], last[2]));
  EXPECT_EQ(intensity.back(), last[3]);
}

TEST_F(KittiIo, RealLabelsHaveReadmeCountsPerStableClass) {
  const auto labels = sgtllc::io::readLabelFile(label("000052"));
  ASSERT_EQ(labels.size(), 120796u);
  std::map<uint32_t, int> per_id;
  for (uint32_t l : labels) ++per_id[l & 0xFFFFu];
  // data/README.md "Verification done": building/fence/vegetation/trunk/terrain/pole/sign of scan 52.
  EXPECT_EQ(per_id[50], 43592);
  EXPECT_EQ(per_id[51], 898);
  EXPECT_EQ(per_id[70], 9950);
  EXPECT_EQ(per_id[71], 2682);
  EXPECT_EQ(per_id[72], 0);
  EXPECT_EQ(per_id[80], 197);
  EXPECT_EQ(per_id[81], 154);
}

TEST_F(KittiIo, ReadLabeledScanPairsTheRealFiles) {
  const sgtllc::LabeledCloud cloud = sgtllc::io::readLabeledScan(bin("004501"), label("004501"));
  EXPECT_EQ(cloud.points.size(), 123013u);
  EXPECT_EQ(cloud.labels.size(), 123013u);
}

TEST_F(KittiIo, SyntheticValuesIncludingNanAreKeptExactly) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string p = writeWords<float>("s.bin", {1.5f, -2.25f, 3e-8f, 0.5f, nan, 7.f, -0.f, 0.99f});
  std::vector<float> intensity;
  const auto points = sgtllc::io::readKittiBin(p, &intensity);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], Eigen::Vector3f(1.5f, -2.25f, 3e-8f));
  EXPECT_TRUE(std::isnan(points[1].x()));
  EXPECT_EQ(points[1].y(), 7.f);
  EXPECT_EQ(intensity, (std::vector<float>{0.5f, 0.99f}));
}

TEST_F(KittiIo, EmptyFilesAreEmptyScans) {
  EXPECT_TRUE(sgtllc::io::readKittiBin(write("e.bin", "")).empty());
  EXPECT_TRUE(sgtllc::io::readLabelFile(write("e.label", "")).empty());
}

TEST_F(KittiIo, BinSizeNotMultipleOf16IsAnError) {
  const std::string p = write("bad.bin", std::string(17, '\0'));
  EXPECT_THAT([&] { sgtllc::io::readKittiBin(p); },
              ::testing::ThrowsMessage<Error>(
                  HasSubstr(p + ": size 17 bytes is not a multiple of 16 (x y z intensity float32)")));
}

TEST_F(KittiIo, LabelSizeNotMultipleOf4IsAnError) {
  const std::string p = write("bad.label", std::string(17, '\0'));
  EXPECT_THAT([&] { sgtllc::io::readLabelFile(p); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("size 17 bytes is not a multiple of 4"))));
}

TEST_F(KittiIo, MissingFileErrorNamesThePath) {
  const std::string p = (dir_ / "nope.bin").string();
  EXPECT_THAT([&] { sgtllc::io::readKittiBin(p); },
              ::testing::ThrowsMessage<Error>(HasSubstr("cannot open " + p + ": No such file or directory")));
  EXPECT_THAT([&] { sgtllc::io::readKittiPoses(p); }, ::testing::ThrowsMessage<Error>(HasSubstr(p)));
  EXPECT_THAT([&] { sgtllc::io::readKittiCalibTr(p); }, ::testing::ThrowsMessage<Error>(HasSubstr(p)));
  EXPECT_THAT([&] { sgtllc::io::readKittiBin(dir_.string()); },
              ::testing::ThrowsMessage<Error>(HasSubstr("is a directory")));
}

TEST_F(KittiIo, CountMismatchNamesBothFilesAndCounts) {
  const std::string b = writeWords<float>("m.bin", std::vector<float>(12, 1.f));  // 3 points
  const std::string l = writeWords<uint32_t>("m.label", {50, 70});                // 2 labels
  EXPECT_THAT([&] { sgtllc::io::readLabeledScan(b, l); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(b + " has 3 points"), HasSubstr(l + " has 8 bytes"))));
}

TEST_F(KittiIo, DefaultLabelPathPrefersSemanticKittiLayout) {
  const fs::path chosen = sgtllc::io::defaultLabelPath(bin("000052"));
  EXPECT_TRUE(fs::equivalent(chosen, label("000052")));
  // Without a ../labels directory the label sits next to the scan.
  EXPECT_EQ(sgtllc::io::defaultLabelPath((dir_ / "velodyne" / "x.bin").string()),
            (dir_ / "velodyne" / "x.label").string());
  EXPECT_EQ(sgtllc::io::defaultLabelPath((dir_ / "scan.bin").string()), (dir_ / "scan.label").string());
}

TEST_F(KittiIo, RealPosesHave4541FramesAndLineTwoValues) {
  const auto poses = sgtllc::io::readKittiPoses((kSeq00 / "poses.txt").string());
  ASSERT_EQ(poses.size(), 4541u);
  EXPECT_TRUE(poses[0].isApprox(Eigen::Matrix4d::Identity(), 1e-6));
  // Line 2: 9.999978e-01 5.272628e-04 -2.066935e-03 -4.690294e-02 ... 8.586941e-01
  EXPECT_DOUBLE_EQ(poses[1](0, 0), 9.999978e-01);
  EXPECT_DOUBLE_EQ(poses[1](0, 1), 5.272628e-04);
  EXPECT_DOUBLE_EQ(poses[1](0, 3), -4.690294e-02);
  EXPECT_DOUBLE_EQ(poses[1](2, 3), 8.586941e-01);
  EXPECT_EQ(poses[1].row(3), Eigen::RowVector4d(0, 0, 0, 1));
}

TEST_F(KittiIo, PosesAcceptPlainAndExponentNumbersAndTrailingBlankLines) {
  const std::string p = write("p.txt",
                              "1 0 0 5 0 1 0 -2.5 0 0 1 0\n"
                              "1.000000e+00 0 0 1.5e+01 0 1 0 0\t0 0 1.0 +3\r\n"
                              "\n  \n");
  const auto poses = sgtllc::io::readKittiPoses(p);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0](0, 3), 5.0);
  EXPECT_EQ(poses[0](1, 3), -2.5);
  EXPECT_EQ(poses[1](0, 3), 15.0);
  EXPECT_EQ(poses[1](2, 3), 3.0);
}

TEST_F(KittiIo, MalformedPoseLinesNameFileAndLine) {
  const std::string row = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  const std::string short_line = write("short.txt", row + "1 0 0 0 0 1 0 0 0 0 1\n");
  EXPECT_THAT([&] { sgtllc::io::readKittiPoses(short_line); },
              ::testing::ThrowsMessage<Error>(HasSubstr(short_line + ":2: expected 12 numbers")));
  const std::string word = write("word.txt", row + row + "1 0 0 x 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT([&] { sgtllc::io::readKittiPoses(word); },
              ::testing::ThrowsMessage<Error>(HasSubstr(word + ":3: 'x' is not a finite number")));
  const std::string gap = write("gap.txt", row + "\n" + row);
  EXPECT_THAT([&] { sgtllc::io::readKittiPoses(gap); }, ::testing::ThrowsMessage<Error>(HasSubstr(gap + ":3:")));
}

TEST_F(KittiIo, RealCalibTrMatchesTheTrLine) {
  const Eigen::Matrix4d Tr = sgtllc::io::readKittiCalibTr((kSeq00 / "calib.txt").string());
  EXPECT_DOUBLE_EQ(Tr(0, 0), 4.276802385584e-04);
  EXPECT_DOUBLE_EQ(Tr(0, 1), -9.999672484946e-01);
  EXPECT_DOUBLE_EQ(Tr(1, 3), -5.403984729748e-02);
  EXPECT_DOUBLE_EQ(Tr(2, 3), -2.921968648686e-01);
  EXPECT_EQ(Tr.row(3), Eigen::RowVector4d(0, 0, 0, 1));
}

TEST_F(KittiIo, CalibWithoutTrIsAnError) {
  const std::string p = write("calib.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT([&] { sgtllc::io::readKittiCalibTr(p); },
              ::testing::ThrowsMessage<Error>(AllOf(HasSubstr(p), HasSubstr("no 'Tr:' line"))));
}

struct DemoPair {
  std::string a, b;
  double distance = 0;
  Eigen::Matrix4d T_a_b = Eigen::Matrix4d::Identity();
};

/// Parses data/kitti/00/demo_pairs.txt: `a b is_loop dist_lidar_m` then T_a_b as 12 row-major numbers.
std::vector<DemoPair> demoPairs() {
  std::ifstream in(kSeq00 / "demo_pairs.txt");
  std::vector<DemoPair> pairs;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    DemoPair p;
    int is_loop = 0;
    fields >> p.a >> p.b >> is_loop >> p.distance;
    for (int k = 0; k < 12; ++k) fields >> p.T_a_b(k / 4, k % 4);
    EXPECT_FALSE(fields.fail()) << line;
    pairs.push_back(p);
  }
  return pairs;
}

TEST_F(KittiIo, LidarPosesReproduceTheDemoPairGroundTruth) {
  const auto cam = sgtllc::io::readKittiPoses((kSeq00 / "poses.txt").string());
  const auto lidar = sgtllc::io::lidarPoses(cam, sgtllc::io::readKittiCalibTr((kSeq00 / "calib.txt").string()));
  ASSERT_EQ(lidar.size(), cam.size());
  const std::vector<DemoPair> pairs = demoPairs();
  ASSERT_EQ(pairs.size(), 2u);  // 52/4501 (loop) and 88/850 (non-loop)
  for (const DemoPair& p : pairs) {
    SCOPED_TRACE(p.a + " " + p.b);
    const Eigen::Matrix4d T_a_b = lidar.at(std::stoul(p.a)).inverse() * lidar.at(std::stoul(p.b));
    EXPECT_LE((T_a_b - p.T_a_b).cwiseAbs().maxCoeff(), 1e-5) << T_a_b;
    EXPECT_NEAR(T_a_b.col(3).head(3).norm(), p.distance, 1e-3);
  }
}

TEST_F(KittiIo, LidarPosesConjugateByTr) {
  Eigen::Matrix4d Tr = Eigen::Matrix4d::Identity();
  Tr.block<3, 3>(0, 0) << 0, -1, 0, 0, 0, -1, 1, 0, 0;  // velodyne (x fwd, y left, z up) → camera axes
  Tr.block<3, 1>(0, 3) << 0.1, -0.2, 0.3;
  Eigen::Matrix4d P = Eigen::Matrix4d::Identity();
  P.block<3, 1>(0, 3) << 0, 0, 10;  // camera moved 10 m along its optical axis (z)
  const auto lidar = sgtllc::io::lidarPoses({P}, Tr);
  ASSERT_EQ(lidar.size(), 1u);
  // The same motion seen by the LiDAR is 10 m forward along its x axis.
  Eigen::Matrix4d forward = Eigen::Matrix4d::Identity();
  forward(0, 3) = 10;
  EXPECT_TRUE(lidar[0].isApprox(forward, 1e-12)) << lidar[0];
  EXPECT_THROW(sgtllc::io::lidarPoses({P}, Eigen::Matrix4d::Zero()), Error);
}

}  // namespace
