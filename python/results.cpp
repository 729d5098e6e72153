// Result types of the detector and of compare_pair, read-only, field by field as in include/sgtllc/detector.h,
// verification.h and node_extraction.h. Eigen members (T_match_query) are (4, 4) float64 arrays that view the
// result (no copy). Adding a field is one `.def_readonly` line here and one line in sgtllc.pyi.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "opaque.h"
#include "sgtllc/detector.h"

namespace sgtllc::python {
namespace {

/// (K, 2) int32 (query node, match node) of the associations @p which (all if null).
py::array_t<int32_t> pairsArray(const MatchResult& r, const std::vector<int>* which) {
  const size_t n = which ? which->size() : r.associations.size();
  py::array_t<int32_t> out({static_cast<py::ssize_t>(n), py::ssize_t{2}});
  auto o = out.mutable_unchecked<2>();
  for (size_t k = 0; k < n; ++k) {
    const NodeMatch& a = r.associations[which ? static_cast<size_t>((*which)[k]) : k];
    o(static_cast<py::ssize_t>(k), 0) = a.query;
    o(static_cast<py::ssize_t>(k), 1) = a.match;
  }
  return out;
}

const Candidate* best(const FrameResult& r) { return r.best >= 0 ? &r.candidates[static_cast<size_t>(r.best)] : nullptr; }

}  // namespace

void bindResults(py::module_& m) {
  py::enum_<Rejection>(m, "Rejection", "Why a candidate got a zero score.")
      .value("NONE", Rejection::kNone, "passed the gates and RANSAC accepted a hypothesis")
      .value("FEW_ASSOCIATIONS", Rejection::kFewAssociations, "score_c < σ_3 or |LA| < min_associations")
      .value("RANSAC_FAILED", Rejection::kRansacFailed, "no hypothesis reached min_inliers")
      .value("FOOTPRINT_MISMATCH", Rejection::kFootprint,
             "the pose puts too few of the query's structure cells on the match's (footprint check)")
      .value("SEEN_THROUGH", Rejection::kSeenThrough,
             "under the pose, one sensor saw through too much of what the other saw (seen-through check)");
  py::class_<SeenThrough>(m, "SeenThrough", "The seen-through check of a verified pose (sight.h).")
      .def_readonly("judged", &SeenThrough::judged,
                    "structure returns of both frames within the other's view (0: the check did not run)")
      .def_readonly("seen_through", &SeenThrough::seen_through, "of those, the ones the other sensor saw through")
      .def_property_readonly("share", &SeenThrough::share, "seen_through / judged (0 if none judged)");

  py::class_<FootprintOverlap>(m, "FootprintOverlap", "The footprint check of a verified pose.")
      .def_readonly("compared", &FootprintOverlap::compared,
                    "query structure cells compared (0: the check did not run)")
      .def_readonly("share", &FootprintOverlap::share, "share of them on or next to a match structure cell")
      .def_readonly("seen", &FootprintOverlap::seen, "the two frames' sights under the pose (SeenThrough)");
  py::class_<FootprintShift>(m, "FootprintShift", "The footprint search of a verified pose (algorithm 7.9).")
      .def_property_readonly("shift",
                             [](const FootprintShift& s) { return py::make_tuple(s.shift.x(), s.shift.y()); },
                             "(x, y) m added to the pose's translation; (0, 0) unless it gained "
                             "verification.footprint_search_gain")
      .def_readonly("compared", &FootprintShift::compared, "query structure cells judged (0: the search did not run)")
      .def_readonly("share", &FootprintShift::share, "share of them on or next to a match structure cell, shifted")
      .def_readonly("unshifted_share", &FootprintShift::unshifted_share, "... and under the pose before the shift");
  py::enum_<Search>(m, "Search", "Whether a frame's query searched the database, or why not.")
      .value("SEARCHED", Search::kSearched, "older frames existed and were searched")
      .value("TOO_RECENT", Search::kTooRecent, "no stored frame is retrieval.exclude_recent or more frames older")
      .value("WARMUP", Search::kWarmup, "frame < retrieval.warmup_frames");

  py::class_<StageTimes>(m, "StageTimes", "Wall-clock time per stage (ms).")
      .def_readonly("extraction_ms", &StageTimes::extraction_ms, "clustering and centres (0 when nodes are given)")
      .def_readonly("description_ms", &StageTimes::description_ms, "graph, local and global descriptors")
      .def_readonly("retrieval_ms", &StageTimes::retrieval_ms, "K-nearest-neighbour search")
      .def_readonly("verification_ms", &StageTimes::verification_ms, "association, RANSAC and pose")
      .def_readonly("refinement_ms", &StageTimes::refinement_ms, "fine registration, its clouds included")
      .def_property_readonly("total_ms", &StageTimes::total_ms, "sum of the stages");

  py::class_<ExtractionStats>(m, "ExtractionStats", "What happened to a scan's points on their way to nodes.")
      .def_readonly("input_points", &ExtractionStats::input_points, "points given")
      .def_readonly("nonfinite_points", &ExtractionStats::nonfinite_points, "points with NaN/Inf, dropped")
      .def_readonly("far_points", &ExtractionStats::far_points, "points beyond ±1e6 m, dropped")
      .def_readonly("unknown_label_points", &ExtractionStats::unknown_label_points, "ids outside the label space")
      .def_readonly("class_points", &ExtractionStats::class_points, "kept points per class (16 entries)")
      .def_readonly("clusters", &ExtractionStats::clusters, "clusters of at least min_size per class (16 entries)")
      .def_readonly("duplicates_suppressed", &ExtractionStats::duplicates_suppressed, "same-class duplicates skipped")
      .def_readonly("capped_nodes", &ExtractionStats::capped_nodes, "nodes dropped above graph.max_nodes");

  py::class_<NodeMatch>(m, "NodeMatch", "One association: query node index, match node index, similarity S.")
      .def_readonly("query", &NodeMatch::query, "index into the query nodes")
      .def_readonly("match", &NodeMatch::match, "index into the match nodes")
      .def_readonly("similarity", &NodeMatch::similarity, "node similarity S (algorithm §6)")
      .def_readonly("guided", &NodeMatch::guided, "paired by guided matching under the pose (algorithm §7.2), not LA")
      .def("__repr__", [](const NodeMatch& a) {
        return "NodeMatch(query=" + std::to_string(a.query) + ", match=" + std::to_string(a.match) + ")";
      });

  py::class_<MatchResult>(m, "MatchResult", "Verification of a query frame against one match frame.")
      .def_readonly("associations", &MatchResult::associations, "LA as NodeMatch objects, in query-node order, then the pairs guided matching added (NodeMatch.guided)")
      .def_readonly("inliers", &MatchResult::inliers, "indices into associations of the inliers (RANSAC's, or guided matching's when more)")
      .def_readonly("score_c", &MatchResult::score_c, "|LA| / M")
      .def_readonly("score", &MatchResult::score, "loop score; 0 unless rejection is NONE")
      .def_readonly("score_t", &MatchResult::score, "the old name of score, kept one release")
      .def_readonly("rejection", &MatchResult::rejection, "why score is 0, or NONE")
      .def_readonly("T_match_query", &MatchResult::T_match_query, "(4, 4): p_match = T_match_query @ p_query")
      .def_readonly("footprint", &MatchResult::footprint, "the footprint check under the verified pose")
      .def_readonly("footprint_search", &MatchResult::footprint_search,
                    "the footprint search (FootprintShift): the shift the pose includes, if any")
      .def_readonly("by_consistency", &MatchResult::by_consistency,
                    "the pairs came from the consistency path, not from the descriptors (algorithm 7.8)")
      .def_property_readonly("association_pairs", [](const MatchResult& r) { return pairsArray(r, nullptr); },
                             "(K, 2) int32: query node, match node of every association")
      .def_property_readonly("inlier_pairs", [](const MatchResult& r) { return pairsArray(r, &r.inliers); },
                             "(n_in, 2) int32: query node, match node of every inlier");

  py::class_<Candidate>(m, "Candidate", "One retrieved candidate frame and its verification.")
      .def_readonly("frame", &Candidate::frame, "database index of the candidate")
      .def_readonly("distance2", &Candidate::distance2, "squared L2 distance of the global descriptors")
      .def_readonly("retrieved", &Candidate::retrieved,
                    "False for a database neighbour of the top-1 verified by verification.neighbour_frames")
      .def_readonly("match", &Candidate::match, "MatchResult (query -> candidate)")
      .def_readonly("refinement", &Candidate::refinement, "Refinement of the declared loop (registration.online), or None");

  py::class_<FrameResult>(m, "FrameResult", "What the detector found for one frame.")
      .def_readonly("frame", &FrameResult::frame, "index of this frame (0, 1, 2, ... in processing order)")
      .def_readonly("num_nodes", &FrameResult::num_nodes, "nodes of this frame")
      .def_readonly("extraction", &FrameResult::extraction, "point bookkeeping (zeros when nodes were given)")
      .def_readonly("search", &FrameResult::search, "whether the database was searched, or why not")
      .def_readonly("candidates", &FrameResult::candidates, "retrieved candidates in ascending frame index")
      .def_readonly("best", &FrameResult::best, "index into candidates of the highest score, or -1")
      .def_readonly("is_loop", &FrameResult::is_loop, "candidates[best].match.score > σ_4")
      .def_readonly("lateral", &FrameResult::lateral, "candidates[best] is estimated >= lateral_distance away")
      .def_readonly("timing", &FrameResult::timing, "stage times of this frame")
      .def_property_readonly("loop", &FrameResult::loop, py::return_value_policy::reference_internal,
                             "the loop-closing Candidate, or None")
      .def_property_readonly("match_frame", [](const FrameResult& r) { return best(r) ? best(r)->frame : -1; },
                             "frame index of the best candidate, or -1")
      .def_property_readonly("score", [](const FrameResult& r) { return best(r) ? best(r)->match.score : 0.0; },
                             "score of the best candidate (0 without one)")
      .def_property_readonly("score_t", [](const FrameResult& r) { return best(r) ? best(r)->match.score : 0.0; },
                             "the old name of score, kept one release")
      .def_property_readonly("score_c", [](const FrameResult& r) { return best(r) ? best(r)->match.score_c : 0.0; },
                             "score_c of the best candidate (0 without one)")
      .def_property_readonly("T_match_query", [](const FrameResult& r) {
        return matrixToArray(best(r) ? best(r)->match.T_match_query : Eigen::Matrix4d::Identity());
      }, "(4, 4) pose of the best candidate (identity without one)");

  py::class_<PairResult>(m, "PairResult", "Result of comparing two frames directly.")
      .def_readonly("match", &PairResult::match, "MatchResult (query -> match)")
      .def_readonly("is_loop", &PairResult::is_loop, "score > σ_4")
      .def_readonly("extraction_query", &PairResult::extraction_query, "point bookkeeping of the query scan")
      .def_readonly("extraction_match", &PairResult::extraction_match, "point bookkeeping of the match scan")
      .def_readonly("timing", &PairResult::timing, "both frames' extraction and description; verification")
      .def_readonly("refinement", &PairResult::refinement, "Refinement (labelled scans, registration.pair), or None")
      .def_property_readonly("query_nodes", [](const PairResult& r) { return nodesToArrays(r.query_nodes); },
                             "(centres (M, 3) float64, classes (M,) int32) that NodeMatch.query indexes")
      .def_property_readonly("match_nodes", [](const PairResult& r) { return nodesToArrays(r.match_nodes); },
                             "(centres (N, 3) float64, classes (N,) int32) that NodeMatch.match indexes")
      .def_property_readonly("score", [](const PairResult& r) { return r.match.score; }, "match.score")
      .def_property_readonly("score_t", [](const PairResult& r) { return r.match.score; },
                             "the old name of score, kept one release")
      .def_property_readonly("score_c", [](const PairResult& r) { return r.match.score_c; }, "match.score_c")
      .def_property_readonly("rejection", [](const PairResult& r) { return r.match.rejection; }, "match.rejection")
      .def_property_readonly("T_match_query", [](const PairResult& r) { return matrixToArray(r.match.T_match_query); },
                             "(4, 4) match.T_match_query");
}

}  // namespace sgtllc::python
