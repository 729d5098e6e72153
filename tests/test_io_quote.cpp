// io::quoteContent: file content repeated in a message reaches the terminal as visible text, never as control bytes,
// and the readers use it.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/eval/pair_eval.h"
#include "sgtllc/io/g2o.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/pcd.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/sim/manifest.h"
#include "test_io_support.h"

namespace sgtllc::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(IoQuoted, PrintableTextIsKeptBetweenQuotes) {
  EXPECT_EQ(quoteContent("binary_lz4"), "'binary_lz4'");
  EXPECT_EQ(quoteContent(""), "''");
  EXPECT_EQ(quoteContent("b\xc3\xa2timent \xe2\x82\xac"), "'b\xc3\xa2timent \xe2\x82\xac'");  // UTF-8 stays readable
}

TEST(IoQuoted, ControlBytesAndInvalidUtf8AreEscaped) {
  EXPECT_EQ(quoteContent("\x1b[2J\x1b]0;owned\x07"), "'\\x1b[2J\\x1b]0;owned\\x07'");
  EXPECT_EQ(quoteContent(std::string("a\0b", 3)), "'a\\x00b'");
  EXPECT_EQ(quoteContent("tab\tnl\ncr\r del\x7f"), "'tab\\tnl\\ncr\\r del\\x7f'");
  EXPECT_EQ(quoteContent("it's a\\b"), "'it\\'s a\\\\b'");  // the quote and the escape character cannot be forged
  EXPECT_EQ(quoteContent("\xc2\x9b" "31m"), "'\\xc2\\x9b31m'");   // U+009B is the 8-bit CSI: a C1 control
  EXPECT_EQ(quoteContent("\x9b" "31m"), "'\\x9b31m'");            // a lone continuation byte
  EXPECT_EQ(quoteContent("\xc0\xaf"), "'\\xc0\\xaf'");            // overlong '/'
  EXPECT_EQ(quoteContent("\xed\xa0\x80"), "'\\xed\\xa0\\x80'");   // a UTF-16 surrogate
  EXPECT_EQ(quoteContent("\xe2\x82"), "'\\xe2\\x82'");            // cut short
}

TEST(IoQuoted, LongContentIsCutAtACharacterBoundary) {
  EXPECT_EQ(quoteContent(std::string(100, 'x'), 8), "'xxxxxxxx'... (100 bytes)");
  EXPECT_EQ(quoteContent("abcdefg\xc3\xa2zz", 8), "'abcdefg'... (11 bytes)");  // â would straddle the limit
  EXPECT_EQ(quoteContent("abcdefgh", 8), "'abcdefgh'");
  EXPECT_EQ(escapeContent("a\x1b" "b", 8), "a\\x1bb");
  EXPECT_EQ(escapeContent(std::string(10, 'y'), 4), "yyyy... (10 bytes)");
}

TEST(IoQuoted, EscapeControlsLeavesSafeTextAlone) {
  EXPECT_EQ(escapeControls("dir/\x1b[31m.txt:1: bad\n\tnext"), "dir/\\x1b[31m.txt:1: bad\n\tnext");
  EXPECT_EQ(escapeControls("\r\x7f\xc2\x9b\xff b\xc3\xa2t"), "\\x0d\\x7f\\xc2\\x9b\\xff b\xc3\xa2t");
  // Text quoteContent made safe (backslashes, quotes) comes back unchanged: no double escaping.
  const std::string quoted = "f: " + quoteContent("it's \x1b\\ \x1b[2J");
  EXPECT_EQ(escapeControls(quoted), quoted);
}

class IoQuotedReaders : public test::TempDirTest {};

// Each reader that repeats file content in a message sends it through quoteContent(): no raw ESC reaches stderr.
TEST_F(IoQuotedReaders, MessagesCarryNoRawControlBytes) {
  const std::string esc = "\x1b[31mred";
  auto message = [](auto&& read) {
    try {
      read();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string pcd = write("h.pcd", "VERSION 0.7\n" + esc + " 1\n");
  const std::string pcd_data = write("d.pcd",
                                     "FIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nWIDTH 1\nHEIGHT 1\nPOINTS 1\n"
                                     "DATA " + esc + "\n");
  const std::string nodes = write("n.txt", "1 2 " + esc + " 50\n");
  const std::string poses = write("poses.txt", "1 0 0 0 0 1 0 0 0 0 1 " + esc + "\n");
  const std::string pairs = write("pairs.txt", "1 0 " + esc + "\n");
  const std::string g2o = write("g.g2o", esc + " 0 0 0 0 0 0 0 1\n");
  const std::string g2o_value = write("v.g2o", "VERTEX_SE3:QUAT 0 0 0 " + esc + " 0 0 0 1\n");
  const std::string texts[] = {
      message([&] { readPcd(pcd); }),
      message([&] { readPcd(pcd_data); }),
      message([&] { readNodesTxt(nodes, LabelMap()); }),
      message([&] { readKittiPoses(poses); }),
      message([&] { eval::readPairList(pairs); }),
      message([&] { readG2o(g2o); }),
      message([&] { readG2o(g2o_value); }),
      message([&] { sim::parseManifest(esc + "\n", "simulation.txt"); }),
      message([&] { sim::parseManifest("format " + esc + "\n", "simulation.txt"); }),
  };
  for (const std::string& t : texts) {
    EXPECT_THAT(t, HasSubstr("\\x1b[31mred'"));
    EXPECT_THAT(t, Not(HasSubstr("\x1b")));
  }
}

}  // namespace
}  // namespace sgtllc::io
