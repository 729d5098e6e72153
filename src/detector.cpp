#include "sgtllc/detector.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "internal/described_cache.h"
#include "internal/squared_distance.h"
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

/// Frames whose descriptions the online detector keeps (internal/described_cache.h). A frame's description is
/// ~0.7 KB per node (49 slots, DescriptorConfig) plus its graph, so ~30 KB for 40 nodes and ~8 MB when full;
/// the urban and suburban simulations' queries find ~85 % of their candidates here.
constexpr size_t kDescribedCacheFrames = 256;

/// The stored frames' footprints (LoopDetector::footprints, a map's Map::footprints) where the searcher has them.
using Footprints = std::vector<Footprint>;

void search(const DescribedFrame& query, const std::vector<float>& key, const FrameDatabase& database, int last,
            const Config& config, FrameResult* result, internal::DescribedCache* cache, const Footprints* footprints);

}  // namespace

LoopDetector::LoopDetector(const Config& config)
    : config_(validated(config)),  // before the extractor reads the class set
      extractor_(config.cluster, effectiveLabelConfig(config), config.graph.max_nodes, config.threads),
      database_(config.retrieval, config.threads),
      clouds_(config.registration, effectiveLabelConfig(config)),
      described_(std::make_unique<internal::DescribedCache>(kDescribedCacheFrames)) {
}

LoopDetector::~LoopDetector() = default;
LoopDetector::LoopDetector(LoopDetector&&) noexcept = default;
LoopDetector& LoopDetector::operator=(LoopDetector&&) noexcept = default;

LoopDetector::LoopDetector(const Config& config, FrameDatabase database, std::vector<Footprint> footprints)
    : LoopDetector(config) {
  if (!footprints.empty() && footprints.size() != static_cast<size_t>(database.size())) {
    throw Error("LoopDetector: " + std::to_string(footprints.size()) + " footprints for " +
                std::to_string(database.size()) + " frames");
  }
  if (database.size() > 0 && database.globalDimension() != retrieval::retrievalKeySize(config_)) {
    throw Error("LoopDetector: the database's keys have " + std::to_string(database.globalDimension()) +
                " entries, the configuration's " + std::to_string(retrieval::retrievalKeySize(config_)) +
                " (retrieval.key, histogram_bins or the class set differ)");
  }
  database_ = std::move(database);
  database_.setSearch(config_.retrieval, config_.threads);
  // The resumed frames have no registration clouds: their loops keep the SVD pose (as frames given as nodes).
  for (int f = 0; f < database_.size(); ++f) clouds_.add(CompactCloud{});
  footprints_ = std::move(footprints);
  footprints_.resize(static_cast<size_t>(database_.size()));  // none given: their candidates go unchecked
  footprint_bytes_ = 0;
  for (const Footprint& f : footprints_) footprint_bytes_ += sizeof(Footprint) + f.bytes();
}

Footprint LoopDetector::footprint(const LabeledCloud& cloud) const {
  return computeFootprint(cloud, extractor_.labelMap(), config_.verification);
}

int LoopDetector::firstSearchedFrame() const {
  return std::max(config_.retrieval.exclude_recent, config_.retrieval.warmup_frames);
}

FrameResult LoopDetector::process(const LabeledCloud& cloud) {
  FrameResult result;
  const auto start = Clock::now();
  Footprint footprint;
  NodeExtractionResult extracted = extractor_.extract(cloud, config_.verification, &footprint);
  result.timing.extraction_ms = msSince(start);
  result.extraction = extracted.stats;
  const auto refine_start = Clock::now();
  RegistrationClouds clouds = clouds_.prepare(cloud);
  const double prepare_ms = msSince(refine_start);
  const ExtractionStats stats = result.extraction;
  const double extraction_ms = result.timing.extraction_ms;
  result = process(std::move(extracted.nodes), std::move(clouds), std::move(footprint));
  result.extraction = stats;
  result.timing.extraction_ms = extraction_ms;
  result.timing.refinement_ms += prepare_ms;
  return result;
}

FrameResult LoopDetector::process(std::vector<Node> nodes) { return process(std::move(nodes), RegistrationClouds{}); }

FrameResult LoopDetector::process(std::vector<Node> nodes, RegistrationClouds clouds, Footprint footprint) {
  FrameResult result = processNodes(std::move(nodes), std::move(footprint), FrameResult{});
  // Only the declared loop is refined (docs/registration.md, "Where it runs"), against the stored cloud of its frame.
  if (result.is_loop && clouds_.enabled() && !clouds.stable.empty()) {
    const auto start = Clock::now();
    Candidate& loop = result.candidates[static_cast<size_t>(result.best)];
    loop.refinement = clouds_.refine(clouds_.queryCloud(clouds.stable), loop.frame, loop.match.T_match_query);
    if (loop.refinement && loop.refinement->used()) loop.match.T_match_query = loop.refinement->T_match_query;
    result.timing.refinement_ms = msSince(start);
  }
  clouds_.add(std::move(clouds.match));  // empty for node input: that frame's loops keep the SVD pose
  return result;
}

