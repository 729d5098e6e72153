// Bad input and existing output on the command line (README, "The `sgtllc` command"): each case exits non-zero
// with a message that names the file and the problem, and leaves every input and every existing file as it was.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "sgtllc/eval/report.h"
#include "sgtllc/io/output_file.h"
#include "test_cli_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

using test::CliRun;
using test::run;

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Every file under @p root (relative path → content): compared before and after a command.
std::map<std::string, std::string> snapshot(const fs::path& root) {
  std::map<std::string, std::string> files;
  if (!fs::exists(root)) return files;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), root).string()] = readAll(e.path());
  }
  return files;
}

std::string scan(const std::string& frame) { return test::dataPath("kitti/00/velodyne/" + frame + ".bin"); }

class CliReliability : public test::CliTempDirTest {
 protected:
  CliReliability() : CliTempDirTest("clirel") {}

  std::string write(const std::string& name, const std::string& bytes) const {
    fs::create_directories(fs::path(path(name)).parent_path());
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }
  /// The planted 54-frame sequence (test_support.h) in dir_/seq, once per test.
  std::string sequence() const {
    const std::string seq = path("seq");
    if (!fs::exists(seq)) test::makePlantedSequence(seq);
    return seq;
  }

  /// Runs @p args, expecting failure (exit 1) with every one of @p texts in the output and no file under dir_
  /// (inputs and existing outputs alike) created, changed or removed.
  CliRun expectRefused(const std::string& args, const std::vector<std::string>& texts) const {
    const auto before = snapshot(dir_);
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 1) << r.out;
    for (const std::string& t : texts) EXPECT_THAT(r.out, HasSubstr(t));
    EXPECT_THAT(r.out, Not(HasSubstr("\x1b")));
    const auto after = snapshot(dir_);
    EXPECT_EQ(before.size(), after.size());
    for (const auto& [name, content] : before) {
      EXPECT_TRUE(after.count(name) && after.at(name) == content) << name << " changed";
    }
    return r;
  }
};

// --- existing output files -------------------------------------------------------------------------------------

TEST_F(CliReliability, EvalReportRefusesAnyExistingReportFile) {
  const std::string seq = sequence();
  // Not only report.md: any file the report would write is the user's until --force says otherwise.
  for (const char* name : {"frames.csv", "metrics.json", "trajectory.png", "report.md"}) {
    fs::remove_all(path("report"));
    const std::string mine = write("report/" + std::string(name), "my own notes\n");
    expectRefused("eval " + seq + " --report " + path("report"), {mine, "file exists", "--force"});
  }
  // The pair-list report's own files: pairs.csv.
  fs::remove_all(path("report"));
  const std::string pairs = write("pairs.txt", "53 0 1\n1 0 0\n");
  const std::string mine = write("report/pairs.csv", "query,candidate\n");
  expectRefused("eval " + seq + " --pairs " + pairs + " --report " + path("report"), {mine, "file exists"});
}

