// PNG plots of the evaluation report (internal to sgtllc_eval).
#pragma once

#include <string>
#include <vector>

#include "sgtllc/eval/sequence_eval.h"

namespace sgtllc::eval {

/// The points of @p c drawn as steps, as sklearn's PrecisionRecallDisplay and evo draw a PR curve: from the
/// appended (recall 0, precision 1) point through the thresholds from the highest, each threshold's precision held
/// over the recall it adds (vertical, then horizontal), never a slanted line between two thresholds.
struct PrSteps {
  std::vector<double> recall, precision;
};
PrSteps prSteps(const PrCurve& c);

/// One PR curve per positive distance (pairwise, solid) and the top-1 curve (dashed) if given, beside a panel
/// zoomed on precision 0.9–1; an axes without positives says so.
void plotPrCurves(const std::string& path, const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1,
                  const std::string& title);
/// Milliseconds per frame and stage over the sequence, the legend beside the axes.
void plotTiming(const std::string& path, const SequenceRun& run);
/// Database bytes over the sequence.
void plotMemory(const std::string& path, const SequenceRun& run);
/// Trajectory from above with a start marker, missed revisits, and detected loops drawn over the path: true
/// (green, marked at the query: its two ends are too close to see a segment), 3–20 m (blue) and false (red).
/// The legend lists only what occurs.
void plotTrajectory(const std::string& path, const SequenceRun& run, const EvalOptions& options);

}  // namespace sgtllc::eval
