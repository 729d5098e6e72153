// Pose-graph back end on a KITTI 00-sized graph (4,541 poses): a simulated 1 m-per-frame urban drive
// (tests/test_backend_support.h) with drifting odometry, a loop every 10th revisiting frame and 5 % false loops.
//   build/bench/sgtllc_bench_backend --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "sgtllc/backend/information.h"
#include "sgtllc/backend/pose_graph_optimizer.h"
#include "test_backend_support.h"

namespace {

using namespace sgtllc;
using namespace sgtllc::backend;

constexpr int kFrames = 4541;

struct Scenario {
  std::vector<Eigen::Isometry3d> odometry;
  std::vector<Edge> loops;  ///< true then false, each sorted by query frame below
};

const Scenario& scenario() {
  static const Scenario s = [] {
    Scenario out;
    const BackendConfig config;
    const std::vector<Eigen::Isometry3d> truth = test::urbanTrajectory(kFrames);
    out.odometry = test::driftingOdometry(truth, 11);
    out.loops = test::trueLoops(truth, 12, config.loops);
    const std::vector<Edge> wrong =
        test::falseLoops(truth, static_cast<int>(out.loops.size() + 19) / 20, 13, config.loops);
    out.loops.insert(out.loops.end(), wrong.begin(), wrong.end());
    std::stable_sort(out.loops.begin(), out.loops.end(),
                     [](const Edge& a, const Edge& b) { return std::max(a.from, a.to) < std::max(b.from, b.to); });
    return out;
  }();
  return s;
}

void BM_BatchOptimize(benchmark::State& state) {
  const Scenario& s = scenario();
  PoseGraph graph = odometryGraph(s.odometry, OdometryNoise{});
  graph.edges.insert(graph.edges.end(), s.loops.begin(), s.loops.end());
  BackendResult r;
  for (auto _ : state) {
    r = optimize(graph);
    benchmark::DoNotOptimize(r.poses.data());
  }
  state.counters["loops"] = static_cast<double>(r.loops.size());
  state.counters["rejected"] = r.num_rejected;
  state.counters["iterations"] = r.iterations;
}
BENCHMARK(BM_BatchOptimize)->Unit(benchmark::kMillisecond);

// One online re-optimisation: every loop but the last already optimised, then the last loop arrives.
void BM_OnlineCloseLoop(benchmark::State& state) {
  const Scenario& s = scenario();
  PoseGraphOptimizer before;
  for (size_t i = 1; i < s.odometry.size(); ++i) before.addOdometry(s.odometry[i - 1].inverse() * s.odometry[i]);
  for (size_t k = 0; k + 1 < s.loops.size(); ++k) before.addLoop(s.loops[k]);
  before.optimize();
  int iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    PoseGraphOptimizer online = before;
    state.ResumeTiming();
    iterations = online.closeLoop(s.loops.back()).iterations;
  }
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_OnlineCloseLoop)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
