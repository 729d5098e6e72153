// Tracking a stream of relocalizations (include/sgtllc/map/relocalization_tracker.h, docs/relocalization.md).
#include "sgtllc/map/relocalization_tracker.h"

#include <string>
#include <utility>

#include "sgtllc/selection.h"
#include "sgtllc/types.h"

namespace sgtllc::map {
namespace {

void check(bool ok, const std::string& field, double value, const char* range) {
  if (!ok) throw Error("tracking: " + field + " = " + std::to_string(value) + " is out of range " + range);
}

}  // namespace

void TrackingOptions::validate() const {
  check(weak_sigma >= 0.0 && weak_sigma <= 1.0, "weak_sigma", weak_sigma, "[0, 1]");
  check(gate_m > 0.0 && gate_m <= 1000.0, "gate_m", gate_m, "(0, 1000]");
  check(max_speed_m_per_frame >= 0.0 && max_speed_m_per_frame <= 1000.0, "max_speed_m_per_frame",
        max_speed_m_per_frame, "[0, 1000]");
  check(window >= 1 && window <= 1000000, "window", window, "[1, 1000000]");
}

RelocalizationTracker::RelocalizationTracker(const Relocalizer& relocalizer, TrackingOptions options)
    : relocalizer_(relocalizer), options_(options) {
  options_.validate();
}

void RelocalizationTracker::reset() {
  last_.reset();
  since_last_ = 0;
}

Relocalization RelocalizationTracker::localize(std::vector<Node> nodes, Footprint footprint) {
  return track(relocalizer_.localize(std::move(nodes), std::move(footprint)));
}

Relocalization RelocalizationTracker::track(Relocalization answer) {
  ++since_last_;
  if (last_ && since_last_ > options_.window) last_.reset();
  if (!answer.localized && last_ && relocalizer_.map().hasPoses()) {
    const double reach = options_.gate_m + options_.max_speed_m_per_frame * since_last_;
    const std::vector<Eigen::Matrix4d>& poses = relocalizer_.map().poses;
    const std::vector<Candidate>& candidates = answer.search.candidates;
    int agreeing = -1;
    for (size_t c = 0; c < candidates.size(); ++c) {
      const MatchResult& m = candidates[c].match;
      if (m.rejection != Rejection::kNone || !(m.score > options_.weak_sigma)) continue;
      if (!relocalizer_.rotationSupported(candidates[c])) continue;
      const Eigen::Matrix4d T_world_query = poses[static_cast<size_t>(candidates[c].frame)] * m.T_match_query;
      if ((T_world_query.topRightCorner<3, 1>() - *last_).norm() > reach) continue;
      // The highest score wins; ties go to the earlier candidate (candidates are in frame order).
      if (agreeing < 0 || m.score > candidates[static_cast<size_t>(agreeing)].match.score) {
        agreeing = static_cast<int>(c);
      }
    }
    if (agreeing >= 0) {
      FrameResult search = std::move(answer.search);
      search.best = agreeing;
      search.lateral = isLateral(search.candidates[static_cast<size_t>(agreeing)].match,
                                 relocalizer_.config().verification);
      answer = relocalizer_.answerWith(std::move(search), agreeing);
      answer.localized = true;
      answer.tracked = true;
    }
  }
  if (answer.localized && answer.T_world_query) {
    last_ = answer.T_world_query->topRightCorner<3, 1>();
    since_last_ = 0;
  }
  return answer;
}

}  // namespace sgtllc::map
