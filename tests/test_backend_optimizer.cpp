// Pose-graph optimisation: analytic reference, recovery of a simulated drive, outlier step, online == batch,
// determinism at 1 and 2 threads, bad graphs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <tuple>

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
struct StraightLine {
  static constexpr int n = 50;
  static constexpr double w_o = 100.0, w_l = 400.0, L = n * 1.0;
  std::vector<double> s = std::vector<double>(n + 1, 0.0);  ///< step lengths
  double S = 0.0;                                            ///< their sum

  StraightLine() {
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.05);
    for (int i = 1; i <= n; ++i) {
      s[i] = 1.0 + noise(rng);
      S += s[i];
    }
  }
  Edge step(int i) const {
    Edge e;
    e.from = i - 1;
    e.to = i;
    e.T_from_to = along_x(s[i]);
    e.information = Matrix6d::Identity() * w_o;
    return e;
  }
  Edge loop() const {
    Edge e;
    e.from = 0;
    e.to = n;
    e.T_from_to = along_x(L);
    e.information = Matrix6d::Identity() * w_l;
    e.kind = EdgeKind::kLoop;
    return e;
  }
  static BackendConfig config() {  // plain least squares, run to machine precision
    BackendConfig c;
    c.loop_loss = RobustLoss::kNone;
    c.solver.function_tolerance = 1e-16;
    c.solver.parameter_tolerance = 1e-16;
    return c;
  }
  double c() const { return w_l * (S - L) / (w_o + n * w_l); }
  /// Worst deviation of x from the analytic solution, and worst of the other coordinates and the rotation.
  std::pair<double, double> errors(const std::vector<Eigen::Isometry3d>& poses) const {
    double x = 0.0, worst_x = 0.0, worst_other = 0.0;
    for (int i = 1; i <= n; ++i) {
      x += s[i] - c();
      worst_x = std::max(worst_x, std::abs(poses[i].translation().x() - x));
      worst_other = std::max({worst_other, poses[i].translation().tail<2>().norm(),
                              Eigen::AngleAxisd(poses[i].rotation()).angle()});
    }
    return {worst_x, worst_other};
  }
};

TEST(BackendOptimizer, StraightLineMatchesTheAnalyticSolution) {
  const StraightLine line;
  PoseGraph graph;
  graph.poses.push_back(Eigen::Isometry3d::Identity());
  for (int i = 1; i <= line.n; ++i) {
    graph.edges.push_back(line.step(i));
    graph.poses.push_back(graph.poses.back() * graph.edges.back().T_from_to);
  }
  graph.edges.push_back(line.loop());
  const BackendResult r = optimize(graph, StraightLine::config());
  ASSERT_EQ(r.num_accepted, 1);
  const auto [worst_x, worst_other] = line.errors(r.poses);
  EXPECT_LT(worst_x, 1e-9);
  EXPECT_LT(worst_other, 1e-12);
  EXPECT_GT(std::abs(line.c() * line.n), 0.1);  // the correction is not negligible
}

// The same graph on the reduced graph: its anchors are frames 0 and N only, so the whole drive is one composed
// edge and every frame in between is placed from the two anchors. The problem along x is linear, so the
// placement is exact.
TEST(BackendOptimizer, ReducedGraphPlacesTheChainExactlyOnAStraightLine) {
  const StraightLine line;
  PoseGraphOptimizer reduced(StraightLine::config());
  for (int i = 1; i <= line.n; ++i) reduced.addOdometry(line.step(i).T_from_to, line.step(i).information);
  const BackendResult r = reduced.closeLoop(line.loop());
  ASSERT_TRUE(r.reduced);
  EXPECT_EQ(r.num_poses_solved, 2);
  const auto [worst_x, worst_other] = line.errors(r.poses);
  EXPECT_LT(worst_x, 1e-9);
  EXPECT_LT(worst_other, 1e-12);
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
  config.consistency.translation_m = 1000.0;  // and no outlier step (the range's top)
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

// Robustness (docs/backend.md, "Outlier step"): 5 % false loops (random pairs > 50 m apart, random poses) leave
// the ATE within 10 % of the clean result, and every false loop is reported rejected.
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
  no_outlier_step.consistency.translation_m = 1000.0;
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

// Over the frames of @p a (the frames after the last loop do not move the earlier ones).
double worstTranslation(const std::vector<Eigen::Isometry3d>& a, const std::vector<Eigen::Isometry3d>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, (a[i].translation() - b[i].translation()).norm());
  return worst;
}

// (from, to, decision) of every loop, sorted: online and batch receive the loops in different orders.
std::vector<std::tuple<int, int, LoopDecision>> decisions(const BackendResult& r) {
  std::vector<std::tuple<int, int, LoopDecision>> out;
  for (const LoopReport& l : r.loops) out.emplace_back(l.from, l.to, l.decision);
  std::sort(out.begin(), out.end());
  return out;
}

