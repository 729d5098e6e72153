// Per-stage timing on the bundled KITTI 00 scans (one thread) and stored bytes per frame.
// Run: build/bench/sgtllc_bench  (see BENCHMARKS.md for the figures and the machine).
#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <string>

#include <Eigen/Geometry>

#include "sgtllc/detector.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/retrieval/retrieval_key.h"

namespace {

using namespace sgtllc;

const char* const kFrames[] = {"000052", "004501", "000088", "000850"};

std::string binPath(const std::string& f) { return std::string(SGTLLC_DATA_DIR) + "/kitti/00/velodyne/" + f + ".bin"; }
std::string labelPath(const std::string& f) {
  return std::string(SGTLLC_DATA_DIR) + "/kitti/00/labels/" + f + ".label";
}

const LabeledCloud& scan(int k) {
  static std::map<int, LabeledCloud> cache;
  auto it = cache.find(k);
  if (it == cache.end()) it = cache.emplace(k, io::readLabeledScan(binPath(kFrames[k]), labelPath(kFrames[k]))).first;
  return it->second;
}

std::vector<Node> nodesOf(int k) { return NodeExtractor(Config{}.cluster, Config{}.labels).extract(scan(k)).nodes; }

/// A plausible other visit of a place: the nodes moved rigidly, jittered by a few cm, a tenth of them dropped.
std::vector<Node> perturbed(const std::vector<Node>& nodes, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> jitter(0.0, 0.05);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI * u(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d t(20 * u(rng), 20 * u(rng), u(rng));
  std::vector<Node> out;
  for (const Node& n : nodes) {
    if (u(rng) > 0.8) continue;
    out.push_back(Node{R * n.centre + t + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)), n.label});
  }
  return out;
}

void BM_LoadScan(benchmark::State& state) {
  const std::string f = kFrames[state.range(0)];
  for (auto _ : state) benchmark::DoNotOptimize(io::readLabeledScan(binPath(f), labelPath(f)));
  state.SetLabel(f);
}
BENCHMARK(BM_LoadScan)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_ExtractNodes(benchmark::State& state) {
  const LabeledCloud& cloud = scan(static_cast<int>(state.range(0)));
  const NodeExtractor extractor(Config{}.cluster, Config{}.labels);
  size_t nodes = 0;
  for (auto _ : state) nodes = extractor.extract(cloud).nodes.size();
  state.counters["points"] = static_cast<double>(cloud.points.size());
  state.counters["nodes"] = static_cast<double>(nodes);
  state.SetLabel(kFrames[state.range(0)]);
}
BENCHMARK(BM_ExtractNodes)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_DescribeFrame(benchmark::State& state) {
  const std::vector<Node> nodes = nodesOf(static_cast<int>(state.range(0)));
  const Config config;
  for (auto _ : state) benchmark::DoNotOptimize(describeFrame(nodes, config.graph, config.descriptor));
  state.SetLabel(kFrames[state.range(0)]);
}
BENCHMARK(BM_DescribeFrame)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

/// Node extraction + descriptors of one scan: the per-frame front end (target ≤ 5 ms).
void BM_ExtractAndDescribe(benchmark::State& state) {
  const LabeledCloud& cloud = scan(static_cast<int>(state.range(0)));
  const Config config;
  const NodeExtractor extractor(config.cluster, config.labels);
  for (auto _ : state) {
    benchmark::DoNotOptimize(describeFrame(extractor.extract(cloud).nodes, config.graph, config.descriptor));
  }
  state.SetLabel(kFrames[state.range(0)]);
}
BENCHMARK(BM_ExtractAndDescribe)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

std::string keyName(int key) { return key == 0 ? "histogram" : "global"; }

