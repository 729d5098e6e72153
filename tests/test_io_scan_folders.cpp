// Sequence folders of PCD and PLY scans (README "Your own data"): the real KITTI 00 scans rewritten in each format
// read back to the same points and labels as the .bin files; labels from a label field, labels/ or a label folder;
// mixed formats, missing labels and a bad scan are errors naming the folder or the file.
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/ply_read.h"
#include "sgtllc/io/sequence.h"
#include "test_io_support.h"
#include "test_scan_folder_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::ScanFile;

const fs::path kSeq00 = fs::path(SGTLLC_DATA_DIR) / "kitti" / "00";

void expectSameClouds(const io::SequenceDir& a, const io::SequenceDir& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.frameName(i), b.frameName(i));
    const LabeledCloud ca = a.load(i), cb = b.load(i);
    ASSERT_EQ(ca.points.size(), cb.points.size()) << a.frameName(i);
    EXPECT_EQ(ca.labels, cb.labels) << a.frameName(i);
    for (size_t k = 0; k < ca.points.size(); ++k) ASSERT_EQ(ca.points[k], cb.points[k]) << a.frameName(i) << " " << k;
  }
}

class ScanFolders : public test::TempDirTest, public ::testing::WithParamInterface<ScanFile> {};

TEST_P(ScanFolders, RealScansReadBackAsTheirBinFilesWithTheLabelField) {
  // Scans in the folder itself (no velodyne/), labels in each file's label field.
  test::convertSequence(kSeq00, dir_ / "seq", GetParam(), /*in_velodyne=*/false);
  const io::SequenceDir bin(kSeq00.string());
  const io::SequenceDir converted(path("seq"));
  EXPECT_TRUE(converted.labelsInScans());
  EXPECT_EQ(converted.scanDir(), path("seq"));
  EXPECT_EQ(fs::path(converted.scanPath(3)).filename().string(),
            std::string("004501") + test::extensionOf(GetParam()));
  expectSameClouds(bin, converted);
}

TEST_P(ScanFolders, ScansWithoutALabelFieldTakeTheLabelFolder) {
  test::convertSequence(kSeq00, dir_ / "seq", GetParam(), /*in_velodyne=*/true);
  // Rewrite the scans without their label field, and give the labels as SemanticKITTI's labels/ folder.
  for (const auto& entry : fs::directory_iterator(dir_ / "seq" / "velodyne")) {
    const std::string stem = entry.path().stem().string();
    const LabeledCloud cloud = io::readLabeledScan((kSeq00 / "velodyne" / (stem + ".bin")).string(),
                                                   (kSeq00 / "labels" / (stem + ".label")).string());
    test::writeScanFile(entry.path().string(), cloud, GetParam(), /*with_labels=*/false);
  }
  fs::copy(kSeq00 / "labels", dir_ / "seq" / "labels");
  const io::SequenceDir converted(path("seq"));
  EXPECT_FALSE(converted.labelsInScans());
  EXPECT_EQ(converted.scanDir(), path("seq/velodyne"));
  EXPECT_EQ(converted.labelPath(0), path("seq/labels/000052.label"));
  expectSameClouds(io::SequenceDir(kSeq00.string()), converted);

  // Without labels/ the message names the first missing file and the missing field.
  fs::remove_all(dir_ / "seq" / "labels");
  const std::string e = test::errorOf([&] { io::SequenceDir{path("seq")}; });
  EXPECT_THAT(e, HasSubstr(path("seq/labels/000052.label") + ": missing label file (4 of 4 scans in " +
                           path("seq/velodyne") + " have no label, and 000052"));
  EXPECT_THAT(e, HasSubstr("has no 'label' field"));
  // The scans alone: points only.
  const io::SequenceDir points(path("seq"), io::SequenceLabels{false, "", LabelFormat::kAuto});
  EXPECT_TRUE(points.load(0).labels.empty());
  EXPECT_EQ(points.load(0).points.size(), io::readKittiBin((kSeq00 / "velodyne" / "000052.bin").string()).size());
}

TEST_P(ScanFolders, ALabelFolderWinsOverTheLabelField) {
  test::convertSequence(kSeq00, dir_ / "seq", GetParam(), /*in_velodyne=*/false);
  // Other labels for every point: id 7 everywhere.
  fs::create_directories(dir_ / "net");
  for (size_t i = 0; i < 4; ++i) {
    const io::SequenceDir seq(path("seq"));
    const std::vector<uint32_t> ids(seq.load(i).points.size(), 7u);
    std::ofstream(path("net/" + seq.frameName(i) + ".label"), std::ios::binary)
        .write(reinterpret_cast<const char*>(ids.data()), static_cast<std::streamsize>(4 * ids.size()));
  }
  const io::SequenceDir seq(path("seq"), io::SequenceLabels{true, path("net"), LabelFormat::kAuto});
  EXPECT_FALSE(seq.labelsInScans());
  const LabeledCloud cloud = seq.load(2);
  ASSERT_FALSE(cloud.labels.empty());
  EXPECT_EQ(cloud.labels, std::vector<uint32_t>(cloud.points.size(), 7u));
}

