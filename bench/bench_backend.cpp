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

PoseGraph scenarioGraph() {
  const Scenario& s = scenario();
  PoseGraph graph = odometryGraph(s.odometry, OdometryNoise{});
  graph.edges.insert(graph.edges.end(), s.loops.begin(), s.loops.end());
  return graph;
}

// Batch: the whole graph from the odometry. Arg 1: warm-started from the reduced graph (the default); 0: not.
void BM_BatchOptimize(benchmark::State& state) {
  const PoseGraph graph = scenarioGraph();
  BackendConfig config;
  config.solver.reduced_warm_start = state.range(0) != 0;
  BackendResult r;
  for (auto _ : state) {
    r = optimize(graph, config);
    benchmark::DoNotOptimize(r.poses.data());
  }
  state.counters["loops"] = static_cast<double>(r.loops.size());
  state.counters["rejected"] = r.num_rejected;
  state.counters["iterations"] = r.iterations;
}
BENCHMARK(BM_BatchOptimize)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// One online re-optimisation: every loop but the last already closed online, then the last loop arrives.
// Arg 1: closeLoop on the reduced graph (the default); 0: on the full graph.
void BM_OnlineCloseLoop(benchmark::State& state) {
  const Scenario& s = scenario();
  BackendConfig config;
  config.online.reduced_graph = state.range(0) != 0;
  PoseGraphOptimizer before(config);
  for (size_t i = 1; i < s.odometry.size(); ++i) before.addOdometry(s.odometry[i - 1].inverse() * s.odometry[i]);
  for (size_t k = 0; k + 1 < s.loops.size(); ++k) before.addLoop(s.loops[k]);
  if (config.online.reduced_graph) {
    before.optimizeReduced();
  } else {
    before.optimize();
  }
  BackendResult r;
  for (auto _ : state) {
    state.PauseTiming();
    PoseGraphOptimizer online = before;
    state.ResumeTiming();
    r = online.closeLoop(s.loops.back());
  }
  state.counters["iterations"] = r.iterations;
  state.counters["poses_solved"] = r.num_poses_solved;
}
BENCHMARK(BM_OnlineCloseLoop)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// The outlier step's incremental part of a closeLoop: the new loop's consistency with all previous ones (O(n)
// cycles) and the maximum clique over all.
void BM_ConsistencyAddAndClique(benchmark::State& state) {
  const Scenario& s = scenario();
  OdometryChain chain;
  for (size_t i = 1; i < s.odometry.size(); ++i) chain.append(s.odometry[i - 1].inverse() * s.odometry[i]);
  ConsistencyGraph before;
  for (size_t k = 0; k + 1 < s.loops.size(); ++k) before.add(s.loops[k], chain, LoopConsistency{});
  size_t clique = 0;
  for (auto _ : state) {
    state.PauseTiming();
    ConsistencyGraph graph = before;
    state.ResumeTiming();
    graph.add(s.loops.back(), chain, LoopConsistency{});
    clique = graph.maximumClique().size();
  }
  state.counters["clique"] = static_cast<double>(clique);
}
BENCHMARK(BM_ConsistencyAddAndClique)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
