/// @file guided_matching.h
/// @brief Guided matching of nodes under a verified pose (algorithm §7.2): the inliers the descriptors missed.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sgtllc/association.h"
#include "sgtllc/graph.h"

namespace sgtllc {

/// Node pairs that the pose @p T_match_query puts together: query node i and the same-class match node j nearest to
/// T·p_i, kept iff each is the other's nearest same-class node under the pose and they lie closer than @p radius (m).
/// One-to-one, in query-node order; ties go to the lower index. NodeMatch::similarity is 0 (no descriptor compared).
std::vector<NodeMatch> pairsUnderPose(const SemanticGraph& query, const SemanticGraph& match,
                                      const Eigen::Matrix4d& T_match_query, double radius);

/// The result of guidedMatching: the node pairs and the pose fitted to them.
struct GuidedMatch {
  std::vector<NodeMatch> pairs;  ///< one-to-one, in query-node order (pairsUnderPose)
  Eigen::Matrix4d T_match_query = Eigen::Matrix4d::Identity();  ///< Kabsch on the pairs' centres
};

/// Starting from a verified pose, pairs nodes under it (pairsUnderPose), refits the pose to those pairs, and
/// repeats while the pairs grow, at most @p rounds times; a refit that turns z by more than @p max_tilt (rad,
/// isUpright) ends the rounds before it. Returns the largest pair set with the pose fitted to it (the pairs were
/// found under the pose before, as RANSAC counts inliers under its hypothesis and then refits); empty pairs (and the
/// identity) if no round found more than @p more_than pairs, so a caller keeps what it had.
GuidedMatch guidedMatching(const SemanticGraph& query, const SemanticGraph& match, const Eigen::Matrix4d& T_match_query,
                           double radius, size_t more_than, double max_tilt = 3.14159265358979323846,
                           int rounds = 3);

}  // namespace sgtllc