TEST_P(ScanFolders, ABadScanIsAnErrorNamingIt) {
  test::convertSequence(kSeq00, dir_ / "seq", GetParam(), /*in_velodyne=*/false);
  const std::string bad = path(std::string("seq/000850") + test::extensionOf(GetParam()));
  {
    std::ifstream in(bad, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes.resize(bytes.size() / 2);  // truncated in the middle of the data
    std::ofstream(bad, std::ios::binary | std::ios::trunc) << bytes;
  }
  const io::SequenceDir seq(path("seq"));
  EXPECT_NO_THROW(seq.load(1));
  EXPECT_THAT(test::errorOf([&] { seq.load(2); }), HasSubstr(bad + ":"));
}

std::string formatName(const ::testing::TestParamInfo<ScanFile>& param) {
  static const char* const kNames[] = {"PcdAscii", "PcdBinary", "PlyAscii", "PlyBinary"};
  return kNames[static_cast<int>(param.param)];
}

INSTANTIATE_TEST_SUITE_P(Formats, ScanFolders,
                         ::testing::Values(ScanFile::kPcdAscii, ScanFile::kPcdBinary, ScanFile::kPlyAscii,
                                           ScanFile::kPlyBinary),
                         formatName);

class ScanFolderLayout : public test::TempDirTest {};

TEST_F(ScanFolderLayout, AFolderMixingFormatsIsAnErrorNamingIt) {
  test::convertSequence(kSeq00, dir_ / "seq", ScanFile::kPcdBinary, /*in_velodyne=*/false);
  fs::copy_file(kSeq00 / "velodyne" / "000052.bin", dir_ / "seq" / "000053.bin");
  EXPECT_EQ(test::errorOf([&] { io::SequenceDir{path("seq")}; }),
            path("seq") + ": mixes scan formats (1 .bin, 4 .pcd files); a sequence folder holds one format");
}

TEST_F(ScanFolderLayout, NamesKeepTheirStemsInByteOrderAndOtherFilesAreIgnored) {
  const LabeledCloud cloud{{{1, 2, 3}, {4, 5, 6}}, {40, 50}};
  fs::create_directories(dir_ / "seq");
  for (const char* name : {"scan_b.PCD", "scan_a.pcd", "Z.pcd"}) {
    test::writeScanFile(path(std::string("seq/") + name), cloud, ScanFile::kPcdAscii, true);
  }
  std::ofstream(path("seq/poses.txt")) << "";
  std::ofstream(path("seq/notes.md")) << "not a scan\n";
  const io::SequenceDir seq(path("seq"));
  ASSERT_EQ(seq.size(), 3u);
  EXPECT_EQ(seq.frameName(0), "Z");
  EXPECT_EQ(seq.frameName(1), "scan_a");
  EXPECT_EQ(seq.frameName(2), "scan_b");
  EXPECT_EQ(seq.load(2).labels, (std::vector<uint32_t>{40, 50}));
}

TEST_F(ScanFolderLayout, AFolderWithoutScansSaysWhatItExpects) {
  fs::create_directories(dir_ / "empty");
  std::ofstream(path("empty/poses.txt")) << "";
  EXPECT_EQ(test::errorOf([&] { io::SequenceDir{path("empty")}; }),
            path("empty") + ": no scans (.bin, .pcd or .ply) and no velodyne/ folder");
}

TEST_F(ScanFolderLayout, AScanWithoutTheFirstScansLabelFieldIsAnErrorNamingIt) {
  const LabeledCloud cloud{{{1, 2, 3}}, {40}};
  fs::create_directories(dir_ / "seq");
  test::writeScanFile(path("seq/000000.pcd"), cloud, ScanFile::kPcdBinary, true);
  test::writeScanFile(path("seq/000001.pcd"), cloud, ScanFile::kPcdBinary, false);
  const io::SequenceDir seq(path("seq"));
  EXPECT_TRUE(seq.labelsInScans());
  EXPECT_THAT(test::errorOf([&] { seq.load(1); }), HasSubstr(path("seq/000001.pcd") + ": no field 'label'"));
}

// ---------------------------------------------------------------------------------------------------------------
// The PLY reader beyond what the folders use: big-endian data, elements around the vertices, list properties,
// double coordinates, and its errors.

class PlyRead : public test::TempDirTest {};

TEST_F(PlyRead, BigEndianDoublesAfterAFaceElementWithLists) {
  std::string data;
  auto be = [&data](const void* p, size_t n) {
    for (size_t k = n; k-- > 0;) data.push_back(static_cast<const char*>(p)[k]);
  };
  // One face (a list of 3 int vertex indices), then two vertices: double x y z, a list of uchar, short label.
  const uint8_t three = 3;
  be(&three, 1);
  for (int32_t v : {0, 1, 1}) be(&v, 4);
  const double xyz[2][3] = {{1.5, -2.25, 1e-3}, {100.0, 0.0, -7.0}};
  const int16_t labels[2] = {-1, 81};
  for (int i = 0; i < 2; ++i) {
    for (double c : xyz[i]) be(&c, 8);
    const uint8_t two = 2, extra[2] = {9, 9};
    be(&two, 1);
    data.append(reinterpret_cast<const char*>(extra), 2);
    be(&labels[i], 2);
  }
  const std::string file = write("big.ply",
                                 "ply\nformat binary_big_endian 1.0\nobj_info test\nelement face 1\n"
                                 "property list uchar int vertex_indices\nelement vertex 2\nproperty double x\n"
                                 "property double y\nproperty double z\nproperty list uint8 uint8 extra\n"
                                 "property short label\nend_header\n" +
                                     data);
  const LabeledCloud cloud = io::readPly(file);
  ASSERT_EQ(cloud.points.size(), 2u);
  EXPECT_EQ(cloud.points[0], Eigen::Vector3f(1.5f, -2.25f, 1e-3f));
  EXPECT_EQ(cloud.points[1], Eigen::Vector3f(100.0f, 0.0f, -7.0f));
  EXPECT_EQ(cloud.labels, (std::vector<uint32_t>{0xFFFFFFFFu, 81u}));
  EXPECT_EQ(io::plyVertexProperties(file), (std::vector<std::string>{"x", "y", "z", "extra", "label"}));
}

TEST_F(PlyRead, AsciiWithListsAndColours) {
  const std::string file = write("a.ply",
                                 "ply\r\nformat ascii 1.0\r\nelement vertex 2\r\nproperty float x\r\nproperty float y\r\n"
                                 "property float z\r\nproperty uchar red\r\nproperty list uchar float n\r\n"
                                 "property float label\r\nend_header\r\n1 2 3 255 2 0.5 0.5 70.4\r\n\r\n-1 -2 -3 0 0 "
                                 "71\r\nelement-after-vertex-is-never-read\n");
  const LabeledCloud cloud = io::readPly(file);
  ASSERT_EQ(cloud.points.size(), 2u);
  EXPECT_EQ(cloud.points[1], Eigen::Vector3f(-1, -2, -3));
  EXPECT_EQ(cloud.labels, (std::vector<uint32_t>{70, 71}));
  EXPECT_EQ(io::readPlyPoints(file).size(), 2u);
}

TEST_F(PlyRead, ErrorsNameTheFileAndTheProblem) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n";
  EXPECT_EQ(test::errorOf([&] { io::readPly(write("n.ply", "PLY\n")); }),
            path("n.ply") + ": not a PLY file (the first line is not 'ply')");
  EXPECT_EQ(test::errorOf([&] { io::readPly(write("z.ply", head + "end_header\n1 2\n")); }),
            path("z.ply") + ": no property 'z' in element vertex (properties: x y)");
  EXPECT_EQ(test::errorOf([&] { io::readPly(write("l.ply", head + "property float z\nend_header\n1 2 3\n")); }),
            path("l.ply") + ": no property 'label' in element vertex (properties: x y z)");
  EXPECT_THAT(test::errorOf([&] { io::readPly(write("h.ply", head + "property float\nend_header\n")); }),
              HasSubstr(path("h.ply") + ":6: malformed header line: 'property float'"));
  EXPECT_THAT(test::errorOf([&] { io::readPly(write("f.ply", "ply\nformat binary 1.0\nend_header\n")); }),
              HasSubstr(path("f.ply") + ":2: malformed header line: "));
  EXPECT_EQ(test::errorOf([&] { io::readPly(write("v.ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n")); }),
            path("v.ply") + ": no vertex element (a point cloud's points are its vertices)");
  EXPECT_EQ(test::errorOf([&] { io::readPlyPoints(write("t.ply", head + "property float z\nend_header\n")); }),
            path("t.ply") + ": truncated ascii data: element vertex has 1 entries, found 0");
  EXPECT_EQ(test::errorOf([&] { io::readPlyPoints(write("w.ply", head + "property float z\nend_header\n1 2 x\n")); }),
            path("w.ply") + ":8: property 'z': 'x' is not a number");
  EXPECT_EQ(test::errorOf([&] {
              io::readPlyPoints(write("b.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 2\n"
                                               "property float x\nproperty float y\nproperty float z\nend_header\n"
                                               "123456789012"));
            }),
            path("b.ply") + ": truncated binary data in element vertex");
}

}  // namespace
}  // namespace sgtllc