TEST_F(CliReliability, EvalReportWritesBesideUnrelatedFilesAndReplacesOnlyWithForce) {
  const std::string seq = sequence();
  const std::string pairs = write("pairs.txt", "53 0 1\n1 0 0\n");
  const std::string notes = write("report/notes.txt", "keep me\n");  // not a report file: never touched
  const CliRun r = run("eval " + seq + " --pairs " + pairs + " --report " + path("report"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(readAll(notes), "keep me\n");
  for (const std::string& f : eval::pairListReportFiles(path("report"))) EXPECT_TRUE(fs::exists(f)) << f;
  // No temporary file stays behind.
  for (const auto& e : fs::directory_iterator(path("report"))) {
    EXPECT_FALSE(io::isTemporaryFileName(e.path().filename().string())) << e.path();
  }
  const std::string metrics = path("report/metrics.json");
  const std::string first = readAll(metrics);
  write("report/metrics.json", "stale");
  expectRefused("eval " + seq + " --pairs " + pairs + " --report " + path("report"), {metrics, "file exists"});
  const CliRun forced = run("eval " + seq + " --pairs " + pairs + " --report " + path("report") + " --force");
  ASSERT_EQ(forced.status, 0) << forced.out;
  EXPECT_EQ(readAll(metrics), first);
  EXPECT_EQ(readAll(notes), "keep me\n");
}

TEST_F(CliReliability, RunOutRefusesAnExistingFile) {
  const std::string out = write("loops.csv", "mine\n");
  expectRefused("run " + sequence() + " --out " + out, {out, "file exists", "--force"});
}

TEST_F(CliReliability, PairExportRefusesAnExistingFileAndCreatesNothing) {
  const std::string mine = write("export/match_nodes.txt", "1 2 3 50\n");
  expectRefused("pair --export " + path("export") + " " + scan("004501") + " " + scan("000052"),
                {mine, "file exists", "--force"});
  EXPECT_FALSE(fs::exists(path("export/query.ply")));
}

TEST_F(CliReliability, PairExportIntoANewFolderCreatesNothingWhenAnInputIsBad) {
  const std::string bad = write("bad.bin", std::string(10, '\0'));  // not a multiple of 16 bytes
  expectRefused("pair --export " + path("new/export") + " " + bad + " " + scan("000052"), {bad});
  EXPECT_FALSE(fs::exists(path("new")));
  expectRefused("pair --export " + path("new/export") + " " + path("missing.bin") + " " + scan("000052"),
                {path("missing.bin"), "No such file"});
  EXPECT_FALSE(fs::exists(path("new")));
}

TEST_F(CliReliability, SimulateRefusesAFolderWithFiles) {
  const std::string mine = write("sim/poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  expectRefused("simulate --out " + path("sim") + " --frames 3 --seed 1 --no-preview",
                {path("sim"), "not empty", "--force"});
  EXPECT_EQ(readAll(mine), "1 0 0 0 0 1 0 0 0 0 1 0\n");
}

// A file that appears between the up-front check and the final rename is kept too: the rename itself refuses.
TEST_F(CliReliability, AFileThatAppearsMeanwhileIsNotClobbered) {
  const std::string target = path("late.csv");
  EXPECT_THAT(
      [&] {
        io::writeThroughTemporary(target, io::Overwrite::kRefuse, [&](const std::string& tmp) {
          std::ofstream(tmp) << "ours\n";
          std::ofstream(target) << "theirs\n";  // the user's file, created while we worked
        });
      },
      testing::ThrowsMessage<Error>(AllOf(HasSubstr(target), HasSubstr("file exists"))));
  EXPECT_EQ(readAll(target), "theirs\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);  // no temporary file left
  io::writeFileAtomically(target, "ours\n", io::Overwrite::kReplace);
  EXPECT_EQ(readAll(target), "ours\n");
  EXPECT_THAT([&] { io::writeFileAtomically(target, "again\n", io::Overwrite::kRefuse); },
              testing::ThrowsMessage<Error>(HasSubstr("file exists")));
  EXPECT_EQ(readAll(target), "ours\n");
}

// --- bad input ---------------------------------------------------------------------------------------------------

TEST_F(CliReliability, EmptyPairListIsAnErrorNamingTheFile) {
  const std::string empty = write("empty.txt", "");
  expectRefused("eval " + sequence() + " --pairs " + empty, {empty, "no pairs"});
  const std::string comments = write("comments.txt", "# query candidate label\n\n");
  expectRefused("eval " + sequence() + " --pairs " + comments + " --report " + path("report"), {comments, "no pairs"});
  EXPECT_FALSE(fs::exists(path("report")));
}

TEST_F(CliReliability, PcdClaimingGigabytesFailsAtOnce) {
  std::string bomb =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 268435455\n"
      "HEIGHT 1\nPOINTS 268435455\nDATA binary_compressed\n";
  const uint32_t sizes[2] = {16, 268435455u * 16u};
  bomb.append(reinterpret_cast<const char*>(sizes), 8);
  bomb += '\x0f' + std::string(15, 'A');
  const std::string p = write("bomb.pcd", bomb);
  expectRefused("pair " + p + " " + scan("000052"), {p, "claims 4294967280 bytes from 16 compressed bytes"});
}

TEST_F(CliReliability, FileContentInMessagesIsEscaped) {
  const std::string esc = "\x1b]0;owned\x07\x1b[2J";
  const std::string pcd = write("esc.pcd", "VERSION 0.7\n" + esc + " 1\nDATA ascii\n");
  expectRefused("pair " + pcd + " " + scan("000052"), {pcd, "unknown keyword '\\x1b]0;owned\\x07\\x1b[2J'"});
  const std::string nodes = write("esc.txt", "1 2 3 " + esc + "\n");
  expectRefused("pair " + nodes + " " + scan("000052"), {nodes, "label '\\x1b]0;owned"});
  const std::string pairs = write("esc_pairs.txt", esc + "\n");
  expectRefused("eval " + sequence() + " --pairs " + pairs, {pairs, "found '\\x1b]0;owned"});
}

}  // namespace
}  // namespace sgtllc
