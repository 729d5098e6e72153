// The time-per-frame plot of the evaluation report (internal to sgtllc_eval), and the statistics it draws.
#pragma once

#include <string>
#include <vector>

#include "sgtllc/eval/sequence_eval.h"

namespace sgtllc::eval {

/// The median of each centred window of 2·@p half + 1 values (truncated at both ends), so a trend over the
/// sequence shows through the frame-to-frame jitter.
std::vector<double> runningMedian(const std::vector<double>& values, int half);

/// Counts of @p values in equal bins over [0, hi]; a value equal to hi falls in the last bin, larger ones are
/// counted in `above` (a long tail would squeeze the bins where most frames lie into one).
struct Histogram {
  double width = 0.0;       ///< of one bin; bin k covers [k·width, (k + 1)·width)
  std::vector<int> counts;  ///< one per bin
  int above = 0;            ///< values > hi
};
Histogram histogram(const std::vector<double>& values, double hi, int bins);

/// Two panels: each stage's running median over the sequence (legend: its median and p99 over all frames), and
/// the histogram of the total time per frame with its median and p99 marked.
void plotTiming(const std::string& path, const SequenceRun& run);

}  // namespace sgtllc::eval
