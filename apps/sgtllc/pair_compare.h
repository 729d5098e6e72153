// What `sgtllc pair` and `sgtllc pair --list` share: one pair of scan files compared (read, extracted, verified,
// refined) and its JSON object.
#pragma once

#include <string>

#include "common.h"

namespace sgtllc::cli {

/// The two inputs of a pair: paths, label files ("" for the default beside each scan) and the PCD/PLY label field.
struct PairFiles {
  std::string query, match;
  std::string labels_query, labels_match;
  std::string label_field = "label";
};

/// A compared pair: the result, both inputs' nodes and bookkeeping (their clouds consumed by the refinement), and
/// the time spent reading them.
struct ComparedPair {
  PairResult result;
  FrameNodes query, match;
  double load_ms = 0.0;
};

/// Reads both inputs, warns about dropped points on stderr (unless @p warn is false: warnInputs() later), verifies
/// the pair (the footprint check where both are scans) and refines its pose by ICP when both are scans and
/// registration.pair is on.
ComparedPair compareFiles(const PairFiles& files, const Config& config, bool warn = true);

/// The warnings compareFiles() prints about a compared pair's inputs (warnAboutInput).
void warnInputs(const PairFiles& files, const ComparedPair& c);

/// Pairs of MatchResult::associations that guided matching added (algorithm §7.2), not LA.
size_t numGuided(const MatchResult& m);

/// The object `sgtllc pair --json` prints for a pair of @p query and @p match.
Json pairJson(const std::string& query, const std::string& match, const PairResult& r, const Config& config,
              double load_ms);

/// `sgtllc pair --list LIST`: every pair of the list (io::readScanPairs) compared in this process, @p threads pairs
/// at once, a CSV row per pair on stdout in the list's order (a header first), or with @p json one JSON object a
/// line (pairJson); stdout and stderr do not depend on @p threads but for the times. A pair that cannot be
/// compared (a missing or bad file) gets its error in its row and on stderr, the others go on, and the command then
/// fails naming how many did not compare.
void runPairList(const std::string& list, const std::string& label_field, const Config& config, bool json,
                 int threads);

}  // namespace sgtllc::cli
