// Retrieval at scale (algorithm §5 "Retrieval at scale"): a database of N frames made from the bundled
// real scans' node sets (tests/test_places_support.h: crops of real frames, five jittered visits each), searched
// with retrieval.method ivf against the exact scan. Prints build time, peak memory, the inverted file's size, and
// per-query time (median, p99; one thread) and the share of the exact top-15 found, for each probe count.
// Run: build/bench/sgtllc_bench_scale FRAMES [--save MAP] [PROBE ...]   (BENCHMARKS.md "Retrieval at scale")
//      build/bench/sgtllc_bench_scale --load MAP [PROBE ...]   (load time and peak memory of a saved map, and its
//      queries: new visits of every 5,000th map frame)
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "sgtllc/database.h"
#include "sgtllc/map/map_file.h"
#include "sgtllc/node_extraction.h"
#include "test_places_support.h"
#include "test_kitti_support.h"

namespace {

using namespace sgtllc;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// CPU time of the calling thread (ms): the machine may be shared, and a query runs on one thread.
double threadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

/// Peak resident memory of this process (MB), from /proc/self/status.
double peakMb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size())))];
}

/// Each probe count's query time and share of the exact top-15 (@p truth) over @p queries, searched in @p db
/// itself (no copy of its keys: the peak memory stays the database's).
void sweep(FrameDatabase& db, const IvfState& state, const std::vector<std::vector<float>>& queries,
           const std::vector<std::vector<RetrievedFrame>>& truth, const std::vector<int>& probes) {
  for (int probe : probes) {
    RetrievalConfig r;
    r.method = RetrievalMethod::kIvf;
    r.ivf_train_frames = state.trained_frames;
    r.ivf_probe = probe;
    db.setSearch(r, 1);
    db.restoreIvf(state);
    db.query(queries.front(), db.size() - 1, 15);  // untimed: the first query makes the lists' codes
    std::vector<double> ms;
    std::vector<double> cpu_ms;
    long found = 0;
    long wanted = 0;
    for (size_t q = 0; q < queries.size(); ++q) {
      const auto t = Clock::now();
      const double cpu = threadCpuMs();
      const auto hits = db.query(queries[q], db.size() - 1, 15);
      cpu_ms.push_back(threadCpuMs() - cpu);
      ms.push_back(since(t) * 1e3);
      for (const auto& h : hits) {
        found += std::any_of(truth[q].begin(), truth[q].end(), [&](const RetrievedFrame& e) { return e.frame == h.frame; });
      }
      wanted += static_cast<long>(truth[q].size());
    }
    std::printf("ivf probe %3d: CPU median %.2f ms, p99 %.2f ms; wall median %.2f ms per query; exact top-15 "
                "found %.4f\n", probe, percentile(cpu_ms, 0.5), percentile(cpu_ms, 0.99), percentile(ms, 0.5),
                static_cast<double>(found) / wanted);
  }
}

/// The exact top-15 of each query, searched by the exact scan of @p db's own keys, timed. Leaves @p db searching
/// exactly; sweep() puts the inverted file back.
std::vector<std::vector<RetrievedFrame>> exactTop15(FrameDatabase& db, const std::vector<std::vector<float>>& queries) {
  db.setSearch(RetrievalConfig{}, 1);
  std::vector<std::vector<RetrievedFrame>> truth;
  std::vector<double> exact_ms;
  std::vector<double> exact_cpu;
  for (const auto& q : queries) {
    const auto t = Clock::now();
    const double cpu = threadCpuMs();
    truth.push_back(db.query(q, db.size() - 1, 15));
    exact_cpu.push_back(threadCpuMs() - cpu);
    exact_ms.push_back(since(t) * 1e3);
  }
  std::printf("exact scan: CPU median %.2f ms, p99 %.2f ms; wall median %.2f ms per top-15 query\n",
              percentile(exact_cpu, 0.5), percentile(exact_cpu, 0.99), percentile(exact_ms, 0.5));
  return truth;
}

RetrievalConfig ivfRetrieval(long frames) {
  RetrievalConfig retrieval;
  retrieval.method = RetrievalMethod::kIvf;
  retrieval.ivf_train_frames = static_cast<int>(std::min<long>(frames, 1000000));
  return retrieval;
}

