/// @file verification_config.h
/// @brief Settings of candidate verification: the association gates, RANSAC, the loop score and decision, the
///        footprint check and search (docs/algorithm.md §7).
#pragma once

#include <cstdint>

namespace sgtllc {

/// Formula of the loop score (algorithm §7.3).
enum class ScoreFormula {
  kPaper,    ///< n_in / |LA|, as the paper
  kLegacy,   ///< (n_in − 1) / |LA|, as the authors' code
  /// n_in / max(M, N): the share of the larger graph's nodes that are verified inliers [default]; M and N leave
  /// out the unmatched nodes of a class with ClassClusterConfig::score_unmatched false
  kOverlap,
};

struct VerificationConfig {
  /// σ_3: skip a candidate if score_c = |LA| / M < σ_3 (algorithm §7.1). [deviation: with the overlap
  /// score, which already divides by the larger graph, the paper's gates (σ_3 0.35, |LA| ≥ 7, 5 inliers;
  /// configs/paper.yaml) only dropped true loops in small graphs. BENCHMARKS.md "Verification gates"]
  double sigma_3 = 0.0;
  int min_associations = 3;       ///< ... or if |LA| is below this (algorithm §7.1)
  int ransac_iterations = 500;    ///< RANSAC hypotheses per candidate (algorithm §7.2)
  /// Node pairs drawn per hypothesis (algorithm §7.2). [deviation: the paper's and code's 7; the minimal
  /// 3, checked for distance consistency before the fit (src/ransac.cpp), is as good and faster. BENCHMARKS.md
  /// "Association and RANSAC sample"]
  int ransac_sample_size = 3;
  bool sample_with_replacement = true;  ///< draw with replacement, as the authors' code (algorithm §7.2)
  double inlier_threshold = 0.4;  ///< a pair is an inlier iff ‖R s + t − t′‖ < this (m) (algorithm §7.2)
  /// A hypothesis is accepted only with at least this many inliers (algorithm §7.2). [deviation:
  /// the authors' 5; see sigma_3]
  int min_inliers = 3;
  double min_inlier_fraction = 0.01;  ///< ... and at least this share of |LA| (algorithm §7.2)
  /// Adaptive RANSAC: stop once an all-inlier sample of the best hypothesis has been drawn with this probability;
  /// 1 = always run ransac_iterations, as the authors' code. [deviation: 500 fixed iterations cost
  /// ~0.5 ms per candidate that passes the gates; at the inlier ratios of true loops (60–80 %, algorithm §11) ~50
  /// suffice]
  double ransac_confidence = 0.999;
  /// score formula (algorithm §7.3). [deviation: the paper's n_in / |LA| scores two scans that share a few objects
  /// high although most of either graph is unmatched; dividing by the larger graph keeps revisits high and pushes
  /// partial overlaps down. BENCHMARKS.md "Loop score"]
  ScoreFormula score_formula = ScoreFormula::kOverlap;
  /// false = no RANSAC (Table IV "w/o RANSAC"): score = score_c and the pose is fitted to all associations.
  bool use_ransac = true;
  /// σ_4: a loop iff the best score > σ_4; 0.1 for MulRan and MCD (algorithm §7.4, §8) (every score
  /// formula, and score_c, lies in [0, 1]).
  double sigma_4 = 0.3;
  /// Score over the nodes each frame could have seen of the other (score_formula overlap): a node counts only if,
  /// under the pose, it lies within the other frame's reach (its farthest node, horizontally, plus
  /// inlier_threshold). Two scans taken apart share less of their surroundings than two taken at one place.
  /// Off by default: it gains on a sparse sensor's real scans (configs/nuscenes.yaml sets it), not on 64-beam ones.
  /// [beyond the paper: algorithm §7.3 "Covisible nodes"; BENCHMARKS.md "Covisible nodes"]
  bool score_covisible = false;
  /// Largest tilt (°) between the up axes of a loop's two scans: RANSAC skips a hypothesis whose rotation turns z
  /// by more (algorithm §7.2); 180 = no check. A sensor pitched by α on the vehicle turns z by up to 2α
  /// between passes driven opposite ways, so a mount pitched more than ~10° wants 180 (or its scans turned into a
  /// z-up frame). [deviation: the paper and the code fit any rotation, including the upside-down mirror of objects
  /// on flat ground. BENCHMARKS.md "Upright check"]
  double max_tilt_deg = 30.0;
  /// Guided matching (guided_matching.h, algorithm §7.2): after RANSAC, the nodes its pose pairs (mutual nearest
  /// same-class nodes closer than inlier_threshold) replace its inliers when they are more, and the pose is
  /// refitted to them. The descriptors associate each node with one candidate only, and where several nodes of a
  /// class look alike (poles along a street) they pick wrong ones that the pose would have paired. Only with
  /// score_formula overlap, which divides by the graph size: the other formulas count inliers among LA.
  bool guided_matching = true;
  /// The consistency path (consistent_matching.h, algorithm §7.8): when the descriptors' candidate is not a loop,
  /// each query node's this many most similar same-class match nodes become hypotheses and their largest
  /// pairwise-consistent set is verified as RANSAC's would be; 0 = off, as the paper. Only with
  /// score_formula overlap and use_ransac. [deviation: BENCHMARKS.md "Consistency path"]
  int consistency_pairs = 16;
  /// Weak evidence (algorithm §7.7): a loop verified by at most this many inliers must reach weak_min_footprint
  /// instead of min_footprint_overlap; 0 = no such rule. [deviation: BENCHMARKS.md "Weak evidence"]
  int weak_inliers = 4;
  /// ... the footprint share such a loop, and every loop of the consistency path, needs (for the consistency
  /// path the check must also have run: both frames from scans, min_footprint_overlap > 0).
  /// [deviation: BENCHMARKS.md "Consistency path", "Weak evidence"]
  double weak_min_footprint = 0.65;
  /// Top-1 choice (selection.h): 0 = the highest score, as the paper (algorithm §7.4); m > 0 = among the verified
  /// candidates scoring at least best − m, the one whose estimated translation is smallest, so that a revisit
  /// wins over its 3–20 m neighbours along the old pass. [deviation: tuned on the urban11 and sub7
  /// sequences, see BENCHMARKS.md ("Top-1 choice")]
  double select_margin = 0.15;
  /// A chosen candidate whose estimated offset ‖t(T_match_query)‖ is at least this is reported as lateral
  /// (FrameResult::lateral): a neighbour of the revisit along the old pass, not the revisit itself. It is still a
  /// loop (its pose is a valid constraint), but the top-1 protocol does not claim it as a revisit (m).
  /// [deviation: 3 m is the protocols' positive distance; BENCHMARKS.md, "Top-1 choice"]
  double lateral_distance = 3.0;
  /// Neighbour check of the top-1 (detector.h, Candidate::retrieved): when the chosen candidate is a loop, the
  /// database frames within ±neighbour_frames of it that retrieval did not return are verified too, and the top-1
  /// is chosen again among all (select_margin); 0 = off, as the paper. [deviation: the old pass's frame
  /// nearest the query often ranks just outside the K retrieved. BENCHMARKS.md "Top-1 choice"]
  int neighbour_frames = 2;
  /// Offset decay of score (verification.h, offsetWeight): a verified candidate whose estimated offset
  /// ‖t(T_match_query)‖ is at most offset_decay_start keeps its score; beyond, score is scaled down linearly to 0
  /// at offset_decay_end (m). [deviation: two passes along one street 20 m apart share many objects, so
  /// only their pose tells them from a revisit; a revisit 10–15 m aside keeps its score. BENCHMARKS.md "Offset
  /// decay of the loop score"]
  double offset_decay_start = 15.0;
  /// ... and the offset at which score reaches 0 (m); 0 = no decay, as the paper; else greater than
  /// offset_decay_start.
  double offset_decay_end = 20.0;
  /// Footprint check (footprint.h, algorithm §7.7): a verified candidate is rejected (Rejection::kFootprint) when,
  /// under its pose, fewer than this share of the query's structure cells land on or next to the match's (with at
  /// least 20 cells compared); 0 = off, as the paper. Needs the scans' points: frames given as nodes are not
  /// checked (a map file keeps its frames' footprints). [deviation: few nodes can agree by chance between two
  /// places; the walls around them rarely do. BENCHMARKS.md "Footprint check"]
  double min_footprint_overlap = 0.5;
  /// Seen-through check (sight.h, algorithm §7.7, "Seen through"; part of the footprint check, so only where it
  /// runs): a verified candidate is rejected (Rejection::kSeenThrough) when, under its pose, either sensor's beams
  /// went on well past more than this share of the other frame's nearest returns at the sensor's height (with at
  /// least 40 returns judged); 1 = off, the default: at 0.4 it removed no false loop on the simulated drives and
  /// cost the 32-beam drive h32 three true ones (BENCHMARKS.md "Seen through"). Below 1 the scans keep their
  /// sights and the share is reported (MatchResult::footprint.seen); 0.99 measures it and rejects nearly nothing.
  double max_seen_through = 1.0;
  /// Footprint search (searchFootprints in verification.h, algorithm §7.9): the declared loop's pose moves by the
  /// horizontal shift, within this reach (m, in x and in y), under which the footprints agree best, when they agree
  /// by footprint_search_gain more there; 0 = off, as the paper. Segments along a straight street are centred on
  /// the part a scan sees and evenly planted trees match their neighbours, so the nodes can agree on a pose metres
  /// short along the street; the structure beside it does not. The loop decision stays that of the nodes' pose.
  /// [deviation: BENCHMARKS.md "Footprint search"]
  double footprint_search = 15.0;
  /// ... the gain in footprint share a shift needs. [tuned on nuScenes scenes 0001 and 0005: BENCHMARKS.md
  /// "Footprint search"]
  double footprint_search_gain = 0.03;
  double footprint_cell = 0.5;     ///< side of a footprint cell (m)
  double footprint_radius = 40.0;  ///< a footprint covers the square reaching this far from the sensor (m)
  /// RANSAC random seed; every candidate starts from it (algorithm §7.2 [CHOICE]).
  uint32_t seed = 42;
};

}  // namespace sgtllc
