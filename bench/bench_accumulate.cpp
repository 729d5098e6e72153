// Scan accumulation (BENCHMARKS.md, "Accumulating solid-state scans"): the cost per frame of merging the N − 1 previous scans into the new one, for
// Mid-70-sized scans (~7,000 points in the simulator, 10,000 at most). The data do not matter, only the counts.
// Run: build/bench/sgtllc_bench_accumulate  (figures and machine in BENCHMARKS.md).
#include <benchmark/benchmark.h>

#include <random>

#include "sgtllc/accumulate/scan_accumulator.h"

namespace {

using namespace sgtllc;

LabeledCloud randomScan(int points, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-50.0f, 50.0f);
  LabeledCloud c;
  for (int k = 0; k < points; ++k) {
    c.points.emplace_back(u(rng), u(rng), 0.1f * u(rng));
    c.labels.push_back(static_cast<uint32_t>(k % 20));
  }
  return c;
}

/// Args: N (scans per frame), points per scan. One add() per iteration, on a buffer that is already full.
void BM_Accumulate(benchmark::State& state) {
  const int scans = static_cast<int>(state.range(0)), points = static_cast<int>(state.range(1));
  std::mt19937 rng(7);
  const LabeledCloud scan = randomScan(points, rng);
  ScanAccumulator buffer(scans);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d step(Eigen::Translation3d(1.0, 0.0, 0.0) * Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ()));
  for (int k = 0; k < scans; ++k, T = T * step) buffer.add(scan, T);
  size_t merged = 0;
  for (auto _ : state) {
    state.PauseTiming();
    LabeledCloud copy = scan;  // add() takes the scan; the copy is the caller's read, not accumulation
    state.ResumeTiming();
    merged = buffer.add(std::move(copy), T).points.size();
    T = T * step;
    benchmark::DoNotOptimize(merged);
  }
  state.counters["points_out"] = static_cast<double>(merged);
  state.counters["buffer_MB"] = static_cast<double>(buffer.bytes()) / 1e6;
}
BENCHMARK(BM_Accumulate)
    ->Args({1, 10000})
    ->Args({5, 10000})
    ->Args({10, 7000})
    ->Args({10, 10000})
    ->Args({20, 10000})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