FrameResult LoopDetector::processNodes(std::vector<Node> nodes, Footprint footprint, FrameResult result) {
  result.frame = database_.size();
  auto start = Clock::now();
  DescribedFrame query = describeFrame(std::move(nodes), config_.graph, config_.descriptor,
                                        /*with_global=*/false, config_.numClasses());
  query.footprint = std::move(footprint);
  std::vector<float> key = retrieval::computeRetrievalKey(query.graph, config_);
  result.num_nodes = query.numNodes();
  result.timing.description_ms = msSince(start);

  // Query q sees frames 0 … q − G only (algorithm §5 [CHOICE]), and none before the warm-up.
  const RetrievalConfig& rc = config_.retrieval;
  if (result.frame < rc.warmup_frames) {
    result.search = Search::kWarmup;
  } else if (result.frame < rc.exclude_recent) {
    result.search = Search::kTooRecent;
  } else {
    search(query, key, database_, result.frame - rc.exclude_recent, config_, &result, described_.get(),
           &footprints_);
  }

  database_.add(StoredFrame{query.graph.nodes, std::move(key)});
  footprint_bytes_ += sizeof(Footprint) + query.footprint.bytes();
  footprints_.push_back(std::move(query.footprint));
  return result;
}

void searchDatabase(const DescribedFrame& query, const std::vector<float>& key, const FrameDatabase& database,
                    int last, const Config& config, FrameResult* result, const std::vector<Footprint>* footprints) {
  if (footprints && footprints->size() != static_cast<size_t>(database.size())) {
    throw Error("searchDatabase: " + std::to_string(footprints->size()) + " footprints for " +
                std::to_string(database.size()) + " frames");
  }
  search(query, key, database, last, config, result, nullptr, footprints);
}

