/// @file pair_eval.h
/// @brief Pair-list protocol: score given `query candidate label` pairs (SSC / SGLC pair files, the simulator's
///        loop_pairs.txt) and their PR metrics and pose errors.
#pragma once

#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/eval/ground_truth.h"
#include "sgtllc/eval/sequence_eval.h"

namespace sgtllc::eval {

struct LoopPairLabel {
  long query = 0;
  long candidate = 0;
  bool loop = false;
};

/// Reads `query candidate label` lines (frame numbers, label 1 = loop, 0 = not); `#` comments and blank lines
/// are skipped. Throws sgtllc::Error naming the file and line for a malformed line (the line is echoed through
/// io::quoteContent), and naming the file for a list without any pair (an empty list given by the user is almost
/// always the wrong file) unless @p allow_empty: a simulated sequence without revisits writes a loop_pairs.txt
/// with none, which `sgtllc eval SEQ` then skips.
std::vector<LoopPairLabel> readPairList(const std::string& path, bool allow_empty = false);

struct PairRecord {
  LoopPairLabel pair;
  bool available = false;      ///< both frames are in the source
  double score = 0.0;
  double score_c = 0.0;
  Rejection rejection = Rejection::kFewAssociations;
  bool is_loop = false;
  bool pose_evaluated = false;  ///< a true, detected loop with a ground-truth pose within pose_max_distance
  PoseError pose_error;
};

struct PairListRun {
  std::vector<PairRecord> pairs;
  int unavailable = 0;  ///< pairs skipped because a frame is missing from the source
};

/// Scores every pair whose two frames are in @p source (each frame is read and clustered once, in parallel).
/// @p truth may be empty (no poses): then no pose errors are computed.
PairListRun runPairListEvaluation(const pipeline::FrameSource& source, const std::vector<LoopPairLabel>& pairs,
                                  const GroundTruth& truth, const Config& config, const EvalOptions& options);
/// The same on frames already reduced to nodes, e.g. those an online run stored (`sgtllc eval` scores a
/// sequence's loop_pairs.txt this way without reading the scans again): @p nodes[i] are the nodes of frame number
/// @p numbers[i], with @p footprints[i] for the footprint check (LoopDetector::footprints; none: not checked).
/// Throws sgtllc::Error if they differ in length.
PairListRun runPairListEvaluation(const std::vector<long>& numbers, const std::vector<std::vector<Node>>& nodes,
                                  const std::vector<LoopPairLabel>& pairs, const GroundTruth& truth,
                                  const Config& config, const EvalOptions& options,
                                  const std::vector<Footprint>& footprints = {});

struct PairListMetrics {
  CurveMetrics curve;     ///< over the available pairs, labels as given
  int n_pairs = 0;
  int n_available = 0;
  int correct = 0;        ///< available pairs whose decision (score > σ_4) equals the label
  int positives_scored_zero = 0;  ///< available pairs labelled loop whose score is 0 (a gate or RANSAC failed)
  PoseSummary poses;
};

PairListMetrics computePairListMetrics(const PairListRun& run, const EvalOptions& options);

}  // namespace sgtllc::eval
