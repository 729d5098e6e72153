// PCD reading and node export. The test writes its own PCD files byte by byte from the PCD v0.7 spec (header lines,
// ascii rows, binary records, binary_compressed = two uint32 sizes + LZF of the fields stored one after another).
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>
#include <tuple>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <liblzf/lzf.h>

#include "sgtllc/io/pcd.h"
#include "test_io_support.h"

namespace {

using sgtllc::Error;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// ------------------------------------------------------------------------------------------------------------------
// A minimal PCD writer for the tests (independent of the library's reader).

struct TestField {
  std::string name;
  char type;  // I, U, F
  int size;   // bytes
  int count;
};

void PrintTo(const TestField& f, std::ostream* os) { *os << f.name << ':' << f.type << f.size << 'x' << f.count; }

/// A cloud as plain numbers: rows[i] holds every element of point i, fields in order, COUNT elements each.
struct TestCloud {
  std::vector<TestField> fields;
  std::vector<std::vector<double>> rows;
  size_t width = 0, height = 1;  // width 0 = number of rows
};

std::string header(const TestCloud& c, const std::string& data, const std::string& version = "0.7",
                   bool with_count = true) {
  std::ostringstream h;
  h << "# .PCD v" << version << " - Point Cloud Data file format\nVERSION " << version << "\nFIELDS";
  for (const auto& f : c.fields) h << ' ' << f.name;
  h << "\nSIZE";
  for (const auto& f : c.fields) h << ' ' << f.size;
  h << "\nTYPE";
  for (const auto& f : c.fields) h << ' ' << f.type;
  if (with_count) {
    h << "\nCOUNT";
    for (const auto& f : c.fields) h << ' ' << f.count;
  }
  h << "\nWIDTH " << (c.width ? c.width : c.rows.size()) << "\nHEIGHT " << c.height << "\n";
  if (version == "0.7") h << "VIEWPOINT 0 0 0 1 0 0 0\n";
  h << "POINTS " << c.rows.size() << "\nDATA " << data << "\n";
  return h.str();
}

template <typename T>
void put(std::string& out, double v) {
  const T t = static_cast<T>(v);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &t, sizeof(T));  // the test host is little-endian, as PCL files are
  out.append(bytes, sizeof(T));
}

void putScalar(std::string& out, const TestField& f, double v) {
  if (f.type == 'F') return f.size == 4 ? put<float>(out, v) : put<double>(out, v);
  const bool s = f.type == 'I';
  switch (f.size) {
    case 1: return s ? put<int8_t>(out, v) : put<uint8_t>(out, v);
    case 2: return s ? put<int16_t>(out, v) : put<uint16_t>(out, v);
    case 4: return s ? put<int32_t>(out, v) : put<uint32_t>(out, v);
    default: return s ? put<int64_t>(out, v) : put<uint64_t>(out, v);
  }
}

/// First element of field @p k within a row.
size_t elementIndex(const TestCloud& c, size_t k) {
  size_t e = 0;
  for (size_t j = 0; j < k; ++j) e += static_cast<size_t>(c.fields[j].count);
  return e;
}

std::string asciiPcd(const TestCloud& c) {
  std::ostringstream out;
  out << header(c, "ascii") << std::setprecision(17);
  for (const auto& row : c.rows) {
    for (size_t e = 0; e < row.size(); ++e) out << (e ? " " : "") << row[e];
    out << "\n";
  }
  return out.str();
}

std::string binaryPcd(const TestCloud& c) {
  std::string out = header(c, "binary");
  for (const auto& row : c.rows) {
    for (size_t k = 0; k < c.fields.size(); ++k) {
      for (int j = 0; j < c.fields[k].count; ++j) putScalar(out, c.fields[k], row[elementIndex(c, k) + j]);
    }
  }
  return out;
}

std::string compressedPcd(const TestCloud& c) {
  std::string soa;  // field by field: every point's elements of field 0, then of field 1, ...
  for (size_t k = 0; k < c.fields.size(); ++k) {
    for (const auto& row : c.rows) {
      for (int j = 0; j < c.fields[k].count; ++j) putScalar(soa, c.fields[k], row[elementIndex(c, k) + j]);
    }
  }
  std::string packed(soa.size() + soa.size() / 16 + 64, '\0');
  const unsigned n = soa.empty() ? 0 : lzf_compress(soa.data(), static_cast<unsigned>(soa.size()), packed.data(),
                                                    static_cast<unsigned>(packed.size()));
  EXPECT_TRUE(soa.empty() || n > 0);
  std::string out = header(c, "binary_compressed");
  put<uint32_t>(out, n);
  put<uint32_t>(out, static_cast<double>(soa.size()));
  out.append(packed.data(), n);
  return out;
}

