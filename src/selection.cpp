#include "sgtllc/selection.h"

namespace sgtllc {

int selectCandidate(const std::vector<const MatchResult*>& matches, const VerificationConfig& config) {
  const int n = static_cast<int>(matches.size());
  int best = -1;
  for (int c = 0; c < n; ++c) {
    const MatchResult& m = *matches[c];
    if (m.rejection != Rejection::kNone) continue;
    if (best < 0 || m.score >= matches[best]->score) best = c;
  }
  if (best < 0 || config.select_margin <= 0.0) return best;

  const double best_score = matches[best]->score;
  const bool loop = isLoop(*matches[best], config);
  int chosen = best;
  double chosen_t = matches[best]->T_match_query.topRightCorner<3, 1>().norm();
  for (int c = 0; c < n; ++c) {
    const MatchResult& m = *matches[c];
    if (c == best || m.rejection != Rejection::kNone || m.score < best_score - config.select_margin) continue;
    if (loop && !isLoop(m, config)) continue;
    const double t = m.T_match_query.topRightCorner<3, 1>().norm();
    const MatchResult& k = *matches[chosen];
    // Later candidates win exact ties, as in the score-only rule.
    if (t < chosen_t || (t == chosen_t && m.score >= k.score)) {
      chosen = c;
      chosen_t = t;
    }
  }
  return chosen;
}

bool isLateral(const MatchResult& match, const VerificationConfig& config) {
  return match.rejection == Rejection::kNone &&
         match.T_match_query.topRightCorner<3, 1>().norm() >= config.lateral_distance;
}

}  // namespace sgtllc
