#include "sgtllc/detector.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "sgtllc/parallel.h"
#include "sgtllc/retrieval/retrieval_key.h"
#include "sgtllc/selection.h"

namespace sgtllc {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const Config& validated(const Config& config) {
  config.validate();
  return config;
}

}  // namespace

LoopDetector::LoopDetector(const Config& config)
    : config_(validated(config)),  // before the extractor reads the class set
      extractor_(config.cluster, effectiveLabelConfig(config), config.graph.max_nodes, config.threads),
      database_(config.retrieval.method),
      clouds_(config.registration, effectiveLabelConfig(config)) {
}

int LoopDetector::firstSearchedFrame() const {
  return std::max(config_.retrieval.exclude_recent, config_.retrieval.warmup_frames);
}

FrameResult LoopDetector::process(const LabeledCloud& cloud) {
  FrameResult result;
  const auto start = Clock::now();
  NodeExtractionResult extracted = extractor_.extract(cloud);
  result.timing.extraction_ms = msSince(start);
  result.extraction = extracted.stats;
  const auto refine_start = Clock::now();
  RegistrationClouds clouds = clouds_.prepare(cloud);
  const double prepare_ms = msSince(refine_start);
  const ExtractionStats stats = result.extraction;
  const double extraction_ms = result.timing.extraction_ms;
  result = process(std::move(extracted.nodes), std::move(clouds));
  result.extraction = stats;
  result.timing.extraction_ms = extraction_ms;
  result.timing.refinement_ms += prepare_ms;
  return result;
}

FrameResult LoopDetector::process(std::vector<Node> nodes) { return process(std::move(nodes), RegistrationClouds{}); }

FrameResult LoopDetector::process(std::vector<Node> nodes, RegistrationClouds clouds) {
  FrameResult result = processNodes(std::move(nodes), FrameResult{});
  // Only the declared loop is refined (issue 13 item 4), against the stored cloud of its frame.
  if (result.is_loop && clouds_.enabled() && !clouds.query.empty()) {
    const auto start = Clock::now();
    Candidate& loop = result.candidates[static_cast<size_t>(result.best)];
    loop.refinement = clouds_.refine(clouds.query, loop.frame, loop.match.T_match_query);
    if (loop.refinement && loop.refinement->used()) loop.match.T_match_query = loop.refinement->T_match_query;
    result.timing.refinement_ms = msSince(start);
  }
  clouds_.add(std::move(clouds.match));  // empty for node input: that frame's loops keep the SVD pose
  return result;
}

FrameResult LoopDetector::processNodes(std::vector<Node> nodes, FrameResult result) {
  result.frame = database_.size();
  auto start = Clock::now();
  const DescribedFrame query = describeFrame(std::move(nodes), config_.graph, config_.descriptor,
                                              /*with_global=*/false, config_.numClasses());
  std::vector<float> key = retrieval::computeRetrievalKey(query.graph, config_);
  result.num_nodes = query.numNodes();
  result.timing.description_ms = msSince(start);

  // Query q sees frames 0 … q − G only (algorithm §5 [CHOICE]), and none before the warm-up.
  start = Clock::now();
  const RetrievalConfig& rc = config_.retrieval;
  std::vector<RetrievedFrame> retrieved;
  if (result.frame < rc.warmup_frames) {
    result.search = Search::kWarmup;
  } else if (result.frame < rc.exclude_recent) {
    result.search = Search::kTooRecent;
  } else {
    retrieved = database_.query(key, result.frame - rc.exclude_recent, rc.num_candidates);
  }
  result.timing.retrieval_ms = msSince(start);

  // Candidates are verified in ascending frame index (algorithm §5); each writes only its own slot.
  start = Clock::now();
  std::sort(retrieved.begin(), retrieved.end(), [](const auto& a, const auto& b) { return a.frame < b.frame; });
  result.candidates.resize(retrieved.size());
  parallelFor(static_cast<int>(retrieved.size()), config_.threads, [&](int c) {
    Candidate& cand = result.candidates[c];
    cand.frame = retrieved[c].frame;
    cand.distance2 = retrieved[c].distance2;
    const DescribedFrame candidate =
        describeFrame(database_.nodes(cand.frame), config_.graph, config_.descriptor, /*with_global=*/false,
                      config_.numClasses());
    cand.match = matchFrames(query, candidate, config_);
  });
  std::vector<const MatchResult*> matches;
  for (const Candidate& cand : result.candidates) matches.push_back(&cand.match);
  result.best = selectCandidate(matches, config_.verification);
  result.lateral = result.best >= 0 && isLateral(result.candidates[result.best].match, config_.verification);
  result.is_loop = result.best >= 0 && isLoop(result.candidates[result.best].match, config_.verification);
  result.timing.verification_ms = msSince(start);

  database_.add(StoredFrame{query.graph.nodes, std::move(key)});
  return result;
}

PairResult comparePair(const LabeledCloud& query, const LabeledCloud& match, const Config& config) {
  config.validate();
  const NodeExtractor extractor(config.cluster, effectiveLabelConfig(config), config.graph.max_nodes, config.threads);
  const auto start = Clock::now();
  NodeExtractionResult q = extractor.extract(query);
  NodeExtractionResult m = extractor.extract(match);
  const double extraction_ms = msSince(start);
  PairResult result = comparePair(std::move(q.nodes), std::move(m.nodes), config);
  result.extraction_query = q.stats;
  result.extraction_match = m.stats;
  result.timing.extraction_ms = extraction_ms;
  if (config.registration.pair && result.match.rejection == Rejection::kNone) {
    const auto refine_start = Clock::now();
    const LabelMap labels(effectiveLabelConfig(config));
    refinePair(&result, queryPoints(query, labels, config.registration), matchPoints(match, labels, config.registration),
               config);
    result.timing.refinement_ms = msSince(refine_start);
  }
  return result;
}

PairResult comparePair(std::vector<Node> query, std::vector<Node> match, const Config& config) {
  config.validate();
  PairResult result;
  auto start = Clock::now();
  const int num_classes = config.numClasses();
  const DescribedFrame q = describeFrame(std::move(query), config.graph, config.descriptor, true, num_classes);
  const DescribedFrame m = describeFrame(std::move(match), config.graph, config.descriptor, true, num_classes);
  result.timing.description_ms = msSince(start);
  start = Clock::now();
  result.match = matchFrames(q, m, config);
  result.timing.verification_ms = msSince(start);
  result.query_nodes = q.graph.nodes;
  result.match_nodes = m.graph.nodes;
  result.is_loop = isLoop(result.match, config.verification);
  return result;
}

void refinePair(PairResult* result, const std::vector<Eigen::Vector3f>& query_points,
                const std::vector<Eigen::Vector3f>& match_points, const Config& config) {
  if (!config.registration.pair || result->match.rejection != Rejection::kNone) return;
  result->refinement = refinePose(query_points, match_points, result->match.T_match_query, config.registration);
  if (result->refinement->used()) result->match.T_match_query = result->refinement->T_match_query;
}

}  // namespace sgtllc