std::string encode(const TestCloud& c, const std::string& data) {
  if (data == "ascii") return asciiPcd(c);
  if (data == "binary") return binaryPcd(c);
  return compressedPcd(c);
}

// ------------------------------------------------------------------------------------------------------------------

class PcdIo : public sgtllc::test::TempDirTest {};

/// Fields in a deliberately mixed order, with an extra scalar (intensity), a 2-count field and packed rgb, so the
/// reader must get every offset right. The label field's type varies.
TestCloud randomCloud(const TestField& label, size_t n, uint32_t seed) {
  TestCloud c;
  c.fields = {{"intensity", 'F', 4, 1}, {"x", 'F', 4, 1},     {"y", 'F', 4, 1}, {"normal_xy", 'F', 4, 2},
              {"z", 'F', 4, 1},         label,                {"rgb", 'U', 4, 1}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coord(-80.f, 80.f);
  std::uniform_int_distribution<int> id(0, 120);
  for (size_t i = 0; i < n; ++i) {
    double l = id(rng);
    if (label.type == 'F') l += (i % 2 ? 0.4 : -0.4);  // floats are rounded to the nearest id
    if (label.type == 'I' && i % 7 == 3) l = -1;        // a common "unlabelled" convention
    c.rows.push_back({coord(rng) / 80.f, coord(rng), coord(rng), 0.25, -0.5, coord(rng), l, double(rng() & 0xFFFFFF)});
  }
  return c;
}

uint32_t expectedLabel(double v) { return static_cast<uint32_t>(static_cast<int64_t>(std::llround(v))); }

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
  expectCloud(sgtllc::io::readPcd(p, label.name), cloud, 1, 6);
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
// Errors: each names the file.

TestCloud smallCloud() { return randomCloud({"label", 'U', 4, 1}, 10, 11); }

void expectError(const std::string& path, const std::string& text, const std::string& label_field = "label") {
  EXPECT_THAT([&] { sgtllc::io::readPcd(path, label_field); },
              ThrowsMessage<Error>(AllOf(HasSubstr(path), HasSubstr(text))));
}

TEST_F(PcdIo, MissingFileOrFieldIsAnError) {
  expectError((dir_ / "none.pcd").string(), "No such file or directory");
  const std::string p = write("c.pcd", binaryPcd(smallCloud()));
  expectError(p, ": no field 'semantic' (fields: intensity x y normal_xy z label rgb)", "semantic");
  expectError(p, ": field 'normal_xy' has COUNT 2; expected 1", "normal_xy");
}

TEST_F(PcdIo, WrongCoordinateTypeIsAnError) {
  TestCloud c;
  c.fields = {{"x", 'I', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"label", 'U', 4, 1}};
  c.rows = {{1, 2, 3, 4}};
  expectError(write("c.pcd", binaryPcd(c)), "field 'x' is I4; expected F4 or F8");
}

TEST_F(PcdIo, UnsupportedDataTypeIsAnError) {
  std::string text = asciiPcd(smallCloud());
  text.replace(text.find("DATA ascii"), 10, "DATA binary_lz4");
  expectError(write("c.pcd", text), ":11: unsupported DATA type 'binary_lz4'");
}

TEST_F(PcdIo, MalformedHeaderLinesAreErrors) {
  const std::string good = asciiPcd(smallCloud());
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return write("c.pcd", text);
  };
  expectError(edit("SIZE 4 4 4 4 4 4 4", "SIZE 4 4 4"), ":4: malformed header line: SIZE has 3 entries but FIELDS has 7");
  expectError(edit("TYPE F", "TYPE Q"), ":5: malformed header line: TYPE 'Q' is not I, U or F");
  expectError(edit("SIZE 4", "SIZE 3"), ":4: malformed header line: SIZE '3' is not 1, 2, 4 or 8");
  expectError(edit("WIDTH", "WIDHT"), ":7: malformed header line: unknown keyword 'WIDHT'");
  expectError(edit("HEIGHT 1", "HEIGHT one"), ":8: malformed header line: HEIGHT needs one non-negative integer");
  expectError(edit("HEIGHT 1", "HEIGHT 2"), "WIDTH x HEIGHT = 10 x 2 = 20 but POINTS = 10");
  expectError(edit("DATA ascii", "DATUM ascii"), "unknown keyword 'DATUM'");
}

