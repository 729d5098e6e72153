#include "sgtllc/verification.h"

#include <algorithm>
#include <cmath>

#include "internal/rigid_inverse.h"
#include "sgtllc/consistent_matching.h"
#include "sgtllc/guided_matching.h"
#include "sgtllc/ransac.h"

namespace sgtllc {

const char* rejectionName(Rejection r) {
  switch (r) {
    case Rejection::kNone:
      return "none";
    case Rejection::kFewAssociations:
      return "few_associations";
    case Rejection::kRansacFailed:
      return "ransac_failed";
    case Rejection::kFootprint:
      return "footprint_mismatch";
    case Rejection::kSeenThrough:
      return "seen_through";
  }
  return "?";
}

RansacParams ransacParams(const VerificationConfig& config) {
  RansacParams p;
  p.iterations = config.ransac_iterations;
  p.sample_size = config.ransac_sample_size;
  p.with_replacement = config.sample_with_replacement;
  p.inlier_threshold = config.inlier_threshold;
  p.min_inliers = config.min_inliers;
  p.min_inlier_fraction = config.min_inlier_fraction;
  p.confidence = config.ransac_confidence;
  p.max_tilt = config.max_tilt_deg * M_PI / 180.0;
  p.seed = config.seed;
  return p;
}

double offsetWeight(double offset_m, const VerificationConfig& config) {
  const double start = config.offset_decay_start, end = config.offset_decay_end;
  if (end <= 0.0 || offset_m <= start) return 1.0;
  if (offset_m >= end) return 0.0;
  return (end - offset_m) / (end - start);
}

namespace {

/// Guided matching (algorithm §7.2): the nodes the RANSAC pose pairs become the inliers when they are more than
/// RANSAC's, and the pose is refitted to them. A pair already in LA keeps its index; the others are appended to
/// the associations, marked NodeMatch::guided.
void addGuidedInliers(const DescribedFrame& query, const DescribedFrame& match, const RansacParams& params,
                      MatchResult* result) {
  GuidedMatch guided = guidedMatching(query.graph, match.graph, result->T_match_query, params.inlier_threshold,
                                      result->inliers.size(), params.max_tilt);
  if (guided.pairs.empty()) return;
  // LA holds at most one pair per query node (associateNodes), so a query node finds its LA pair directly.
  std::vector<int> in_la(static_cast<size_t>(query.numNodes()), -1);
  const int la = static_cast<int>(result->associations.size());
  for (int k = 0; k < la; ++k) in_la[result->associations[k].query] = k;
  result->inliers.clear();
  for (NodeMatch& pair : guided.pairs) {
    const int k = in_la[pair.query];
    if (k >= 0 && result->associations[k].match == pair.match) {
      result->inliers.push_back(k);
    } else {
      pair.guided = true;
      result->inliers.push_back(static_cast<int>(result->associations.size()));
      result->associations.push_back(pair);
    }
  }
  std::sort(result->inliers.begin(), result->inliers.end());
  result->T_match_query = guided.T_match_query;
}

/// Fewest query cells the footprint check compares before it judges: a scan of open fields or one whose pose
/// leaves it mostly outside the match's reach says too little either way.
constexpr int kMinFootprintCells = 20;
/// Fewest structure returns (of both frames) the seen-through check judges before it judges the pose: a scan of
/// open fields, or two whose sights barely overlap under the pose.
constexpr int kMinSightReturns = 40;

/// The footprint check (algorithm §7.7): a pose under which the structure around the nodes does not agree is not
/// a revisit, however many nodes agree.
void checkFootprints(const DescribedFrame& query, const DescribedFrame& match, const VerificationConfig& vc,
                     MatchResult* result) {
  if (vc.min_footprint_overlap <= 0.0 || query.footprint.empty() || match.footprint.empty()) return;
  result->footprint = footprintOverlap(query.footprint, match.footprint, result->T_match_query);
  // Three or four nodes of two places agree by chance far more often than five: such weak evidence needs the
  // structure around it to agree more (BENCHMARKS.md, "Weak evidence").
  const bool weak = result->by_consistency || static_cast<int>(result->inliers.size()) <= vc.weak_inliers;
  const double needed = weak ? std::max(vc.min_footprint_overlap, vc.weak_min_footprint) : vc.min_footprint_overlap;
  const SeenThrough& seen = result->footprint.seen;
  if (result->footprint.compared >= kMinFootprintCells && result->footprint.share < needed) {
    result->rejection = Rejection::kFootprint;
  } else if (seen.judged >= kMinSightReturns && seen.share() > vc.max_seen_through) {
    // Structure where the other sensor's beams went on: one of the two scans would have seen it (BENCHMARKS.md,
    // "Seen through").
    result->rejection = Rejection::kSeenThrough;
  } else {
    return;
  }
  result->score = 0.0;
  result->T_match_query = Eigen::Matrix4d::Identity();
}

/// Whether class @p label's nodes count in the node counts when unmatched (ClassClusterConfig::score_unmatched;
/// a label outside the classes counts).
bool countsUnmatched(int label, const ClusterConfig& cluster) {
  return label < 0 || label >= static_cast<int>(cluster.classes.size()) ||
         cluster.classes[static_cast<size_t>(label)].score_unmatched;
}

/// The nodes of @p frame whose class counts unmatched (algorithm §7.3, "Node count").
int countedNodes(const DescribedFrame& frame, const ClusterConfig& cluster) {
  int n = 0;
  for (const Node& node : frame.graph.nodes) n += countsUnmatched(node.label, cluster) ? 1 : 0;
  return n;
}

/// The nodes of @p frame that count unmatched and that, moved by @p T_other_frame, lie within @p other's reach:
/// its farthest node's horizontal range plus @p margin.
int covisibleNodes(const DescribedFrame& frame, const DescribedFrame& other, const Eigen::Matrix4d& T_other_frame,
                   double margin, const ClusterConfig& cluster) {
  double reach = 0.0;
  for (const Node& node : other.graph.nodes) reach = std::max(reach, node.centre.head<2>().norm());
  reach += margin;
  const Eigen::Matrix3d R = T_other_frame.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = T_other_frame.topRightCorner<3, 1>();
  int n = 0;
  for (const Node& node : frame.graph.nodes) {
    if (countsUnmatched(node.label, cluster) && (R * node.centre + t).head<2>().norm() <= reach) ++n;
  }
  return n;
}

/// The pairs of @p pairs (all of them, or those @p indices picks) whose class counts only when matched.
int matchedOnly(const DescribedFrame& query, const std::vector<NodeMatch>& pairs, const std::vector<int>* indices,
                const ClusterConfig& cluster) {
  int n = 0;
  const size_t count = indices ? indices->size() : pairs.size();
  for (size_t k = 0; k < count; ++k) {
    const NodeMatch& m = pairs[indices ? static_cast<size_t>((*indices)[k]) : k];
    n += countsUnmatched(query.graph.nodes[m.query].label, cluster) ? 0 : 1;
  }
  return n;
}

/// score_c = |LA| / M, M the query's node count (algorithm §7.1).
double associationShare(const DescribedFrame& query, const std::vector<NodeMatch>& la, const ClusterConfig& cluster) {
  const int nodes = countedNodes(query, cluster) + matchedOnly(query, la, nullptr, cluster);
  return nodes > 0 ? static_cast<double>(la.size()) / nodes : 0.0;
}

/// score of a pose-verified result under the configured formula, scaled by the offset decay; then the footprint
/// check (algorithm §7.3, §7.7).
void scoreVerified(const DescribedFrame& query, const DescribedFrame& match, const Config& config, int la,
                   MatchResult* result) {
  const VerificationConfig& vc = config.verification;
  const double n_in = static_cast<double>(result->inliers.size());
  switch (vc.score_formula) {
    case ScoreFormula::kPaper:
      result->score = n_in / la;
      break;
    case ScoreFormula::kLegacy:
      result->score = (n_in - 1.0) / la;
      break;
    case ScoreFormula::kOverlap: {
      // The larger graph's node count, a class that counts only matched adding its inliers (equal on both sides).
      const Eigen::Matrix4d& T = result->T_match_query;
      const int larger =
          vc.score_covisible
              ? std::max(covisibleNodes(query, match, T, vc.inlier_threshold, config.cluster),
                         covisibleNodes(match, query, internal::rigidInverse(T), vc.inlier_threshold, config.cluster))
              : std::max(countedNodes(query, config.cluster), countedNodes(match, config.cluster));
      result->score = n_in / std::max(1, larger + matchedOnly(query, result->associations, &result->inliers,
                                                              config.cluster));
      break;
    }
  }
  result->score *= offsetWeight(result->T_match_query.topRightCorner<3, 1>().norm(), vc);
  checkFootprints(query, match, vc, result);
}

/// The consistency path (algorithm §7.8): each query node's `consistency_pairs` most similar same-class match
/// nodes are hypotheses, their largest pairwise-consistent one-to-one set the inliers. Where the descriptors of a
/// sparse or re-labelled graph change with the viewpoint, the true pairs are rarely each node's best match but
/// still agree in their distances. Returns a result with rejection kRansacFailed when no rigid set is found.
MatchResult matchByConsistency(const DescribedFrame& query, const DescribedFrame& match,
                               const NodeSimilarities& similarities, const Config& config, double score_c) {
  const VerificationConfig& vc = config.verification;
  MatchResult result;
  result.score_c = score_c;
  result.rejection = Rejection::kRansacFailed;
  result.by_consistency = true;
  const std::vector<NodeMatch> pairs = hypothesisPairs(similarities, vc.consistency_pairs);
  if (static_cast<int>(pairs.size()) < vc.min_inliers) return result;
  std::vector<Eigen::Vector3d> source, target;
  std::vector<int> source_ids, target_ids;
  for (const NodeMatch& m : pairs) {
    source.push_back(query.graph.nodes[m.query].centre);
    target.push_back(match.graph.nodes[m.match].centre);
    source_ids.push_back(m.query);
    target_ids.push_back(m.match);
  }
  const std::vector<int> set =
      largestConsistentSet(source, target, source_ids, target_ids, 2.0 * vc.inlier_threshold);
  if (static_cast<int>(set.size()) < vc.min_inliers) return result;
  std::vector<Eigen::Vector3d> src_in, dst_in;
  for (int k : set) {
    src_in.push_back(source[k]);
    dst_in.push_back(target[k]);
  }
  const Eigen::Matrix4d T = fitRigid(src_in, dst_in);
  const double max_tilt = vc.max_tilt_deg * M_PI / 180.0;
  if (!isUpright(T, max_tilt)) return result;
  // Consistent distances allow a mirror image; the fit's residuals do not.
  const double thr2 = vc.inlier_threshold * vc.inlier_threshold;
  for (int k : set) {
    if ((T.topLeftCorner<3, 3>() * source[k] + T.topRightCorner<3, 1>() - target[k]).squaredNorm() < thr2) {
      result.inliers.push_back(static_cast<int>(result.associations.size()));
      result.associations.push_back(pairs[k]);
    }
  }
  if (static_cast<int>(result.inliers.size()) < vc.min_inliers) {
    result.inliers.clear();
    result.associations.clear();
    return result;
  }
  result.rejection = Rejection::kNone;
  result.T_match_query = T;
  if (vc.guided_matching) addGuidedInliers(query, match, ransacParams(vc), &result);
  scoreVerified(query, match, config, static_cast<int>(result.associations.size()), &result);
  return result;
}

/// The paper's path: LA by descriptors, the gates, RANSAC, guided matching (algorithm §6, §7.1–§7.3).
MatchResult matchByDescriptors(const DescribedFrame& query, const DescribedFrame& match,
                               const NodeSimilarities& similarities, const Config& config) {
  const VerificationConfig& vc = config.verification;
  MatchResult result;
  result.associations = associateNodes(similarities, config.association);
  const int la = static_cast<int>(result.associations.size());
  result.score_c = associationShare(query, result.associations, config.cluster);
  if (result.score_c < vc.sigma_3 || la < vc.min_associations || la == 0) {
    result.rejection = Rejection::kFewAssociations;
    return result;
  }

  // Source = query node centres, target = match node centres, so the pose maps query into match (algorithm §7.5).
  std::vector<Eigen::Vector3d> source, target;
  for (const NodeMatch& m : result.associations) {
    source.push_back(query.graph.nodes[m.query].centre);
    target.push_back(match.graph.nodes[m.match].centre);
  }
  if (!vc.use_ransac) {
    // Table IV "w/o RANSAC": score_c is the score and every association is used for the pose.
    result.rejection = Rejection::kNone;
    result.score = result.score_c;
    for (int k = 0; k < la; ++k) result.inliers.push_back(k);
    result.T_match_query = fitRigid(source, target);
    return result;
  }
  const RansacParams params = ransacParams(vc);
  const RansacResult ransac = ransacRigid(source, target, params);
  if (!ransac.accepted) {
    result.rejection = Rejection::kRansacFailed;
    return result;
  }
  result.rejection = Rejection::kNone;
  result.inliers = ransac.inliers;
  std::vector<Eigen::Vector3d> src_in, dst_in;
  for (int k : ransac.inliers) {
    src_in.push_back(source[k]);
    dst_in.push_back(target[k]);
  }
  result.T_match_query = fitRigid(src_in, dst_in);
  // RANSAC checked its hypotheses; a refit to nearly collinear centres leaves the turn about their line free.
  if (!isUpright(result.T_match_query, params.max_tilt)) result.T_match_query = ransac.T_target_source;
  if (vc.guided_matching && vc.score_formula == ScoreFormula::kOverlap) addGuidedInliers(query, match, params, &result);
  scoreVerified(query, match, config, la, &result);
  return result;
}

}  // namespace

void searchFootprints(const DescribedFrame& query, const DescribedFrame& match, const VerificationConfig& vc,
                      MatchResult* result) {
  if (vc.footprint_search <= 0.0 || !isLoop(*result, vc) || result->footprint.compared < kMinFootprintCells) return;
  // No shift can gain enough over footprints that already agree this well (most loops of a 64-beam sensor).
  if (result->footprint.share + vc.footprint_search_gain > 1.0) return;
  FootprintShift& s = result->footprint_search;
  s = bestFootprintShift(query.footprint, match.footprint, result->T_match_query, vc.footprint_search,
                         kMinFootprintCells, vc.footprint_search_gain);
  // A best shift on the edge of the searched square is no peak: the structure may agree better beyond it.
  const double edge = std::floor(vc.footprint_search / query.footprint.cell) * query.footprint.cell;
  const bool on_edge = std::abs(s.shift.x()) >= edge || std::abs(s.shift.y()) >= edge;
  if (s.compared == 0 || on_edge || !(s.share >= s.unshifted_share + vc.footprint_search_gain)) {
    s.shift.setZero();
    s.share = s.unshifted_share;
    return;
  }
  Eigen::Matrix4d shifted = result->T_match_query;
  shifted(0, 3) += s.shift.x();
  shifted(1, 3) += s.shift.y();
  result->T_match_query = shifted;
  // The search moves in whole cells; the nodes the shifted pose pairs refine it within one cell. The pairs of the
  // nodes' pose stay the result's inliers: they are the loop's evidence.
  const GuidedMatch refit = guidedMatching(query.graph, match.graph, shifted, vc.inlier_threshold,
                                           static_cast<size_t>(std::max(0, vc.min_inliers - 1)),
                                           vc.max_tilt_deg * M_PI / 180.0);
  if (!refit.pairs.empty() &&
      (refit.T_match_query.topRightCorner<2, 1>() - shifted.topRightCorner<2, 1>()).norm() <= query.footprint.cell) {
    result->T_match_query = refit.T_match_query;
  }
  // What the footprints say under the pose the result now has; the check's decision, under the nodes' pose, stands.
  result->footprint = footprintOverlap(query.footprint, match.footprint, result->T_match_query);
}

MatchResult matchFrames(const DescribedFrame& query, const DescribedFrame& match, const Config& config) {
  // The node similarities are computed once: the consistency path ranks the same ones.
  const NodeSimilarities similarities = nodeSimilarities(query, match, config.association, config.descriptor);
  MatchResult result = matchByDescriptors(query, match, similarities, config);
  const VerificationConfig& vc = config.verification;
  if (vc.consistency_pairs <= 0 || !vc.use_ransac || vc.score_formula != ScoreFormula::kOverlap ||
      isLoop(result, vc)) {
    return result;
  }
  // Its many hypotheses find a small consistent set more often by chance than RANSAC on LA does, so it answers
  // only where the footprints can judge its pose, and by a stricter share (BENCHMARKS.md "Consistency path").
  if (query.footprint.empty() || match.footprint.empty() || vc.min_footprint_overlap <= 0.0) return result;
  MatchResult consistent = matchByConsistency(query, match, similarities, config, result.score_c);
  if (!isLoop(consistent, vc) || consistent.footprint.compared < kMinFootprintCells) {
    return result;
  }
  return consistent;
}

}  // namespace sgtllc
