// The sgtllc command at the detector's limits: node files above graph.max_nodes fail naming the file, and a
// sequence too short to have any loop candidate is said so once.
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_cli_support.h"
#include "test_io_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using test::CliRun;
using test::run;

/// Occurrences of @p what in @p text.
int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class CliLimits : public test::TempDirTest {
 protected:
  /// A node file of @p n rows on a 7 m lattice, the stable classes in turn (SemanticKITTI raw ids).
  std::string nodeFile(const std::string& name, int n) const {
    static const int kIds[7] = {50, 51, 70, 71, 72, 80, 81};
    std::string rows;
    for (int k = 0; k < n; ++k) {
      rows += std::to_string(7 * (k % 30)) + " " + std::to_string(7 * (k / 30)) + " 0 " +
              std::to_string(kIds[k % 7]) + "\n";
    }
    return write(name, rows);
  }
};

TEST_F(CliLimits, NodeFilesAboveMaxNodesAreNamed) {
  // The default graph.max_nodes is 1,000: a 1,001-row file fails at once (no quadratic graph is built).
  const std::string big = nodeFile("big.txt", 1001);
  const std::string small = nodeFile("small.txt", 12);
  const CliRun r = run("pair " + big + " " + small);
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr(big + " has 1001 nodes, more than graph.max_nodes = 1000"));
  // At the boundary of a configured limit: 20 rows load, 21 do not; `run` names the file too.
  const std::string config = write("limit.yaml", "graph:\n  max_nodes: 20\n");
  const std::string at = nodeFile("seq/000000.txt", 20);
  EXPECT_EQ(run("pair --config " + config + " " + at + " " + small).status, 0);
  const std::string over = nodeFile("seq/000001.txt", 21);
  const CliRun seq = run("run --config " + config + " --nodes " + path("seq"));
  EXPECT_EQ(seq.status, 1);
  EXPECT_THAT(seq.out, HasSubstr(over + " has 21 nodes, more than graph.max_nodes = 20"));
}

TEST_F(CliLimits, AShortSequenceIsSaidOnceToHaveNoCandidates) {
  for (int f = 0; f < 3; ++f) nodeFile("seq/00000" + std::to_string(f) + ".txt", 12);
  const std::string seq = path("seq");
  const CliRun r = run("run --nodes " + seq);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(count(r.out, "note:"), 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr("note: " + seq + " has 3 frames, so no frame can have loop candidates: a frame is "
                               "compared only with frames at least retrieval.exclude_recent = 50 older. Set "
                               "retrieval.exclude_recent below 3"));
  // A warm-up longer than the sequence is named instead; a gap the sequence exceeds gives no note.
  const std::string warm = write("warm.yaml", "retrieval:\n  exclude_recent: 1\n  warmup_frames: 5\n");
  EXPECT_THAT(run("run --config " + warm + " --nodes " + seq).out,
              HasSubstr("no frame is searched before retrieval.warmup_frames = 5"));
  const std::string gap = write("gap.yaml", "retrieval:\n  exclude_recent: 2\n");
  const CliRun searched = run("run --json --config " + gap + " --nodes " + seq);
  EXPECT_EQ(searched.status, 0);
  EXPECT_THAT(searched.out, Not(HasSubstr("note:")));
  EXPECT_THAT(searched.out, HasSubstr("\"loops\": 1"));  // frame 2 revisits the identical frame 0
}

}  // namespace
}  // namespace sgtllc
