#include "sgtllc/eval/pair_eval.h"

#include <exception>
#include <functional>
#include <fstream>
#include <map>
#include <sstream>

#include "sgtllc/io/quote.h"
#include "sgtllc/parallel.h"

namespace sgtllc::eval {
namespace {

bool parseFrame(const std::string& token, long* out) {
  if (token.empty() || token.size() > 12) return false;
  for (char c : token) {
    if (c < '0' || c > '9') return false;
  }
  *out = std::stol(token);
  return true;
}

}  // namespace

std::vector<LoopPairLabel> readPairList(const std::string& path, bool allow_empty) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open pair list " + path);
  std::vector<LoopPairLabel> pairs;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream tokens(line);
    std::string q, c, l, extra;
    tokens >> q >> c >> l;
    LoopPairLabel p;
    if (!parseFrame(q, &p.query) || !parseFrame(c, &p.candidate) || (l != "0" && l != "1") || (tokens >> extra)) {
      throw Error(path + ":" + std::to_string(number) + ": expected 'query candidate label' (frame numbers and 0/1), " +
                  "found " + io::quoteContent(line));
    }
    p.loop = l == "1";
    pairs.push_back(p);
  }
  if (in.bad()) throw Error("cannot read pair list " + path);
  // An empty list scores nothing and would print zero metrics: almost always the wrong file.
  if (pairs.empty() && !allow_empty) throw Error(path + ": the pair list has no pairs (only blank or '#' lines)");
  return pairs;
}

namespace {

/// Marks which pairs have both frames (index_of maps a frame number to its slot in the caller's frames) and
/// lists, in first-use order, the slots any available pair needs.
PairListRun planPairs(const std::vector<LoopPairLabel>& pairs, const std::map<long, size_t>& index_of,
                      std::vector<size_t>* needed, std::map<long, size_t>* slot_of) {
  PairListRun run;
  for (const LoopPairLabel& p : pairs) {
    PairRecord r;
    r.pair = p;
    r.available = index_of.count(p.query) && index_of.count(p.candidate);
    run.unavailable += !r.available;
    if (r.available) {
      for (long f : {p.query, p.candidate}) {
        if (slot_of->emplace(f, needed->size()).second) needed->push_back(index_of.at(f));
      }
    }
    run.pairs.push_back(r);
  }
  return run;
}

/// A frame's nodes and footprint (empty for node input), by the caller's index.
using FrameOf = std::function<std::pair<std::vector<Node>, Footprint>(size_t)>;

/// Describes the needed frames in parallel.
std::vector<DescribedFrame> describeNeeded(const std::vector<size_t>& needed, const FrameOf& frame_of,
                                           const Config& config, int threads) {
  std::vector<DescribedFrame> frames(needed.size());
  std::vector<std::exception_ptr> errors(needed.size());
  parallelFor(static_cast<int>(needed.size()), threads, [&](int k) {
    try {
      auto [nodes, footprint] = frame_of(needed[k]);
      frames[k] = describeFrame(std::move(nodes), config.graph, config.descriptor, /*with_global=*/true,
                                config.numClasses());
      frames[k].footprint = std::move(footprint);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return frames;
}

void scorePairs(PairListRun& run, const std::vector<DescribedFrame>& frames, const std::map<long, size_t>& slot_of,
                const GroundTruth& truth, const Config& config, const EvalOptions& options) {
  parallelFor(static_cast<int>(run.pairs.size()), options.threads, [&](int k) {
    PairRecord& r = run.pairs[k];
    if (!r.available) return;
    const DescribedFrame& query = frames[slot_of.at(r.pair.query)];
    const DescribedFrame& candidate = frames[slot_of.at(r.pair.candidate)];
    MatchResult m = matchFrames(query, candidate, config);
    searchFootprints(query, candidate, config.verification, &m);  // each listed pair is a declared loop if it is one
    r.score = m.score;
    r.score_c = m.score_c;
    r.rejection = m.rejection;
    r.is_loop = isLoop(m, config.verification);
    if (r.is_loop && r.pair.loop && truth.has(r.pair.query) && truth.has(r.pair.candidate) &&
        truth.distance(r.pair.query, r.pair.candidate) <= options.pose_max_distance) {
      r.pose_evaluated = true;
      r.pose_error = poseError(m.T_match_query, truth.relative(r.pair.candidate, r.pair.query));
    }
  });
  if (options.progress) options.progress(run.pairs.size(), run.pairs.size(), 0);
}

}  // namespace

PairListRun runPairListEvaluation(const pipeline::FrameSource& source, const std::vector<LoopPairLabel>& pairs,
                                  const GroundTruth& truth, const Config& config, const EvalOptions& options) {
  config.validate();
  std::map<long, size_t> index_of, slot_of;
  for (size_t i = 0; i < source.size(); ++i) index_of[source.number(i)] = i;
  // Each frame that any available pair needs is read and clustered once.
  std::vector<size_t> needed;
  PairListRun run = planPairs(pairs, index_of, &needed, &slot_of);
  const FrameOf frame_of = [&source](size_t i) {
    pipeline::LoadedFrame f = source.load(i);
    return std::make_pair(std::move(f.nodes), std::move(f.footprint));
  };
  const auto frames = describeNeeded(needed, frame_of, config, options.threads);
  scorePairs(run, frames, slot_of, truth, config, options);
  return run;
}

PairListRun runPairListEvaluation(const std::vector<long>& numbers, const std::vector<std::vector<Node>>& nodes,
                                  const std::vector<LoopPairLabel>& pairs, const GroundTruth& truth,
                                  const Config& config, const EvalOptions& options,
                                  const std::vector<Footprint>& footprints) {
  config.validate();
  if (numbers.size() != nodes.size()) throw Error("runPairListEvaluation: one node set per frame number is needed");
  if (!footprints.empty() && footprints.size() != nodes.size()) {
    throw Error("runPairListEvaluation: one footprint per frame, or none, is needed");
  }
  std::map<long, size_t> index_of, slot_of;
  for (size_t i = 0; i < numbers.size(); ++i) index_of[numbers[i]] = i;
  std::vector<size_t> needed;
  PairListRun run = planPairs(pairs, index_of, &needed, &slot_of);
  const FrameOf frame_of = [&nodes, &footprints](size_t i) {
    return std::make_pair(nodes[i], footprints.empty() ? Footprint{} : footprints[i]);
  };
  const auto frames = describeNeeded(needed, frame_of, config, options.threads);
  scorePairs(run, frames, slot_of, truth, config, options);
  return run;
}

PairListMetrics computePairListMetrics(const PairListRun& run, const EvalOptions& options) {
  PairListMetrics m;
  std::vector<ScoredSample> samples;
  std::vector<PoseError> errors;
  for (const PairRecord& r : run.pairs) {
    ++m.n_pairs;
    if (!r.available) continue;
    ++m.n_available;
    samples.push_back({r.score, r.pair.loop});
    m.correct += r.is_loop == r.pair.loop;
    m.positives_scored_zero += r.pair.loop && r.score == 0.0;
    if (r.pose_evaluated) errors.push_back(r.pose_error);
  }
  m.curve = curveMetrics(samples, options.positive_distances.at(0));
  m.poses = summarisePoses(errors, options.success_translation, options.success_rotation);
  return m;
}

}  // namespace sgtllc::eval
