// False inter-session loops for the merge's robustness test (eval/false_loops.h, docs/sessions.md): where they tie
// a session frame to, how many there are, and that a seed gives the same ones.
#include <gtest/gtest.h>

#include "sgtllc/eval/false_loops.h"

namespace sgtllc {
namespace {

constexpr int kMapFrames = 201;  // a straight street, a frame a metre

std::vector<Eigen::Isometry3d> street() {
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < kMapFrames; ++i) poses.emplace_back(Eigen::Translation3d(i, 0.0, 0.0));
  return poses;
}

std::vector<std::string> names() {
  std::vector<std::string> n;
  for (int i = 0; i < kMapFrames; ++i) n.push_back("m" + std::to_string(i));
  return n;
}

/// Four inter-session loops (map frames 10, 60, 110, 190 to session frames 0..3) and one intra-session loop.
std::vector<pipeline::ClosingLoop> found() {
  std::vector<pipeline::ClosingLoop> loops;
  int j = 0;
  for (const int k : {10, 60, 110, 190}) {
    pipeline::ClosingLoop l;
    l.edge = {k, kMapFrames + j, Eigen::Isometry3d::Identity(), backend::Matrix6d::Identity() * (k + 1),
              backend::EdgeKind::kLoop};
    l.query = "s/" + std::to_string(j++);
    l.match = "m" + std::to_string(k);
    loops.push_back(l);
  }
  pipeline::ClosingLoop intra;
  intra.edge = {kMapFrames + 0, kMapFrames + 3, Eigen::Isometry3d::Identity(), backend::Matrix6d::Identity(),
                backend::EdgeKind::kLoop};
  loops.push_back(intra);
  return loops;
}

TEST(FalseInterSessionLoops, TieASessionFrameToAMapFrameFarFromIt) {
  const std::vector<pipeline::ClosingLoop> loops = found();
  const std::vector<pipeline::ClosingLoop> f = eval::falseInterSessionLoops(street(), loops, 0.5, 11, names());
  ASSERT_EQ(f.size(), 2u);  // half of the four inter-session loops; the intra-session one does not count
  for (const pipeline::ClosingLoop& l : f) {
    EXPECT_TRUE(l.injected);
    ASSERT_GE(l.edge.to, kMapFrames);
    ASSERT_LT(l.edge.to, kMapFrames + 4);
    const pipeline::ClosingLoop& real = loops[static_cast<size_t>(l.edge.to - kMapFrames)];
    EXPECT_GT(std::abs(l.edge.from - real.edge.from), 50) << l.edge.from;  // metres along the street
    EXPECT_EQ(l.query, real.query);
    EXPECT_EQ(l.match, "m" + std::to_string(l.edge.from));
    EXPECT_EQ(l.edge.information, real.edge.information);  // weighs like the loop it copies
  }
  const std::vector<pipeline::ClosingLoop> again = eval::falseInterSessionLoops(street(), loops, 0.5, 11, names());
  ASSERT_EQ(again.size(), f.size());
  for (size_t k = 0; k < f.size(); ++k) {
    EXPECT_EQ(again[k].edge.from, f[k].edge.from);
    EXPECT_EQ(again[k].edge.T_from_to.matrix(), f[k].edge.T_from_to.matrix());
  }
  EXPECT_EQ(eval::falseInterSessionLoops(street(), loops, 0.01, 11, names()).size(), 1u);  // at least one
  EXPECT_TRUE(eval::falseInterSessionLoops(street(), loops, 0.0, 11, names()).empty());
  // A map no longer than 50 m has no frame far enough from any.
  const std::vector<Eigen::Isometry3d> whole = street();
  const std::vector<Eigen::Isometry3d> short_street(whole.begin(), whole.begin() + 40);
  std::vector<pipeline::ClosingLoop> near = loops;
  for (pipeline::ClosingLoop& l : near) {
    l.edge.from = std::min(l.edge.from, 39);
    l.edge.to += 40 - kMapFrames;
  }
  EXPECT_THROW(eval::falseInterSessionLoops(short_street, near, 0.5, 11, names()), Error);
}

}  // namespace
}  // namespace sgtllc
