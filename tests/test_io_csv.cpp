// CSV fields as RFC 4180 quotes them (io/csv.h): the writer leaves ordinary fields alone and quotes the rest, the
// reader takes back exactly what was written, and the loops CSV keeps its columns for any frame name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sgtllc/io/csv.h"
#include "sgtllc/io/loops_csv.h"
#include "sgtllc/types.h"
#include "test_io_support.h"
#include "test_support.h"

namespace sgtllc::io {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::vector<std::vector<std::string>> records(const std::string& text) {
  CsvReader reader(text, "t.csv");
  std::vector<std::vector<std::string>> out;
  for (std::vector<std::string> f; reader.next(f);) out.push_back(f);
  return out;
}

std::string errorOf(const std::string& text) {
  return test::errorOf([&] { records(text); });
}

/// Fields that need quoting and some that do not, in every position of a record.
const std::vector<std::string> kAwkward = {"a,b\"c", "", "plain", "\"", ",", "x\ny", "cr\r", "\r\n", "\"\"", " sp "};

TEST(IoCsv, OrdinaryFieldsAreWrittenAsTheyAre) {
  EXPECT_EQ(csvField("004501"), "004501");
  EXPECT_EQ(csvField(""), "");
  EXPECT_EQ(csvField("-1.500000"), "-1.500000");
  EXPECT_EQ(csvField(" a b "), " a b ");  // spaces are part of a field (RFC 4180 §2.4), no reason to quote
}

TEST(IoCsv, CommasQuotesAndLineBreaksAreQuoted) {
  EXPECT_EQ(csvField("a,b\"c"), "\"a,b\"\"c\"");
  EXPECT_EQ(csvField("\""), "\"\"\"\"");
  EXPECT_EQ(csvField("x\ny"), "\"x\ny\"");
  EXPECT_EQ(csvField("cr\r"), "\"cr\r\"");
  std::string out = "k=";
  appendCsvField(out, "zz,evil,1,2");
  EXPECT_EQ(out, "k=\"zz,evil,1,2\"");
}

TEST(IoCsv, WrittenRecordsReadBackExactly) {
  std::string text;
  std::vector<std::vector<std::string>> written;
  for (size_t shift = 0; shift < kAwkward.size(); ++shift) {
    std::vector<std::string> record;
    for (size_t k = 0; k < 4; ++k) record.push_back(kAwkward[(shift + k) % kAwkward.size()]);
    for (size_t k = 0; k < record.size(); ++k) {
      if (k > 0) text += ',';
      appendCsvField(text, record[k]);
    }
    text += shift % 2 ? "\r\n" : "\n";  // CRLF and LF endings alike
    written.push_back(record);
  }
  EXPECT_EQ(records(text), written);
}

TEST(IoCsv, RecordsStartOnTheLineTheReaderReports) {
  CsvReader reader("h\n\"two\nlines\",x\n\n\r\nlast\n", "t.csv");
  std::vector<std::string> f;
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(reader.line(), 1u);
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f, (std::vector<std::string>{"two\nlines", "x"}));
  EXPECT_EQ(reader.at(), "t.csv:2");
  ASSERT_TRUE(reader.next(f));  // the blank lines 4 and 5 are skipped
  EXPECT_EQ(f, std::vector<std::string>{"last"});
  EXPECT_EQ(reader.line(), 6u);
  EXPECT_FALSE(reader.next(f));
  EXPECT_EQ(f, std::vector<std::string>{"last"});  // untouched at the end
}

TEST(IoCsv, EmptyFieldsAndAnUnterminatedLastLine) {
  EXPECT_EQ(records(",,\n"), (std::vector<std::vector<std::string>>{{"", "", ""}}));
  EXPECT_EQ(records("a,\"\""), (std::vector<std::vector<std::string>>{{"a", ""}}));
  EXPECT_EQ(records("a,b\r"), (std::vector<std::vector<std::string>>{{"a", "b"}}));
  EXPECT_TRUE(records("").empty());
  EXPECT_TRUE(records("\n\r\n\r").empty());
}

TEST(IoCsv, MalformedQuotingNamesTheLine) {
  EXPECT_THAT(errorOf("a\n\"open,\nstill open"), AllOf(HasSubstr("t.csv:2:"), HasSubstr("never closed")));
  EXPECT_THAT(errorOf("a\nb\n\"x\"y,z\n"), AllOf(HasSubstr("t.csv:3:"), HasSubstr("after the closing quote of field 1")));
  EXPECT_THAT(errorOf("a,b\"c\n"), AllOf(HasSubstr("t.csv:1:"), HasSubstr("inside unquoted field 2")));
  EXPECT_THAT(errorOf("\"x\"\r,y\n"), HasSubstr("after the closing quote"));  // a CR not ending the line
}

// The loops CSV: a frame name that holds the separator, quotes or a newline keeps every column in place.
class LoopsCsvQuoting : public test::TempDirTest {};

TEST_F(LoopsCsvQuoting, AwkwardFrameNamesRoundTrip) {
  const std::vector<std::string> frames = {"000000", "a,b\"c", "zz,evil,1,2", "two\nlines", "\"", "cr\r\nlf"};
  std::vector<LoopRecord> loops;
  for (size_t q = 1; q < frames.size(); ++q) {
    LoopRecord l;
    l.query = frames[q];
    l.match = frames[q - 1];
    l.score = 0.25 * static_cast<double>(q);
    l.T_match_query = test::rigid(10.0 * static_cast<double>(q), 0.0, 0.0, Eigen::Vector3d(1.0, 2.0, 3.0));
    loops.push_back(l);
  }
  for (const bool with_information : {false, true}) {
    const std::string file = write("loops.csv", loopsCsvText(loops, with_information));
    const std::vector<LoopRecord> back = readLoopsCsv(file, frames);
    ASSERT_EQ(back.size(), loops.size());
    for (size_t i = 0; i < back.size(); ++i) {
      EXPECT_EQ(back[i].query, loops[i].query);
      EXPECT_EQ(back[i].match, loops[i].match);
      EXPECT_EQ(back[i].query_index, static_cast<int>(i + 1));
      EXPECT_EQ(back[i].match_index, static_cast<int>(i));
      EXPECT_DOUBLE_EQ(back[i].score, loops[i].score);
      EXPECT_NEAR((back[i].T_match_query - loops[i].T_match_query).cwiseAbs().maxCoeff(), 0.0, 5e-7);
    }
  }
  // The first data line of the file as written: the names quoted, the numbers as before.
  const std::string text = loopsCsvText({loops[0]});
  EXPECT_THAT(text, HasSubstr("\n\"a,b\"\"c\",000000,0.250000,"));
}

TEST_F(LoopsCsvQuoting, AnUnknownQuotedNameIsShownEscaped) {
  const std::string file = write("loops.csv", "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n"
                                              "\"x,\x1b[31m\nred\",000000,1,1,1,0,0,0,0,1,0,0,0,0,1,0\n");
  EXPECT_THAT(test::errorOf([&] { readLoopsCsv(file, {"000000"}); }),
              AllOf(HasSubstr(file + ":2: unknown query frame 'x,\\x1b[31m\\nred'"), testing::Not(HasSubstr("\x1b"))));
}

}  // namespace
}  // namespace sgtllc::io
