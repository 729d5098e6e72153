// Retrieval at scale (issue 10, algorithm §5 "Retrieval at scale"): a database of N frames made from the bundled
// real scans' node sets (tests/test_places_support.h: crops of real frames, five jittered visits each), searched
// with retrieval.method ivf against the exact scan. Prints build time, peak memory, the inverted file's size, and
// per-query time (median, p99; one thread) and the share of the exact top-15 found, for each probe count.
// Run: build/bench/sgtllc_bench_scale FRAMES [PROBE ...]   (BENCHMARKS.md "Retrieval at scale")
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "sgtllc/database.h"
#include "sgtllc/node_extraction.h"
#include "test_places_support.h"
#include "test_support.h"

namespace {

using namespace sgtllc;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FRAMES [PROBE ...]\n", argv[0]);
    return 2;
  }
  const long frames = std::stol(argv[1]);
  std::vector<int> probes;
  for (int a = 2; a < argc; ++a) probes.push_back(std::stoi(argv[a]));
  if (probes.empty()) probes = {8, 16, 32, 64};

  const Config config;
  const NodeExtractor extractor(config.cluster, config.labels);
  std::vector<std::vector<Node>> real;
  for (const char* f : {"000052", "004501", "000088", "000850"}) real.push_back(extractor.extract(test::kittiScan(f)).nodes);

  RetrievalConfig retrieval;
  retrieval.method = RetrievalMethod::kIvf;
  retrieval.ivf_train_frames = static_cast<int>(std::min<long>(frames, 1000000));
  FrameDatabase db(retrieval, 2);
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
  std::printf("inverted file: %d lists, trained and filled in %.1f s (2 threads); %.1f MB; peak memory %.0f MB\n",
              state.lists, since(t), (state.centroids.size() * 4.0 + state.list_of_frame.size() * 4.0) / 1e6, peakMb());

  RetrievalConfig exact_config;
  FrameDatabase exact(exact_config);
  for (int f = 0; f < db.size(); ++f) {
    exact.add(StoredFrame{{}, std::vector<float>(db.global(f), db.global(f) + db.globalDimension())});
  }
  std::vector<std::vector<RetrievedFrame>> truth;
  std::vector<double> exact_ms;
  for (const auto& q : queries) {
    t = Clock::now();
    truth.push_back(exact.query(q, exact.size() - 1, 15));
    exact_ms.push_back(since(t) * 1e3);
  }
  std::printf("exact scan: median %.2f ms, p99 %.2f ms per top-15 query\n", percentile(exact_ms, 0.5),
              percentile(exact_ms, 0.99));

  for (int probe : probes) {
    RetrievalConfig r = retrieval;
    r.ivf_probe = probe;
    FrameDatabase probed(r, 1);
    for (int f = 0; f < db.size(); ++f) {
      probed.add(StoredFrame{{}, std::vector<float>(db.global(f), db.global(f) + db.globalDimension())});
    }
    probed.restoreIvf(state);
    std::vector<double> ms;
    long found = 0;
    long wanted = 0;
    for (size_t q = 0; q < queries.size(); ++q) {
      t = Clock::now();
      const auto hits = probed.query(queries[q], probed.size() - 1, 15);
      ms.push_back(since(t) * 1e3);
      for (const auto& h : hits) {
        found += std::any_of(truth[q].begin(), truth[q].end(), [&](const RetrievedFrame& e) { return e.frame == h.frame; });
      }
      wanted += static_cast<long>(truth[q].size());
    }
    std::printf("ivf probe %3d: median %.2f ms, p99 %.2f ms per query; exact top-15 found %.4f\n", probe,
                percentile(ms, 0.5), percentile(ms, 0.99), static_cast<double>(found) / wanted);
  }
  return 0;
}