namespace {

/// Database frame @p frame described as a candidate. A candidate is only matched against, and its description is
/// cached: its footprint is dilated once, each query cell then costs one look-up instead of nine (footprint.h).
std::shared_ptr<const DescribedFrame> describeCandidate(int frame, const FrameDatabase& database, const Config& config,
                                                        const Footprints* footprints) {
  DescribedFrame described = describeFrame(database.nodes(frame), config.graph, config.descriptor,
                                           /*with_global=*/false, config.numClasses());
  if (footprints) described.footprint = dilateFootprint((*footprints)[static_cast<size_t>(frame)]);
  return std::make_shared<const DescribedFrame>(std::move(described));
}

/// Verifies candidates[first..] against the query; each writes only its own slot. Cache look-ups and inserts stay on
/// this thread, in candidate order; workers describe the misses.
void verifyCandidates(const DescribedFrame& query, const FrameDatabase& database, const Config& config,
                      internal::DescribedCache* cache, const Footprints* footprints, std::vector<Candidate>& candidates,
                      size_t first) {
  const size_t count = candidates.size() - first;
  std::vector<std::shared_ptr<const DescribedFrame>> described(count);
  if (cache) {
    for (size_t c = 0; c < count; ++c) described[c] = cache->find(candidates[first + c].frame);
  }
  parallelFor(static_cast<int>(count), config.threads, [&](int c) {
    Candidate& cand = candidates[first + static_cast<size_t>(c)];
    if (!described[c]) described[c] = describeCandidate(cand.frame, database, config, footprints);
    cand.match = matchFrames(query, *described[c], config);
  });
  if (cache) {
    for (size_t c = 0; c < count; ++c) cache->insert(candidates[first + c].frame, std::move(described[c]));
  }
}

int chooseCandidate(const std::vector<Candidate>& candidates, const VerificationConfig& config) {
  std::vector<const MatchResult*> matches;
  for (const Candidate& cand : candidates) matches.push_back(&cand.match);
  return selectCandidate(matches, config);
}

void search(const DescribedFrame& query, const std::vector<float>& key, const FrameDatabase& database, int last,
            const Config& config, FrameResult* result, internal::DescribedCache* cache, const Footprints* footprints) {
  auto start = Clock::now();
  std::vector<RetrievedFrame> retrieved = database.query(key, last, config.retrieval.num_candidates);
  result->timing.retrieval_ms = msSince(start);

  // Candidates are verified in ascending frame index (algorithm §5); each writes only its own slot.
  start = Clock::now();
  std::sort(retrieved.begin(), retrieved.end(), [](const auto& a, const auto& b) { return a.frame < b.frame; });
  result->candidates.assign(retrieved.size(), Candidate{});
  for (size_t c = 0; c < retrieved.size(); ++c) {
    result->candidates[c].frame = retrieved[c].frame;
    result->candidates[c].distance2 = retrieved[c].distance2;
  }
  verifyCandidates(query, database, config, cache, footprints, result->candidates, 0);
  result->best = chooseCandidate(result->candidates, config.verification);

  // Neighbour check (VerificationConfig::neighbour_frames): the top-1 loop's database neighbours that retrieval
  // missed are verified as well, and the choice is made again among all, in ascending frame index.
  const int reach = config.verification.neighbour_frames;
  if (reach > 0 && result->best >= 0 && isLoop(result->candidates[result->best].match, config.verification)) {
    const int top = result->candidates[result->best].frame;
    const size_t first_added = result->candidates.size();
    for (int g = std::max(0, top - reach); g <= std::min(last, top + reach); ++g) {
      const bool listed = std::any_of(result->candidates.begin(), result->candidates.begin() + first_added,
                                      [g](const Candidate& c) { return c.frame == g; });
      if (listed) continue;
      Candidate added;
      added.frame = g;
      added.distance2 = internal::squaredDistance(key.data(), database.global(g), static_cast<int>(key.size()));
      added.retrieved = false;
      result->candidates.push_back(std::move(added));
    }
    if (result->candidates.size() > first_added) {
      verifyCandidates(query, database, config, cache, footprints, result->candidates, first_added);
      std::stable_sort(result->candidates.begin(), result->candidates.end(),
                       [](const Candidate& a, const Candidate& b) { return a.frame < b.frame; });
      result->best = chooseCandidate(result->candidates, config.verification);
    }
  }
  Candidate* best = result->best >= 0 ? &result->candidates[result->best] : nullptr;
  // The declared loop's pose, and only its, gets the footprint search (searchFootprints), before it is judged lateral.
  if (best && isLoop(best->match, config.verification) && config.verification.footprint_search > 0.0 && footprints) {
    std::shared_ptr<const DescribedFrame> match = cache ? cache->find(best->frame) : nullptr;
    if (!match) match = describeCandidate(best->frame, database, config, footprints);
    searchFootprints(query, *match, config.verification, &best->match);
  }
  result->lateral = best && isLateral(best->match, config.verification);
  result->is_loop = best && isLoop(best->match, config.verification);
  result->timing.verification_ms = msSince(start);
}

}  // namespace

PairResult comparePair(const LabeledCloud& query, const LabeledCloud& match, const Config& config) {
  config.validate();
  const NodeExtractor extractor(config.cluster, effectiveLabelConfig(config), config.graph.max_nodes, config.threads);
  const auto start = Clock::now();
  Footprint query_footprint, match_footprint;
  NodeExtractionResult q = extractor.extract(query, config.verification, &query_footprint);
  NodeExtractionResult m = extractor.extract(match, config.verification, &match_footprint);
  const double extraction_ms = msSince(start);
  const LabelMap& labels = extractor.labelMap();
  PairResult result = comparePair(std::move(q.nodes), std::move(m.nodes), config, std::move(query_footprint),
                                  std::move(match_footprint));
  result.extraction_query = q.stats;
  result.extraction_match = m.stats;
  result.timing.extraction_ms = extraction_ms;
  if (config.registration.pair && result.match.rejection == Rejection::kNone) {
    const auto refine_start = Clock::now();
    refinePair(&result, queryPoints(query, labels, config.registration), matchPoints(match, labels, config.registration),
               config);
    result.timing.refinement_ms = msSince(refine_start);
  }
  return result;
}

PairResult comparePair(std::vector<Node> query, std::vector<Node> match, const Config& config,
                       Footprint query_footprint, Footprint match_footprint) {
  config.validate();
  PairResult result;
  auto start = Clock::now();
  const int num_classes = config.numClasses();
  DescribedFrame q = describeFrame(std::move(query), config.graph, config.descriptor, true, num_classes);
  DescribedFrame m = describeFrame(std::move(match), config.graph, config.descriptor, true, num_classes);
  q.footprint = std::move(query_footprint);
  m.footprint = std::move(match_footprint);
  result.timing.description_ms = msSince(start);
  start = Clock::now();
  result.match = matchFrames(q, m, config);
  searchFootprints(q, m, config.verification, &result.match);
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
