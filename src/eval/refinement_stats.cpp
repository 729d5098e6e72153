#include "sgtllc/eval/refinement_stats.h"

#include <cstdio>
#include <numeric>

#include "sgtllc/eval/sequence_eval.h"

namespace sgtllc::eval {

RefinementStats refinementStats(bool enabled, const std::vector<std::optional<RefinementStatus>>& statuses,
                                const std::vector<double>& refinement_ms, size_t cloud_bytes) {
  RefinementStats s;
  s.enabled = enabled;
  for (const auto& status : statuses) {
    if (!status) continue;
    ++s.refined;
    ++s.by_status[static_cast<size_t>(*status)];
    s.used += *status == RefinementStatus::kConverged || *status == RefinementStatus::kMaxIterations;
  }
  if (!refinement_ms.empty()) {
    s.ms_per_frame_median = percentile(refinement_ms, 0.5);
    s.ms_per_frame_mean =
        std::accumulate(refinement_ms.begin(), refinement_ms.end(), 0.0) / static_cast<double>(refinement_ms.size());
    s.cloud_bytes_per_frame = static_cast<double>(cloud_bytes) / static_cast<double>(refinement_ms.size());
  }
  return s;
}

std::string refinementLine(const RefinementStats& s) {
  if (!s.enabled) return "refinement: off (registration.online: false)\n";
  auto status = [&s](RefinementStatus st) {
    return std::string(refinementStatusName(st)) + " " + std::to_string(s.by_status[static_cast<size_t>(st)]);
  };
  std::string out = "refinement: " + std::to_string(s.refined) + " loops refined, " + std::to_string(s.used) +
                    " used (" + status(RefinementStatus::kConverged) + ", " +
                    status(RefinementStatus::kMaxIterations) + "); kept the SVD pose " +
                    std::to_string(s.fallbacks()) + " (";
  bool first = true;
  for (RefinementStatus st : {RefinementStatus::kTooFewPoints, RefinementStatus::kDegenerate,
                              RefinementStatus::kLowFitness, RefinementStatus::kMovedTooFar}) {
    out += (first ? "" : ", ") + status(st);
    first = false;
  }
  char tail[160];
  std::snprintf(tail, sizeof(tail), "); %.2f ms per frame median (mean %.2f); cloud store %.0f bytes per frame\n",
                s.ms_per_frame_median, s.ms_per_frame_mean, s.cloud_bytes_per_frame);
  return out + tail;
}

}  // namespace sgtllc::eval