// Online: odometry frame by frame, closeLoop at every loop (on the reduced graph, the default, or on the full
// graph), then optimize() at the end.
struct OnlineRun {
  BackendResult last_close;  ///< the result of the last closeLoop
  BackendResult final;       ///< optimize() after the last frame
  int reoptimisations = 0;
};

OnlineRun runOnline(const Drive& d, const BackendConfig& config) {
  std::vector<std::vector<Edge>> loops_at(d.truth.size());
  for (const Edge& e : d.graph.edges) {
    if (e.kind == EdgeKind::kLoop) loops_at[std::max(e.from, e.to)].push_back(e);
  }
  PoseGraphOptimizer online(config);
  OnlineRun run;
  for (size_t i = 0; i < d.truth.size(); ++i) {
    if (i > 0) online.addOdometry(d.graph.edges[i - 1].T_from_to);
    for (const Edge& e : loops_at[i]) {
      run.last_close = online.closeLoop(e);
      ++run.reoptimisations;
    }
  }
  run.final = online.optimize();
  return run;
}

// The reduced graph's closeLoop ends within a centimetre of the batch result (first-order placement of the
// frames between anchors; 6 mm measured), with the same loop decisions; optimize() then is the batch result up
// to the solver tolerance from two starting points.
TEST(BackendOptimizer, OnlineEndsAtTheBatchResult) {
  const Drive d = simulatedDrive(1300, 5);
  const BackendResult batch = optimize(d.graph);
  const OnlineRun run = runOnline(d, BackendConfig{});
  EXPECT_GT(run.reoptimisations, 20);
  ASSERT_GT(run.last_close.poses.size(), d.truth.size() - 20);  // the last loop is near the end
  EXPECT_TRUE(run.last_close.reduced);
  EXPECT_LT(run.last_close.num_poses_solved, static_cast<int>(d.truth.size()) / 3);
  RecordProperty("reduced_vs_batch_m", std::to_string(worstTranslation(run.last_close.poses, batch.poses)));
  RecordProperty("final_vs_batch_m", std::to_string(worstTranslation(run.final.poses, batch.poses)));
  EXPECT_LT(worstTranslation(run.last_close.poses, batch.poses), 0.01);
  EXPECT_EQ(run.last_close.num_rejected, batch.num_rejected);
  EXPECT_EQ(decisions(run.last_close), decisions(batch));
  EXPECT_FALSE(run.final.reduced);
  EXPECT_LT(worstTranslation(run.final.poses, batch.poses), 1e-4);
  EXPECT_EQ(run.final.num_rejected, batch.num_rejected);
}

// With the reduced graph switched off, every closeLoop solves the full graph and also ends at the batch result.
TEST(BackendOptimizer, OnlineOnTheFullGraphEndsAtTheBatchResult) {
  const Drive d = simulatedDrive(1300, 5);
  const BackendResult batch = optimize(d.graph);
  BackendConfig full;
  full.online.reduced_graph = false;
  const OnlineRun run = runOnline(d, full);
  EXPECT_FALSE(run.last_close.reduced);
  EXPECT_EQ(run.last_close.num_poses_solved, static_cast<int>(run.last_close.poses.size()));
  EXPECT_LT(worstTranslation(run.last_close.poses, batch.poses), 1e-4);
  EXPECT_EQ(run.last_close.num_rejected, batch.num_rejected);
}

TEST(BackendOptimizer, OnlineIsIdenticalAtOneAndTwoThreadsAndOnRerun) {
  const Drive d = simulatedDrive(1000, 5);
  BackendConfig one, two;
  one.solver.num_threads = 1;
  two.solver.num_threads = 2;
  const OnlineRun a = runOnline(d, one);
  const OnlineRun b = runOnline(d, two);
  const OnlineRun c = runOnline(d, one);
  EXPECT_TRUE(samePoses(a.last_close.poses, b.last_close.poses));
  EXPECT_TRUE(samePoses(a.last_close.poses, c.last_close.poses));
  EXPECT_TRUE(samePoses(a.final.poses, b.final.poses));
  EXPECT_TRUE(samePoses(a.final.poses, c.final.poses));
}

// The warm start from the reduced graph changes the starting point of the full solve only.
TEST(BackendOptimizer, BatchWithAndWithoutTheReducedWarmStartAgree) {
  const Drive d = simulatedDrive(1300, 5);
  BackendConfig cold;
  cold.solver.reduced_warm_start = false;
  const BackendResult warm_result = optimize(d.graph);
  const BackendResult cold_result = optimize(d.graph, cold);
  EXPECT_LT(worstTranslation(warm_result.poses, cold_result.poses), 1e-4);
  EXPECT_EQ(warm_result.num_rejected, cold_result.num_rejected);
  EXPECT_EQ(warm_result.solves, cold_result.solves + 1);
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
