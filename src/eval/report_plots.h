// PNG plots of the evaluation report (internal to sgtllc_eval).
#pragma once

#include <string>
#include <vector>

#include "sgtllc/eval/sequence_eval.h"

namespace sgtllc::eval {

/// One PR curve per positive distance (pairwise, solid) and the top-1 curve (dashed) if given.
void plotPrCurves(const std::string& path, const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1,
                  const std::string& title);
/// Milliseconds per frame and stage over the sequence.
void plotTiming(const std::string& path, const SequenceRun& run);
/// Database bytes over the sequence.
void plotMemory(const std::string& path, const SequenceRun& run);
/// Trajectory from above with detected loops as true (green) and false (red) positives and missed revisits.
void plotTrajectory(const std::string& path, const SequenceRun& run, const EvalOptions& options);

}  // namespace sgtllc::eval
