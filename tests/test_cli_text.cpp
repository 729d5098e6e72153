// File names and file contents as text the command line writes: a frame name with a comma or a quote keeps the
// columns of `run --out` and `localize --out` (RFC 4180 quoting, io/csv.h), and no escape byte of any input reaches
// the terminal raw (io/quote.h).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/loops_csv.h"
#include "test_cli_support.h"
#include "test_node_files_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using test::CliRun;
using test::run;

constexpr const char* kAwkward = "a,b\"c";  // a comma and a quote: the frame name of the acceptance test

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Every CSV record of @p path.
std::vector<std::vector<std::string>> csvRecords(const std::string& path) {
  const std::string text = slurp(path);
  io::CsvReader reader(text, path);
  std::vector<std::vector<std::string>> out;
  for (std::vector<std::string> f; reader.next(f);) out.push_back(f);
  return out;
}

class CliText : public test::CliTempDirTest {
 protected:
  CliText() : CliTempDirTest("text") {}

  /// The planted sequence (test_support.h: frame 53 revisits frame 0) in dir_/seq, and its frames as node files
  /// in dir_/NODES, frame 53's named @p revisit (a name that sorts after 000052, so that it stays frame 53).
  void nodeFolder(const std::string& nodes, const std::string& revisit) {
    if (!fs::exists(path("seq"))) test::makePlantedSequence(path("seq"));
    test::writeNodeFiles(pipeline::FrameSource::semanticKitti(path("seq"), Config{}), path(nodes));
    fs::rename(path(nodes + "/000053.txt"), path(nodes + "/" + revisit + ".txt"));
  }
  /// The names of the node folder @p nodes, in frame order.
  std::vector<std::string> names(const std::string& nodes) const {
    const pipeline::FrameSource source = pipeline::FrameSource::nodeFiles(path(nodes), Config{});
    std::vector<std::string> out;
    for (size_t i = 0; i < source.size(); ++i) out.push_back(source.name(i));
    return out;
  }
};

TEST_F(CliText, RunOutWithACommaAndAQuoteInAFrameNameRoundTripsThroughOptimize) {
  nodeFolder("nodes", kAwkward);
  const CliRun r = run("run --nodes " + path("nodes") + " --out " + path("loops.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("loop a,b\"c -> 000000"));
  // The row as written: the name quoted, its quote doubled; 37 fields.
  const std::string csv = slurp(path("loops.csv"));
  EXPECT_THAT(csv, HasSubstr("\n\"a,b\"\"c\",000000,"));
  const auto records = csvRecords(path("loops.csv"));
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[1].size(), 37u);
  const std::vector<io::LoopRecord> loops = io::readLoopsCsv(path("loops.csv"), names("nodes"));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].query, kAwkward);
  EXPECT_EQ(loops[0].query_index, 53);
  EXPECT_EQ(loops[0].match_index, 0);

  // optimize reads it back against the node folder's names (the sequence's own poses as odometry).
  const CliRun o = run("optimize --odometry " + path("seq/poses.txt") + " --calib " + path("seq/calib.txt") +
                       " --loops " + path("loops.csv") + " --frames " + path("nodes") + " --out-trajectory " +
                       path("corrected.txt"));
  ASSERT_EQ(o.status, 0) << o.out;
  EXPECT_THAT(o.out, HasSubstr("frames 54, loops read 1"));
  EXPECT_TRUE(fs::is_regular_file(path("corrected.txt")));
}

