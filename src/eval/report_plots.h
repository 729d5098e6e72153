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

/// The lower ends of the zoom panel's axes (both end at 1): a good detector's curves differ only in the corner where
/// precision falls off at high recall, so the panel frames the knee of the curves, on both axes from the data.
struct PrZoom {
  double recall_lo = 0.0, precision_lo = 0.0;
};
/// Each axis spans twice the largest gap to 1 of the curves' F1max points on that axis (at least 0.02, rounded up
/// to one significant digit, at most the whole axis), so every knee lies in the panel's upper-right quarter with
/// the curves' fall beside and below it. Curves without positives count for nothing; none gives the whole axes.
PrZoom prZoom(const std::vector<const PrCurve*>& curves);

/// One PR curve per positive distance (pairwise, solid) and the top-1 curve (dashed) if given, beside a panel
/// zoomed on their knee (prZoom); an axes without positives says so.
void plotPrCurves(const std::string& path, const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1,
                  const std::string& title);
/// Database bytes over the sequence.
void plotMemory(const std::string& path, const SequenceRun& run);
/// Trajectory from above with a start marker, detected loops drawn over the path: true (green, marked at the
/// query: its two ends are too close to see a segment), 3–20 m (blue) and false (red), and the missed revisits on
/// top of them all (large outlined markers: a few misses among a thousand true loops must stay visible).
/// The legend lists only what occurs.
void plotTrajectory(const std::string& path, const SequenceRun& run, const EvalOptions& options);

}  // namespace sgtllc::eval
