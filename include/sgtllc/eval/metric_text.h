/// @file metric_text.h
/// @brief How a metric reads in text and JSON: its value, or `n/a` / `null` with a one-line reason when it is
///        undefined (no positives, no pose to check), never a 0 that reads like a result.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sgtllc/eval/pair_eval.h"
#include "sgtllc/eval/sequence_eval.h"

namespace sgtllc::eval {

/// @p value with @p digits decimals, or "n/a" if not @p defined.
std::string metricText(double value, bool defined, int digits);
/// @p value, or null if not @p defined.
nlohmann::ordered_json metricJson(double value, bool defined);

/// Metrics that are undefined and why: `metrics` names them as the JSON does, `reason` is one line.
struct UndefinedMetrics {
  std::string metrics;
  std::string reason;
};

/// The undefined metrics of a sequence evaluation (empty if every metric has a value).
std::vector<UndefinedMetrics> undefinedMetrics(const SequenceMetrics& m);
/// The undefined metrics of a pair-list evaluation.
std::vector<UndefinedMetrics> undefinedMetrics(const PairListMetrics& m);

/// "n/a: METRICS: REASON" lines, each after @p indent and ending in a newline.
std::string undefinedText(const std::vector<UndefinedMetrics>& list, const std::string& indent = "");
/// The same as a JSON array of "METRICS: REASON" strings.
nlohmann::ordered_json undefinedJson(const std::vector<UndefinedMetrics>& list);

}  // namespace sgtllc::eval
