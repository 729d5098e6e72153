// Lists of scan pairs for `sgtllc pair --list` (io/scan_pairs.h): records, comments, a header, paths from the
// list's folder, and a message naming the file and line for every malformed list.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sgtllc/io/scan_pairs.h"
#include "test_io_support.h"

namespace sgtllc::io {
namespace {

using ::testing::HasSubstr;
using test::errorOf;

class ScanPairs : public test::TempDirTest {};

TEST_F(ScanPairs, RelativePathsAreTakenFromTheListsFolderAndAbsoluteOnesStay) {
  const std::string list = write("lists/pairs.txt",
                                 "query,match\n"
                                 "a.bin,../scans/b.bin\n"
                                 "# a comment, with a comma\n"
                                 "\n"
                                 "/abs/c.bin,\"d,1 \"\"x\"\".bin\"\r\n");
  const std::vector<ScanPair> pairs = readScanPairs(list);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].query, path("lists/a.bin"));
  EXPECT_EQ(pairs[0].match, path("lists/../scans/b.bin"));
  EXPECT_EQ(pairs[0].line, 2u);
  EXPECT_EQ(pairs[1].query, "/abs/c.bin");
  EXPECT_EQ(pairs[1].match, path("lists/d,1 \"x\".bin"));
  EXPECT_EQ(pairs[1].line, 5u);
}

TEST_F(ScanPairs, OnlyAFirstRecordIsAHeader) {
  const std::vector<ScanPair> pairs = readScanPairs(write("p.txt", "/q.bin,/m.bin\nquery,match\n"));
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[1].query, path("query"));
  EXPECT_EQ(pairs[1].match, path("match"));
}

TEST_F(ScanPairs, AMalformedListIsRefusedNamingItsLine) {
  const std::string one = write("one.txt", "/q.bin,/m.bin\n/only.bin\n");
  EXPECT_THAT(errorOf([&] { readScanPairs(one); }), HasSubstr(one + ":2: 1 fields, expected two: QUERY,MATCH"));
  const std::string three = write("three.txt", "/a,/b,/c\n");
  EXPECT_THAT(errorOf([&] { readScanPairs(three); }), HasSubstr(three + ":1: 3 fields"));
  const std::string empty_field = write("empty_field.txt", "/a,\n");
  EXPECT_THAT(errorOf([&] { readScanPairs(empty_field); }), HasSubstr(empty_field + ":1: an empty path"));
  const std::string nul = write("nul.txt", std::string("/a,/b\0c\n", 8));
  EXPECT_THAT(errorOf([&] { readScanPairs(nul); }), HasSubstr(nul + ":1: the path '/b\\x00c' holds a NUL byte"));
  const std::string quote = write("quote.txt", "/a,\"/b\n");
  EXPECT_THAT(errorOf([&] { readScanPairs(quote); }), HasSubstr(quote + ":1:"));
}

TEST_F(ScanPairs, AListWithoutPairsOrFileIsRefused) {
  const std::string none = write("none.txt", "query,match\n# nothing yet\n\n");
  EXPECT_EQ(errorOf([&] { readScanPairs(none); }), none + ": no pair (one a line: QUERY,MATCH)");
  EXPECT_THAT(errorOf([&] { readScanPairs(path("missing.txt")); }), HasSubstr(path("missing.txt")));
}

}  // namespace
}  // namespace sgtllc::io
