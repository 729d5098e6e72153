// Undefined metrics as n/a / null with their reason (metric_text.h).
#include "sgtllc/eval/metric_text.h"

#include <cstdio>

namespace sgtllc::eval {
namespace {

std::string metres(double d) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.0f m", d);
  return buf;
}

void addPoseReasons(std::vector<UndefinedMetrics>& out, const PoseSummary& p) {
  if (!p.rateDefined()) {
    out.push_back({"success_rate, rte_mean, rre_mean", "no detected true loop had its pose checked"});
  } else if (!p.meansDefined()) {
    out.push_back({"rte_mean, rre_mean", "no checked loop pose succeeded, so there is no mean over successes"});
  }
}

}  // namespace

std::string metricText(double value, bool defined, int digits) {
  if (!defined) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, value);
  return buf;
}

nlohmann::ordered_json metricJson(double value, bool defined) {
  return defined ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

std::vector<UndefinedMetrics> undefinedMetrics(const SequenceMetrics& m) {
  std::vector<UndefinedMetrics> out;
  const double positive = m.pairwise.empty() ? 0.0 : m.pairwise.front().positive_distance;
  if (!m.pairwise.empty() && !m.pairwise.front().defined()) {
    out.push_back({"f1_max, ep, recall_at_100_precision",
                   "no positives in this sequence: no scored pair is closer than " + metres(positive)});
  }
  if (m.n_revisit_queries == 0) {
    out.push_back({"retrieval_recall_at_15, top1",
                   "no queried frame revisits a place within " + metres(positive)});
  }
  addPoseReasons(out, m.poses);
  return out;
}

std::vector<UndefinedMetrics> undefinedMetrics(const PairListMetrics& m) {
  std::vector<UndefinedMetrics> out;
  if (!m.curve.defined()) {
    out.push_back({"f1_max, ep, recall_at_100_precision", "no positives: no scored pair is labelled a loop"});
  }
  addPoseReasons(out, m.poses);
  return out;
}

std::string undefinedText(const std::vector<UndefinedMetrics>& list, const std::string& indent) {
  std::string s;
  for (const UndefinedMetrics& u : list) s += indent + "n/a: " + u.metrics + ": " + u.reason + "\n";
  return s;
}

nlohmann::ordered_json undefinedJson(const std::vector<UndefinedMetrics>& list) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const UndefinedMetrics& u : list) j.push_back(u.metrics + ": " + u.reason);
  return j;
}

}  // namespace sgtllc::eval
