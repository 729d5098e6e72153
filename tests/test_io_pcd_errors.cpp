// PCD reading errors: each names the file and the problem.
#include <cstring>
#include <string>

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

}  // namespace
