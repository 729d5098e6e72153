// Online latency: LoopDetector::process on each scan of a sequence in turn, as a robot calls it, with every worker
// thread on the one frame (`sgtllc eval` instead extracts several frames at once, one thread each, for throughput).
// Reading is not timed. Prints the median and p99 of the frame (extraction + description + retrieval +
// verification) and each stage's median. Written against the API of the speed baseline too, so that the baseline
// can be timed by the same source (BENCHMARKS.md "Time per frame").
//
// Run: build/bench/sgtllc_bench_online SEQ [THREADS] [FRAMES]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "sgtllc/detector.h"
#include "sgtllc/io/sequence.h"

namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SEQ [THREADS] [FRAMES]\n", argv[0]);
    return 2;
  }
  const sgtllc::io::SequenceDir seq(argv[1]);
  sgtllc::Config config;
  config.threads = argc > 2 ? std::atoi(argv[2]) : 1;
  const size_t frames = argc > 3 ? std::min<size_t>(seq.size(), std::strtoul(argv[3], nullptr, 10)) : seq.size();
  sgtllc::LoopDetector detector(config);
  std::vector<double> total, extraction, description, retrieval, verification;
  int loops = 0;
  for (size_t i = 0; i < frames; ++i) {
    const sgtllc::LabeledCloud cloud = seq.load(i);
    const sgtllc::FrameResult r = detector.process(cloud);
    const auto& t = r.timing;
    total.push_back(t.extraction_ms + t.description_ms + t.retrieval_ms + t.verification_ms);
    extraction.push_back(t.extraction_ms);
    description.push_back(t.description_ms);
    retrieval.push_back(t.retrieval_ms);
    verification.push_back(t.verification_ms);
    loops += r.loop() ? 1 : 0;
  }
  std::printf("frames %zu threads %d loops %d | frame median %.3f ms p99 %.3f | extraction %.3f description %.3f "
              "retrieval %.3f verification %.3f\n",
              frames, config.threads, loops, percentile(total, 0.5), percentile(total, 0.99), percentile(extraction, 0.5),
              percentile(description, 0.5), percentile(retrieval, 0.5), percentile(verification, 0.5));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "sgtllc_bench_online: %s\n", e.what());
  return 1;
}