TEST_F(PcdIo, VersionLineIsOptional) {
  std::string text = asciiPcd(smallCloud());
  text.replace(text.find("VERSION 0.7\n"), 12, "");
  EXPECT_EQ(sgtllc::io::readPcd(write("c.pcd", text)).points.size(), 10u);
}

TEST_F(PcdIo, HeaderWithoutDataOrFieldsIsAnError) {
  const std::string text = asciiPcd(smallCloud());
  expectError(write("a.pcd", text.substr(0, text.find("DATA"))), "PCD header has no DATA line");
  std::string no_type = text;
  no_type.erase(no_type.find("TYPE"), no_type.find("COUNT") - no_type.find("TYPE"));
  expectError(write("b.pcd", no_type), "PCD header has no TYPE line");
}

TEST_F(PcdIo, TruncatedDataIsAnError) {
  const TestCloud c = smallCloud();
  const std::string binary = binaryPcd(c);
  expectError(write("b.pcd", binary.substr(0, binary.size() - 5)),
              "truncated binary data: 10 points need 320 bytes, found 315");
  const std::string packed = compressedPcd(c);
  expectError(write("c.pcd", packed.substr(0, packed.size() - 5)), "truncated binary_compressed data");
  expectError(write("d.pcd", packed.substr(0, header(c, "binary_compressed").size() + 6)),
              "truncated binary_compressed data");
  const std::string ascii = asciiPcd(c);
  expectError(write("e.pcd", ascii.substr(0, ascii.rfind('\n', ascii.size() - 2) + 1)),
              "truncated ascii data: POINTS is 10 but found 9 points");
}

TEST_F(PcdIo, InconsistentCompressedSizesAreAnError) {
  const TestCloud c = smallCloud();
  std::string packed = compressedPcd(c);
  const size_t sizes = header(c, "binary_compressed").size();
  const uint32_t wrong = 319;
  std::memcpy(&packed[sizes + 4], &wrong, 4);
  expectError(write("c.pcd", packed), "binary_compressed block unpacks to 319 bytes but 10 points of 32 bytes need 320");
}

TEST_F(PcdIo, BadAsciiRowsAreErrorsWithLineNumbers) {
  const std::string head =
      "VERSION 0.7\nFIELDS x y z rgb label\nSIZE 4 4 4 4 4\nTYPE F F F F U\nCOUNT 1 1 1 1 1\n"
      "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n";  // data starts on line 10
  EXPECT_EQ(sgtllc::io::readPcd(write("ok.pcd", head + "1 2 3 junk 50\n\n4 5 6 0 70\n\n")).labels,
            (std::vector<uint32_t>{50, 70}));  // skipped fields are not parsed; blank lines are ignored
  expectError(write("a.pcd", head + "1 2 3 0 50\n4 5 6 70\n"), ":11: expected 5 values, found 4");
  expectError(write("b.pcd", head + "1 2.5.5 3 0 50\n4 5 6 0 70\n"), ":10: field 'y': '2.5.5' is not a number");
  expectError(write("c.pcd", head + "1 2 3 0 50\n4 5 6 0 70\n7 8 9 0 71\n"), ":12: more points than POINTS 2");
  expectError(write("d.pcd", head + "1 2 3 0 -5e9\n4 5 6 0 70\n"), ": point 0: label -5e9 is not a valid uint32 id");
}

TEST_F(PcdIo, NonFiniteFloatLabelIsAnError) {
  TestCloud c;
  c.fields = {{"x", 'F', 4, 1}, {"y", 'F', 4, 1}, {"z", 'F', 4, 1}, {"label", 'F', 4, 1}};
  c.rows = {{1, 2, 3, 50}, {1, 2, 3, std::nan("")}};
  expectError(write("c.pcd", binaryPcd(c)), ": point 1: label (F4) is not a valid uint32 id");
}

// ------------------------------------------------------------------------------------------------------------------
// Node export

TEST_F(PcdIo, WriteNodesPcdIoRoundTripsThroughReadPcd) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-100, 100);
  std::vector<sgtllc::Node> nodes(25);
  for (size_t i = 0; i < nodes.size(); ++i) {
    nodes[i].centre = Eigen::Vector3d(coord(rng), coord(rng), coord(rng));
    nodes[i].label = static_cast<int>(i % sgtllc::kNumClasses);
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