/// Top-15 retrieval in a database the size of KITTI 00 (4541 frames) built from perturbed real node sets.
/// range(1): 0 brute force, 1 kd-tree; range(2): 0 the distance-histogram key (default), 1 Des^G (G2).
void BM_Retrieval(benchmark::State& state) {
  Config c;
  c.retrieval.method = static_cast<RetrievalMethod>(state.range(1));
  c.retrieval.key = state.range(2) == 0 ? RetrievalKey::kDistanceHistogram : RetrievalKey::kGlobalDescriptor;
  std::mt19937 rng(7);
  FrameDatabase db(c.retrieval.method);
  std::vector<std::vector<Node>> base;
  for (int k = 0; k < 4; ++k) base.push_back(nodesOf(k));
  for (int f = 0; f < state.range(0); ++f) {
    const SemanticGraph g = buildGraph(perturbed(base[f % 4], rng), c.graph);
    db.add(StoredFrame{g.nodes, retrieval::computeRetrievalKey(g, c)});
  }
  const std::vector<float> query = retrieval::computeRetrievalKey(buildGraph(base[1], c.graph), c);
  const int last = db.size() - 1;
  db.query(query, last, 15);  // builds the kd-tree outside the timed loop
  for (auto _ : state) benchmark::DoNotOptimize(db.query(query, last, 15));
  state.SetLabel(std::string(state.range(1) == 0 ? "brute_force" : "kdtree") + ", " + keyName(state.range(2)));
}
BENCHMARK(BM_Retrieval)
    ->Args({4541, 0, 0})
    ->Args({4541, 0, 1})
    ->Args({4541, 1, 0})
    ->Args({4541, 1, 1})
    ->Unit(benchmark::kMicrosecond);

/// Computing a frame's retrieval key from its graph: range(1) as BM_Retrieval's range(2).
void BM_RetrievalKey(benchmark::State& state) {
  Config c;
  c.retrieval.key = state.range(1) == 0 ? RetrievalKey::kDistanceHistogram : RetrievalKey::kGlobalDescriptor;
  const SemanticGraph g = buildGraph(nodesOf(static_cast<int>(state.range(0))), c.graph);
  for (auto _ : state) benchmark::DoNotOptimize(retrieval::computeRetrievalKey(g, c));
  state.counters["nodes"] = g.size();
  state.SetLabel(std::string(kFrames[state.range(0)]) + ", " + keyName(state.range(1)));
}
BENCHMARK(BM_RetrievalKey)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMicrosecond);

/// Verifying 15 candidates of query 4501 as the detector does: rebuilding each candidate's descriptors from its
/// stored nodes, association, gates, RANSAC, pose. range(0) = 0: the true match 000052 plus 14 other places
/// (realistic: most fail the gates); 1: 15 perturbed copies of 000052 (worst case: every candidate runs RANSAC).
/// range(1) = 1: all 500 RANSAC iterations (ransac_confidence 1, as the authors' code).
void BM_Verify15(benchmark::State& state) {
  Config config;
  if (state.range(1) == 1) config.verification.ransac_confidence = 1.0;
  std::mt19937 rng(11);
  const DescribedFrame query = describeFrame(nodesOf(1), config.graph, config.descriptor);
  std::vector<std::vector<Node>> candidates;
  const std::vector<Node> match = nodesOf(0);
  candidates.push_back(match);
  const std::vector<Node> others[] = {nodesOf(2), nodesOf(3)};
  while (candidates.size() < 15) {
    candidates.push_back(state.range(0) == 0 ? perturbed(others[candidates.size() % 2], rng) : perturbed(match, rng));
  }
  int passed = 0;
  for (auto _ : state) {
    passed = 0;
    for (const auto& nodes : candidates) {
      const DescribedFrame cand = describeFrame(nodes, config.graph, config.descriptor, /*with_global=*/false);
      const MatchResult m = matchFrames(query, cand, config);
      passed += m.rejection == Rejection::kNone;
      benchmark::DoNotOptimize(m);
    }
  }
  state.counters["ransac_runs"] = passed;
  state.SetLabel(std::string(state.range(0) == 0 ? "1 true match + 14 other places" : "15 true matches") +
                 (state.range(1) == 1 ? ", 500 iterations" : ", adaptive"));
}
BENCHMARK(BM_Verify15)->Args({0, 0})->Args({1, 0})->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMillisecond);

/// Bytes the online detector stores per frame, over the four bundled scans.
void BM_StoredBytesPerFrame(benchmark::State& state) {
  double bytes = 0.0;
  for (auto _ : state) {
    LoopDetector detector;
    for (int k = 0; k < 4; ++k) detector.process(scan(k));
    bytes = static_cast<double>(detector.database().totalBytes()) / detector.numFrames();
  }
  state.counters["bytes_per_frame"] = bytes;
}
BENCHMARK(BM_StoredBytesPerFrame)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
