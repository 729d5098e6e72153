// The settings of verification and the loop decision (VerificationConfig in config.h, which documents each field
// and cites the algorithm's sections and BENCHMARKS.md).
#include "setting_table.h"

namespace sgtllc::detail {

void addVerificationSettings(std::vector<Setting>* out) {
  using V = VerificationConfig;
  const std::string nodes = "[1, " + std::to_string(kMaxGraphNodes) + "]";
  SectionTable<V> v("verification", [](Config& c) -> V& { return c.verification; }, out);
  v.number("sigma_3", &V::sigma_3, "[0, 1]", "", "σ_3: skip a candidate iff score_c < σ_3");
  v.number("min_associations", &V::min_associations, nodes, "", "... or |LA| < this");
  v.number("ransac_iterations", &V::ransac_iterations, "[1, 10000]", "", "RANSAC hypotheses per candidate");
  // A rigid fit needs three pairs.
  v.number("ransac_sample_size", &V::ransac_sample_size, "[3, 100]", "", "node pairs per hypothesis");
  v.flag("sample_with_replacement", &V::sample_with_replacement, "draw pairs with replacement (authors' code)");
  v.number("inlier_threshold", &V::inlier_threshold, "(0, 10]", "m", "inlier iff ‖R s + t − t′‖ < this");
  v.number("min_inliers", &V::min_inliers, nodes, "", "accept a hypothesis only with >= this many inliers");
  v.number("min_inlier_fraction", &V::min_inlier_fraction, "[0, 1]", "", "... and >= this share of |LA|");
  v.flag("use_ransac", &V::use_ransac, "false = score_c as the score, pose from all associations");
  v.number("ransac_confidence", &V::ransac_confidence, "(0, 1]", "",
           "stop RANSAC once an all-inlier sample is drawn with this probability; 1 = all iterations");
  v.choice("score_formula", &V::score_formula,
           {{"paper", ScoreFormula::kPaper}, {"legacy", ScoreFormula::kLegacy}, {"overlap", ScoreFormula::kOverlap}},
           "score: n_in/|LA|, (n_in - 1)/|LA| or n_in/max(M, N)");
  v.flag("score_covisible", &V::score_covisible,
         "score_formula overlap: count only the nodes within the other frame's reach under the pose");
  v.number("max_tilt_deg", &V::max_tilt_deg, "[1, 180]", "deg",
           "RANSAC skips a rotation that tilts the up axis more than this; 180 = no check");
  v.flag("guided_matching", &V::guided_matching,
         "after RANSAC, pair the nodes its pose puts together (score_formula overlap only)");
  v.number("consistency_pairs", &V::consistency_pairs, "[0, 16]", "",
           "when the descriptors' pairs give no loop, verify the largest consistent set of each query node's this "
           "many most similar same-class nodes; 0 = off");
  v.number("weak_inliers", &V::weak_inliers, "[0, 1000]", "",
           "a loop of at most this many inliers needs weak_min_footprint (0 = no such rule)");
  v.number("weak_min_footprint", &V::weak_min_footprint, "[0, 1]", "",
           "footprint share a loop of few inliers, or of the consistency path, needs");
  v.number("sigma_4", &V::sigma_4, "[0, 1]", "", "σ_4: loop iff best score > σ_4 (0.1 for MulRan/MCD)");
  v.number("select_margin", &V::select_margin, "[0, 1]", "",
           "top-1: the nearest (smallest translation) of the candidates within this of the best score; 0 = best");
  v.number("lateral_distance", &V::lateral_distance, "(0, 1000]", "m",
           "a chosen candidate estimated this far or farther is reported as lateral, not a revisit");
  v.number("neighbour_frames", &V::neighbour_frames, "[0, 50]", "",
           "also verify the top-1 loop's database neighbours within this many frames; 0 = off");
  v.number("offset_decay_start", &V::offset_decay_start, "[0, 1000]", "m",
           "score is scaled down linearly for an estimated offset beyond this ...");
  // Config::validate also asks for 0 or more than offset_decay_start.
  v.number("offset_decay_end", &V::offset_decay_end, "[0, 1000]", "m", "... to 0 at this offset; 0 = no decay");
  v.number("min_footprint_overlap", &V::min_footprint_overlap, "[0, 1]", "",
           "reject a verified candidate whose pose puts less than this share of the query's structure cells on the "
           "match's; 0 = off");
  v.number("max_seen_through", &V::max_seen_through, "[0, 1]", "",
           "reject a verified candidate when, under its pose, one frame's beams went past more than this share of the "
           "other's structure taller than the sensor; 1 = off");
  v.number("footprint_search", &V::footprint_search, "[0, 40]", "m",
           "shift the declared loop's pose by up to this far in x and y to where the footprints agree best ...; "
           "0 = off");
  v.number("footprint_search_gain", &V::footprint_search_gain, "[0, 1]", "",
           "... when they agree there by this much more (footprint share)");
  v.number("footprint_cell", &V::footprint_cell, "[0.2, 10]", "m", "side of a footprint cell");
  v.number("footprint_radius", &V::footprint_radius, "[5, 200]", "m", "footprints reach this far from the sensor");
  v.number("seed", &V::seed, "[0, 4294967295]", "", "RANSAC seed (std::mt19937)");
}

}  // namespace sgtllc::detail
