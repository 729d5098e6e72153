// A second session merged into a map whose poses are the truth: the simulated urban route of
// test_backend_support.h, its first 1,200 frames the map and the next 900 (the middle and outer streets again, some
// the other way) a new session with its own drifting odometry, started at the identity.
#include <gtest/gtest.h>

#include <random>

#include "sgtllc/backend/session_merge.h"
#include "test_backend_support.h"

namespace sgtllc {
namespace {

constexpr int kMapFrames = 1200;
constexpr int kSessionFrames = 900;

struct Drive {
  std::vector<Eigen::Isometry3d> truth;    // every frame, map frames first
  backend::SessionGraph graph;
  std::vector<int> false_loops;  // indices into graph.loops
};

/// Inter-session loops from session frames every 10th frame to the nearest map frame within 3 m, and intra-session
/// loops where the session drives its own streets again; @p false_count wrong inter-session loops.
Drive makeDrive(int false_count, const backend::BackendConfig& config) {
  Drive d;
  d.truth = test::urbanTrajectory(kMapFrames + kSessionFrames);
  d.graph.map_poses.assign(d.truth.begin(), d.truth.begin() + kMapFrames);
  const std::vector<Eigen::Isometry3d> session_truth(d.truth.begin() + kMapFrames, d.truth.end());
  // The session's odometry knows nothing of the map: it starts at the identity in a frame of its own.
  std::vector<Eigen::Isometry3d> own;
  for (const Eigen::Isometry3d& T : session_truth) own.push_back(session_truth.front().inverse() * T);
  d.graph.odometry = test::driftingOdometry(own, 11, 1.5e-4, 0.01);
  std::mt19937 rng(5);
  for (int q = 0; q < kSessionFrames; q += 10) {
    int best = -1;
    double best_d = 3.0;
    for (int m = 0; m < kMapFrames; ++m) {
      const double dist = (d.truth[m].translation() - session_truth[q].translation()).norm();
      if (dist < best_d) {
        best_d = dist;
        best = m;
      }
    }
    if (best < 0) continue;
    d.graph.loops.push_back(test::fittedLoop(best, kMapFrames + q, d.truth[best].inverse() * session_truth[q], rng,
                                             config.loops));
  }
  for (const backend::Edge& e : test::trueLoops(session_truth, 6, config.loops)) {
    backend::Edge shifted = e;
    shifted.from += kMapFrames;
    shifted.to += kMapFrames;
    d.graph.loops.push_back(shifted);
  }
  std::uniform_int_distribution<int> map_frame(0, kMapFrames - 1), session_frame(0, kSessionFrames - 1);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI), t(-5.0, 5.0);
  while (static_cast<int>(d.false_loops.size()) < false_count) {
    const int m = map_frame(rng), q = session_frame(rng);
    if ((d.truth[m].translation() - session_truth[q].translation()).norm() <= 50.0) continue;
    const double heading = yaw(rng);
    const Eigen::Vector3d offset{t(rng), t(rng), 0.0};
    d.false_loops.push_back(static_cast<int>(d.graph.loops.size()));
    d.graph.loops.push_back(test::fittedLoop(m, kMapFrames + q, test::planarPose(offset, heading), rng, config.loops));
  }
  return d;
}

double maxError(const std::vector<Eigen::Isometry3d>& poses, const std::vector<Eigen::Isometry3d>& truth, int first) {
  double worst = 0.0;
  for (size_t i = 0; i < poses.size(); ++i) {
    worst = std::max(worst, (poses[i].translation() - truth[first + i].translation()).norm());
  }
  return worst;
}

TEST(SessionMerge, PlacesTheSessionInTheMapsFrameAndRejectsFalseInterSessionLoops) {
  const backend::BackendConfig config;
  const Drive d = makeDrive(6, config);
  const backend::SessionMerge merged = backend::mergeSession(d.graph, config);
  ASSERT_TRUE(merged.placed);
  ASSERT_EQ(merged.result.poses.size(), static_cast<size_t>(kSessionFrames));
  ASSERT_EQ(merged.result.loops.size(), d.graph.loops.size());
  for (int k : d.false_loops) EXPECT_NE(merged.result.loops[k].decision, backend::LoopDecision::kAccepted) << k;
  int inter = 0;
  for (const backend::Edge& e : d.graph.loops) inter += e.from < kMapFrames;
  EXPECT_EQ(merged.inter_loops, inter);
  EXPECT_EQ(merged.inter_accepted, inter - 6);  // every true one
  // No alignment: the map's frame is the truth's. The odometry alone, placed by the first loop, is metres off.
  EXPECT_LT(maxError(merged.result.poses, d.truth, kMapFrames), 0.5);
  std::vector<Eigen::Isometry3d> dead_reckoned;
  for (const Eigen::Isometry3d& T : d.graph.odometry) dead_reckoned.push_back(merged.T_world_odometry * T);
  EXPECT_GT(maxError(dead_reckoned, d.truth, kMapFrames), 5.0);
}

TEST(SessionMerge, FalseLoopsDoNotMoveTheSession) {
  const backend::BackendConfig config;
  const Drive clean = makeDrive(0, config), dirty = makeDrive(6, config);
  const backend::SessionMerge a = backend::mergeSession(clean.graph, config);
  const backend::SessionMerge b = backend::mergeSession(dirty.graph, config);
  ASSERT_TRUE(a.placed && b.placed);
  EXPECT_LT(maxError(b.result.poses, clean.truth, kMapFrames), 1.1 * maxError(a.result.poses, clean.truth, kMapFrames) + 1e-3);
}

TEST(SessionMerge, TooFewInterSessionLoopsLeaveTheSessionInItsOwnFrame) {
  const backend::BackendConfig config;
  Drive d = makeDrive(0, config);
  // One inter-session loop, no intra-session one: not placed, and the odometry is the optimum.
  std::vector<backend::Edge> one{d.graph.loops.front()};
  d.graph.loops = one;
  const backend::SessionMerge merged = backend::mergeSession(d.graph, config);  // two needed by default
  EXPECT_FALSE(merged.placed);
  EXPECT_EQ(merged.inter_accepted, 0);
  EXPECT_EQ(merged.result.loops[0].decision, backend::LoopDecision::kInconsistent);
  EXPECT_LT(maxError(merged.result.poses, d.graph.odometry, 0), 1e-9);
  // With one loop allowed to place it, the session starts where that loop says.
  backend::BackendConfig one_is_enough = config;
  one_is_enough.sessions.min_inter_loops = 1;
  const backend::SessionMerge placed = backend::mergeSession(d.graph, one_is_enough);
  ASSERT_TRUE(placed.placed);
  const backend::Edge& e = d.graph.loops[0];
  const Eigen::Isometry3d at = d.graph.map_poses[e.from] * e.T_from_to;
  EXPECT_LT((placed.result.poses[e.to - kMapFrames].translation() - at.translation()).norm(), 1e-6);
}

TEST(SessionMerge, RefusesLoopsThatDoNotFitTheGraph) {
  const backend::BackendConfig config;
  backend::SessionGraph g;
  g.map_poses.assign(3, Eigen::Isometry3d::Identity());
  EXPECT_THROW(backend::mergeSession(g, config), Error);  // no session frames
  g.odometry.assign(2, Eigen::Isometry3d::Identity());
  backend::Edge e;
  e.kind = backend::EdgeKind::kLoop;
  for (auto [from, to] : {std::pair{0, 1}, std::pair{3, 3}, std::pair{0, 5}, std::pair{-1, 3}}) {
    e.from = from;
    e.to = to;
    g.loops = {e};
    EXPECT_THROW(backend::mergeSession(g, config), Error) << from << " -> " << to;
  }
  e.from = 0;
  e.to = 4;
  g.loops = {e};
  EXPECT_NO_THROW(backend::mergeSession(g, config));
}

}  // namespace
}  // namespace sgtllc
