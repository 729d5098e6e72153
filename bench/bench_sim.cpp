// Simulator speed: world generation, one HDL-64E frame, one accumulated Mid-70 frame, and whole sequences written
// to disk at 1 and 2 threads (frames per second). Run: build/bench/sgtllc_bench_sim
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "sgtllc/sim/sequence_writer.h"

namespace {

using namespace sgtllc::sim;

SimConfig urban(int frames, SensorKind sensor = SensorKind::kHdl64) {
  SimConfig c;
  c.frames = frames;
  c.seed = 7;
  c.sensor = SensorConfig::preset(sensor);
  return c;
}

const Simulator& shared(SensorKind sensor) {
  static std::unique_ptr<Simulator> hdl, mid;
  auto& s = sensor == SensorKind::kHdl64 ? hdl : mid;
  if (!s) s = std::make_unique<Simulator>(urban(2000, sensor));
  return *s;
}

/// World, route and trajectory of a 2,000-frame urban sequence.
void BM_GenerateUrbanWorld(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(Simulator(urban(2000)).numFrames());
}
BENCHMARK(BM_GenerateUrbanWorld)->Unit(benchmark::kMillisecond);

/// One HDL-64E frame (ray casting, noise, label errors) on one thread.
void BM_Hdl64Frame(benchmark::State& state) {
  const Simulator& sim = shared(SensorKind::kHdl64);
  int i = 0;
  size_t points = 0;
  for (auto _ : state) {
    points = sim.frame(i).points.size();
    i = (i + 97) % sim.numFrames();
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Hdl64Frame)->Unit(benchmark::kMillisecond);

/// One Livox Mid-70 frame: 10 raw scans of 10,000 rays merged.
void BM_Mid70Frame(benchmark::State& state) {
  const Simulator& sim = shared(SensorKind::kMid70);
  int i = 10;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sim.frame(i).points.size());
    i = 10 + (i + 97) % (sim.numFrames() - 10);
  }
}
BENCHMARK(BM_Mid70Frame)->Unit(benchmark::kMillisecond);

/// 100 HDL-64E frames written to disk (files, loop pairs, previews, node statistics) at range(0) threads.
void BM_WriteSequence(benchmark::State& state) {
  const Simulator sim(urban(100));
  const std::string dir = (std::filesystem::temp_directory_path() / "sgtllc_bench_sim").string();
  for (auto _ : state) {
    WriteOptions o;
    o.dir = dir;
    o.threads = static_cast<int>(state.range(0));
    o.force = true;
    benchmark::DoNotOptimize(writeSequence(sim, o).frames);
  }
  std::filesystem::remove_all(dir);
  state.counters["frames/s"] =
      benchmark::Counter(100.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WriteSequence)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
