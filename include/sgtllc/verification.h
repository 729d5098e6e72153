/// @file verification.h
/// @brief Verifying one candidate frame: association, score_c gate, RANSAC, score and the SVD pose (algorithm §6–§7).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sgtllc/association.h"
#include "sgtllc/config.h"
#include "sgtllc/footprint.h"
#include "sgtllc/footprint_search.h"
#include "sgtllc/frame.h"
#include "sgtllc/ransac.h"

namespace sgtllc {

/// Why a candidate got a zero score.
enum class Rejection {
  kNone,              ///< passed the gates and RANSAC accepted a hypothesis
  kFewAssociations,   ///< score_c < σ_3 or |LA| < min_associations (algorithm §7.1)
  kRansacFailed,      ///< no hypothesis reached min_inliers and min_inlier_fraction (algorithm §7.2)
  /// the pose puts too few of the query's structure cells on the match's (footprint.h; algorithm §7.7)
  kFootprint,
  /// under the pose, one sensor saw through too much of what the other saw (sight.h; algorithm §7.7)
  kSeenThrough,
};

/// "none", "few_associations", "ransac_failed", "footprint_mismatch" or "seen_through", as printed by the CLI and
/// written to reports.
const char* rejectionName(Rejection r);

/// Outcome of comparing a query frame with one candidate ("match") frame.
struct MatchResult {
  /// LA in query-node order, then the pairs guided matching added (NodeMatch::guided; algorithm §7.2). A query node
  /// can appear twice: its LA pair, not an inlier, and a guided pair with another match node. |LA| is the number of
  /// entries that are not guided.
  std::vector<NodeMatch> associations;
  /// Indices into associations of the inliers, ascending: RANSAC's, or guided matching's pairs when it found more.
  std::vector<int> inliers;
  /// |LA| / M, M = all query nodes, isolated ones included, those of a class with score_unmatched false only when
  /// in LA (algorithm §7.1, §7.3 "Node count")
  double score_c = 0.0;
  double score = 0.0;                 ///< loop score; 0 unless rejection == kNone (algorithm §7.3)
  Rejection rejection = Rejection::kFewAssociations;
  /// Maps query-frame points into the match frame: p_match = T_match_query · p_query. Kabsch on all inliers
  /// (algorithm §7.5), or RANSAC's hypothesis where that refit would tilt beyond verification.max_tilt_deg; the
  /// identity unless rejection == kNone.
  Eigen::Matrix4d T_match_query = Eigen::Matrix4d::Identity();
  /// The footprint check under the verified pose (algorithm §7.7); compared = 0 when it did not run (no footprints,
  /// the check off, no pose).
  FootprintOverlap footprint;
  /// The pairs came from the consistency path (algorithm §7.8), not from the descriptors' LA: `associations` are
  /// then that path's pairs (and guided ones), score_c is still the descriptors' |LA| / M.
  bool by_consistency = false;
  /// The footprint search (searchFootprints, algorithm §7.9) from the nodes' pose: the shift T_match_query includes
  /// (zero when no shift gained verification.footprint_search_gain) and the footprint shares with and without it;
  /// compared = 0 when it did not run (not the declared loop, verification.footprint_search 0, no footprints, or
  /// footprints that already agree too well for any shift to gain that much).
  FootprintShift footprint_search;
};

/// RANSAC parameters of the verification config.
RansacParams ransacParams(const VerificationConfig& config);

/// Weight in [0, 1] of a verified candidate's score for its estimated offset ‖t(T_match_query)‖ (m): 1 up to
/// `config.offset_decay_start`, then linearly down to 0 at `config.offset_decay_end`; always 1 when that is 0.
/// A pose that puts the query 20 m from the candidate says it is not the same place, however many objects agree.
double offsetWeight(double offset_m, const VerificationConfig& config);

/// Associates nodes, applies the score_c gate, runs RANSAC, fits the pose on its inliers and scales score by
/// offsetWeight of the pose's translation. When that is not a loop and verification.consistency_pairs > 0, the
/// consistency path (algorithm §7.8) tries again, and its result is returned if it is a loop.
MatchResult matchFrames(const DescribedFrame& query, const DescribedFrame& match, const Config& config);

/// The loop decision for one candidate score: score > σ_4 (algorithm §7.4).
inline bool isLoop(const MatchResult& m, const VerificationConfig& config) {
  return m.rejection == Rejection::kNone && m.score > config.sigma_4;
}

/// The footprint search (algorithm §7.9, footprint_search.h) on a loop: its pose moves by the horizontal shift,
/// within verification.footprint_search, under which the footprints agree by footprint_search_gain more (not one on
/// the edge of the searched square), and the nodes the moved pose pairs refine it within a cell; `footprint` is then
/// what the footprints say under the moved pose, `footprint_search` what the search found. The loop decision and
/// score stand as verified on the nodes' pose: judged at the best of a thousand shifts, two different places'
/// footprints agree more than at one pose. Like fine registration it is for the declared loop (the detector's top-1,
/// a pair): run on every candidate it cost an online run a tenth of its time and moved none of its poses
/// (BENCHMARKS.md "Footprint search"). Does nothing unless @p result is a loop whose footprint check ran.
void searchFootprints(const DescribedFrame& query, const DescribedFrame& match, const VerificationConfig& config,
                      MatchResult* result);

}  // namespace sgtllc
