// Pose-graph optimisation: analytic reference, recovery of a simulated drive, outlier step, online == batch,
// determinism at 1 and 2 threads, bad graphs.
#include <gtest/gtest.h>

#include <cstring>

#include "sgtllc/backend/information.h"
#include "sgtllc/backend/pose_graph_optimizer.h"
#include "test_backend_support.h"

namespace sgtllc::backend {
namespace {

using test::ate;

Eigen::Isometry3d along_x(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

// A straight drive along x with noisy step lengths and one exact loop 0 → N: the least-squares solution spreads
// the loop's discrepancy evenly, u_i = s_i − c with c = w_l (S − L) / (w_o + N w_l) (docs/backend.md derivation).
TEST(BackendOptimizer, StraightLineMatchesTheAnalyticSolution) {
  const int n = 50;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  const double w_o = 100.0, w_l = 400.0, L = n * 1.0;
  PoseGraph graph;
  graph.poses.push_back(Eigen::Isometry3d::Identity());
  std::vector<double> s(n + 1, 0.0);
  double S = 0.0;
  for (int i = 1; i <= n; ++i) {
    s[i] = 1.0 + noise(rng);
    S += s[i];
    Edge e;
    e.from = i - 1;
    e.to = i;
    e.T_from_to = along_x(s[i]);
    e.information = Matrix6d::Identity() * w_o;
    graph.edges.push_back(e);
    graph.poses.push_back(graph.poses.back() * e.T_from_to);
  }
  Edge loop;
  loop.from = 0;
  loop.to = n;
  loop.T_from_to = along_x(L);
  loop.information = Matrix6d::Identity() * w_l;
  loop.kind = EdgeKind::kLoop;
  graph.edges.push_back(loop);

  BackendConfig config;
  config.loop_loss = RobustLoss::kNone;
  config.solver.function_tolerance = 1e-16;  // run the linear problem to machine precision
  config.solver.parameter_tolerance = 1e-16;
  const BackendResult r = optimize(graph, config);
  ASSERT_EQ(r.num_accepted, 1);
  const double c = w_l * (S - L) / (w_o + n * w_l);
  double x = 0.0, worst_x = 0.0, worst_other = 0.0;
  for (int i = 1; i <= n; ++i) {
    x += s[i] - c;
    worst_x = std::max(worst_x, std::abs(r.poses[i].translation().x() - x));
    worst_other = std::max({worst_other, r.poses[i].translation().tail<2>().norm(),
                            Eigen::AngleAxisd(r.poses[i].rotation()).angle()});
  }
  EXPECT_LT(worst_x, 1e-9);
  EXPECT_LT(worst_other, 1e-12);
  EXPECT_GT(std::abs(c * n), 0.1);  // the correction is not negligible
}

struct Drive {
  std::vector<Eigen::Isometry3d> truth;
  PoseGraph graph;
  int num_true_loops = 0;
};

Drive simulatedDrive(int frames, int false_percent, const BackendConfig& config = {}) {
  Drive d;
  d.truth = test::urbanTrajectory(frames);
  d.graph = odometryGraph(test::driftingOdometry(d.truth, 11), config.odometry);
  const std::vector<Edge> loops = test::trueLoops(d.truth, 12, config.loops);
  d.num_true_loops = static_cast<int>(loops.size());
  d.graph.edges.insert(d.graph.edges.end(), loops.begin(), loops.end());
  const int num_false = (d.num_true_loops * false_percent + 99) / 100;
  const std::vector<Edge> wrong = test::falseLoops(d.truth, num_false, 13, config.loops);
  d.graph.edges.insert(d.graph.edges.end(), wrong.begin(), wrong.end());
  return d;
}

TEST(BackendOptimizer, CorrectsAnUrbanDriveWithDriftingOdometry) {
  const Drive d = simulatedDrive(2000, 0);
  const double ate_odometry = ate(d.graph.poses, d.truth);
  const BackendResult r = optimize(d.graph);
  const double ate_corrected = ate(r.poses, d.truth);
  RecordProperty("ate_odometry_m", std::to_string(ate_odometry));
  RecordProperty("ate_corrected_m", std::to_string(ate_corrected));
  EXPECT_GT(ate_odometry, 3.0);
  EXPECT_LE(ate_corrected, 0.3);
  EXPECT_GT(d.num_true_loops, 50);
  EXPECT_EQ(r.num_rejected, 0);
  EXPECT_TRUE(r.converged);
}

// Exact loops from frame 0 to every 25th frame pin the drift down to the odometry noise between them. (Loops
// between two passes alone cannot: a deformation shared by both passes satisfies them.)
TEST(BackendOptimizer, RecoversTheTrajectoryFromNoisyOdometryAndExactLoops) {
  const std::vector<Eigen::Isometry3d> truth = test::urbanTrajectory(1500);
  PoseGraph graph = odometryGraph(test::driftingOdometry(truth, 21, 4.0e-5, 0.002), OdometryNoise{});
  for (int q = 25; q < 1500; q += 25) {
    Edge e;
    e.from = 0;
    e.to = q;
    e.T_from_to = truth[0].inverse() * truth[q];
    e.information = Matrix6d::Identity() * 1e6;
    e.kind = EdgeKind::kLoop;
    graph.edges.push_back(e);
  }
  BackendConfig config;
  config.loop_loss = RobustLoss::kNone;     // exact loops: plain least squares
  config.consistency.translation_m = 1e9;   // and no outlier step
  config.consistency.rotation_rad = 10.0;
  const BackendResult r = optimize(graph, config);
  EXPECT_GT(ate(graph.poses, truth), 2.0);
  double worst_anchor = 0.0;
  for (int q = 25; q < 1500; q += 25) {
    worst_anchor = std::max(worst_anchor, (r.poses[q].translation() - truth[q].translation()).norm());
  }
  EXPECT_LT(worst_anchor, 0.005);
  EXPECT_LT(ate(r.poses, truth), 0.05);
  EXPECT_EQ(r.num_rejected, 0);
}

// Issue 8 robustness: 5 % false loops (random pairs > 50 m apart, random poses) leave the ATE within 10 % of the
// clean result, and every false loop is reported rejected.
TEST(BackendOptimizer, FalseLoopsAreRejectedAndDoNotBendTheMap) {
  const Drive clean = simulatedDrive(2000, 0);
  const Drive dirty = simulatedDrive(2000, 5);
  const BackendResult r_clean = optimize(clean.graph);
  const BackendResult r = optimize(dirty.graph);
  const double ate_clean = ate(r_clean.poses, clean.truth);
  const double ate_dirty = ate(r.poses, dirty.truth);
  RecordProperty("ate_clean_m", std::to_string(ate_clean));
  RecordProperty("ate_with_false_loops_m", std::to_string(ate_dirty));
  EXPECT_LE(ate_dirty, 1.1 * ate_clean);
  const int num_false = static_cast<int>(r.loops.size()) - dirty.num_true_loops;
  ASSERT_GE(num_false, 5);
  EXPECT_EQ(r.num_rejected, num_false);
  for (size_t i = dirty.num_true_loops; i < r.loops.size(); ++i) {
    EXPECT_NE(r.loops[i].decision, LoopDecision::kAccepted) << "false loop " << i;
  }
  // Without the outlier step the same loops do bend the map (the test can fail).
  BackendConfig no_outlier_step;
  no_outlier_step.consistency.translation_m = 1e9;
  no_outlier_step.consistency.rotation_rad = 10.0;
  no_outlier_step.max_rejection_rounds = 0;
  no_outlier_step.loop_loss = RobustLoss::kNone;
  EXPECT_GT(ate(optimize(dirty.graph, no_outlier_step).poses, dirty.truth), 2.0 * ate_clean);
}

bool samePoses(const std::vector<Eigen::Isometry3d>& a, const std::vector<Eigen::Isometry3d>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::memcmp(a[i].matrix().data(), b[i].matrix().data(), sizeof(double) * 16) != 0) return false;
  }
  return true;
}

TEST(BackendOptimizer, IdenticalAtOneAndTwoThreadsAndOnRerun) {
  const Drive d = simulatedDrive(1000, 5);
  BackendConfig one, two;
  one.solver.num_threads = 1;
  two.solver.num_threads = 2;
  const BackendResult a = optimize(d.graph, one);
  const BackendResult b = optimize(d.graph, two);
  const BackendResult c = optimize(d.graph, one);
  EXPECT_TRUE(samePoses(a.poses, b.poses));
  EXPECT_TRUE(samePoses(a.poses, c.poses));
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_GT(a.num_rejected, 0);
}

// Online: odometry frame by frame, re-optimising at every loop, ends where the batch does.
TEST(BackendOptimizer, OnlineEndsAtTheBatchResult) {
  const Drive d = simulatedDrive(1300, 5);
  const BackendResult batch = optimize(d.graph);
  std::vector<std::vector<Edge>> loops_at(d.truth.size());
  for (const Edge& e : d.graph.edges) {
    if (e.kind == EdgeKind::kLoop) loops_at[std::max(e.from, e.to)].push_back(e);
  }
  PoseGraphOptimizer online;
  int reoptimisations = 0;
  for (size_t i = 0; i < d.truth.size(); ++i) {
    if (i > 0) online.addOdometry(d.graph.edges[i - 1].T_from_to);
    for (const Edge& e : loops_at[i]) {
      online.closeLoop(e);
      ++reoptimisations;
    }
  }
  EXPECT_GT(reoptimisations, 20);
  ASSERT_EQ(online.numFrames(), static_cast<int>(d.truth.size()));
  double worst = 0.0;
  for (size_t i = 0; i < d.truth.size(); ++i) {
    worst = std::max(worst, (online.poses()[i].translation() - batch.poses[i].translation()).norm());
  }
  EXPECT_LT(worst, 1e-3);  // the solver tolerance, from two starting points
  EXPECT_EQ(online.result().num_rejected, batch.num_rejected);
}

TEST(BackendOptimizer, RejectsMalformedGraphs) {
  PoseGraph g = odometryGraph(test::urbanTrajectory(5), OdometryNoise{});
  PoseGraph missing = g;
  missing.edges.erase(missing.edges.begin() + 2);
  EXPECT_THROW(
      {
        try {
          optimize(missing);
        } catch (const Error& e) {
          EXPECT_STREQ(e.what(), "pose graph: no odometry edge 2 -> 3");
          throw;
        }
      },
      Error);
  PoseGraph outside = g;
  Edge loop;
  loop.from = 1;
  loop.to = 9;
  loop.kind = EdgeKind::kLoop;
  outside.edges.push_back(loop);
  EXPECT_THROW(optimize(outside), Error);
  PoseGraph self = g;
  loop.to = 1;
  self.edges.push_back(loop);
  EXPECT_THROW(optimize(self), Error);
  PoseGraphOptimizer online;
  EXPECT_THROW(online.addLoop(loop), Error);
  EXPECT_THROW(optimize(PoseGraph{}), Error);
}

}  // namespace
}  // namespace sgtllc::backend