TEST_F(CliText, LocalizeOutQuotesTheQueryName) {
  nodeFolder("nodes", "000053");  // the plain sequence, for the map
  const CliRun saved = run("run " + path("seq") + " --save-map " + path("m.sgtmap"));
  ASSERT_EQ(saved.status, 0) << saved.out;
  // One query: frame 53's nodes under the awkward name (another name than the map's, so not the map's session).
  fs::create_directories(path("query"));
  fs::copy_file(path("nodes/000053.txt"), path("query/" + std::string(kAwkward) + ".txt"));
  const CliRun r = run("localize --map " + path("m.sgtmap") + " --nodes " + path("query") + " --out " + path("hits.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("a,b\"c -> 000053"));
  const auto records = csvRecords(path("hits.csv"));
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].size(), 31u);
  ASSERT_EQ(records[1].size(), 31u);
  EXPECT_EQ(records[1][0], kAwkward);
  EXPECT_EQ(records[1][1], "000053");
  EXPECT_EQ(records[1][2], "1");
}

// --- no raw escape byte on stdout or stderr, one case per input kind ----------------------------------------

constexpr const char* kEsc = "\x1b[31m";

/// Runs @p args; its stdout and stderr must hold no ESC byte and each of @p texts (the escaped forms).
CliRun expectEscaped(const std::string& args, int status, const std::vector<std::string>& texts) {
  const CliRun r = run(args);
  EXPECT_EQ(r.status, status) << r.out;
  EXPECT_THAT(r.out, Not(HasSubstr("\x1b"))) << args;
  for (const std::string& t : texts) EXPECT_THAT(r.out, HasSubstr(t)) << args;
  return r;
}

TEST_F(CliText, NodeFileNamesInLoopsWarningsAndMapsAreEscaped) {
  // The revisit named z<ESC>[31m, and a first frame <ESC>[31m with a label id no label set knows (a warning).
  nodeFolder("nodes", "z" + std::string(kEsc));
  std::ofstream(path("nodes/" + std::string(kEsc) + ".txt")) << "1 2 3 4242\n";
  expectEscaped("run --nodes " + path("nodes") + " --save-map " + path("m.sgtmap"), 0,
                {"loop z\\x1b[31m -> 000000", "(first: \\x1b[31m)"});
  // The map's frame names, in `map info` and in `localize`'s answers.
  expectEscaped("map info " + path("m.sgtmap"), 0, {"first \\x1b[31m, last z\\x1b[31m"});
  fs::create_directories(path("query"));
  fs::copy_file(path("nodes/z" + std::string(kEsc) + ".txt"), path("query/q" + std::string(kEsc) + ".txt"));
  expectEscaped("localize --map " + path("m.sgtmap") + " --nodes " + path("query"), 0,
                {"q\\x1b[31m -> z\\x1b[31m"});
  // A bad node file whose name holds the escape: the error names it escaped.
  fs::create_directories(path("bad"));
  std::ofstream(path("bad/b" + std::string(kEsc) + ".txt")) << "1 2\n";
  expectEscaped("run --nodes " + path("bad"), 1, {"b\\x1b[31m.txt:1: expected 4 values"});
}

TEST_F(CliText, FileContentInMessagesIsEscaped) {
  // An unknown YAML key.
  std::ofstream(path("esc.yaml")) << "\"" << kEsc << "red\": 1\n";
  expectEscaped("config --config " + path("esc.yaml"), 1, {"unknown key '\\x1b[31mred'"});
  // A bad TUM timestamp token.
  std::ofstream(path("tum.txt")) << kEsc << " 0 0 0 0 0 0 1\n";
  std::ofstream(path("loops.csv")) << "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n";
  expectEscaped("optimize --odometry " + path("tum.txt") + " --loops " + path("loops.csv"), 1, {"\\x1b[31m"});
  // A loops CSV naming an unknown frame.
  std::ofstream(path("odo.txt")) << "0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 0 1\n";
  std::ofstream(path("bad.csv")) << "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n"
                                 << kEsc << ",000000,1,1,1,0,0,0,0,1,0,0,0,0,1,0\n";
  expectEscaped("optimize --odometry " + path("odo.txt") + " --loops " + path("bad.csv"), 1,
                {"unknown query frame '\\x1b[31m'"});
}

}  // namespace
}  // namespace sgtllc