void saveMap(const FrameDatabase& db, const std::string& path) {
  Config config;
  config.retrieval = ivfRetrieval(db.size());
  std::vector<std::string> names(static_cast<size_t>(db.size()));
  for (size_t f = 0; f < names.size(); ++f) names[f] = std::to_string(f);
  auto t = Clock::now();
  const map::Map m = map::makeMap(db, config, names);
  const double make_s = since(t);
  t = Clock::now();
  map::writeMapFile(path, m, io::Overwrite::kReplace);
  std::printf("map %s: %.1f MB written in %.1f s (copied into the map in %.1f s)\n", path.c_str(),
              static_cast<double>(std::filesystem::file_size(path)) / 1e6, since(t), make_s);
}

/// --load: the saved map's load time and peak memory, then its queries.
int loadMap(const std::string& path, const std::vector<int>& probes) {
  Config config;
  config.retrieval = ivfRetrieval(1000000);
  const auto t = Clock::now();
  map::Map m = map::readMapFile(path, config);
  std::printf("map %s: %d frames loaded in %.2f s; peak memory %.0f MB\n", path.c_str(), m.size(), since(t), peakMb());
  const std::optional<IvfState> state = m.database.ivfState();
  if (!state) {
    std::fprintf(stderr, "%s holds no inverted file\n", path.c_str());
    return 1;
  }
  std::mt19937 rng(11);
  std::vector<std::vector<float>> queries;
  for (int f = 0; f < m.size(); f += std::max(1, m.size() / 200)) {
    queries.push_back(test::keyOf(test::visit(m.database.nodes(f), rng), config));
  }
  sweep(m.database, *state, queries, exactTop15(m.database, queries), probes);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FRAMES [--save MAP] [PROBE ...] | --load MAP [PROBE ...]\n", argv[0]);
    return 2;
  }
  const bool loading = std::string(argv[1]) == "--load";
  if (loading && argc < 3) {
    std::fprintf(stderr, "--load needs a map file\n");
    return 2;
  }
  std::string save;
  std::vector<int> probes;
  for (int a = loading ? 3 : 2; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--save" && a + 1 < argc) {
      save = argv[++a];
    } else {
      probes.push_back(std::stoi(arg));
    }
  }
  if (probes.empty()) probes = {8, 16, 32};
  if (loading) return loadMap(argv[2], probes);
  const long frames = std::stol(argv[1]);

  const Config config;
  const NodeExtractor extractor(config.cluster, config.labels);
  std::vector<std::vector<Node>> real;
  for (const char* f : {"000052", "004501", "000088", "000850"}) real.push_back(extractor.extract(test::kittiScan(f)).nodes);

  FrameDatabase db(ivfRetrieval(frames), 2);
  std::mt19937 rng(7);
  std::vector<std::vector<float>> queries;
  auto t = Clock::now();
  size_t nodes = 0;
  for (long p = 0; db.size() < frames; ++p) {
    const std::vector<Node> place = test::cropPlace(real[p % 4], rng);
    for (int v = 0; v < 5 && db.size() < frames; ++v) {
      std::vector<Node> seen = test::visit(place, rng);
      nodes += seen.size();
      std::vector<float> key = test::keyOf(seen, config);
      db.add(StoredFrame{std::move(seen), std::move(key)});
    }
    if (p % (frames / 1000 + 1) == 0 && queries.size() < 200) queries.push_back(test::keyOf(test::visit(place, rng), config));
  }
  std::printf("frames %d, nodes per frame %.1f, key %d floats; made in %.1f s\n", db.size(),
              static_cast<double>(nodes) / db.size(), db.globalDimension(), since(t));

  t = Clock::now();
  db.query(queries[0], db.size() - 1, 15);  // trains and files every frame
  const IvfState state = *db.ivfState();
  std::printf("inverted file: %d lists, trained and filled in %.1f s (2 threads); %.1f MB saved, %.1f MB of codes; "
              "peak memory %.0f MB\n", state.lists, since(t),
              (state.centroids.size() * 4.0 + state.list_of_frame.size() * 4.0) / 1e6,
              static_cast<double>(db.size()) * db.globalDimension() / 1e6, peakMb());

  const std::vector<std::vector<RetrievedFrame>> truth = exactTop15(db, queries);
  sweep(db, state, queries, truth, probes);
  std::printf("peak memory %.0f MB\n", peakMb());
  if (!save.empty()) saveMap(db, save);
  return 0;
}
