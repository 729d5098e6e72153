/// @file selection.h
/// @brief Which verified candidate a query reports (algorithm §7.4; BENCHMARKS.md, "Top-1 choice"): the highest score, or the
///        geometrically closest one among those scoring nearly as well.
#pragma once

#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/verification.h"

namespace sgtllc {

/// Index into @p matches (one per candidate, in ascending candidate frame index) of the candidate the query
/// reports, or −1 if none passed verification (rejection != kNone).
///
/// With `config.select_margin` = 0: the highest score; a tie goes to the later (higher-index) candidate, as the
/// authors' `>=` (algorithm §7.4). With a margin m > 0: among the verified candidates whose score ≥ best − m, the one
/// whose estimated translation ‖t(T_match_query)‖ is smallest (ties: higher score, then the later candidate). A
/// revisit's neighbours along the old pass (3–20 m "lateral" matches) often verify too and can score a little
/// higher; the revisit itself is the one the pose places closest. When the best score is a loop (> σ_4), only
/// loops are eligible, so the choice never turns a frame's loop into no loop.
int selectCandidate(const std::vector<const MatchResult*>& matches, const VerificationConfig& config);

/// Whether a verified match places the query at least `config.lateral_distance` from the candidate
/// (‖t(T_match_query)‖): a lateral match, a neighbour of the revisit rather than the revisit.
bool isLateral(const MatchResult& match, const VerificationConfig& config);

}  // namespace sgtllc
