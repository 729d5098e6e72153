/// @file consistent_matching.h
/// @brief Node pairs chosen by their geometric consistency instead of their descriptors (algorithm §7.8).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sgtllc/association.h"
#include "sgtllc/config.h"
#include "sgtllc/frame.h"

namespace sgtllc {

/// Hypothesis pairs: for every non-isolated query node, its @p per_node most similar same-class match nodes
/// (nodeSimilarity, ties to the lower index; a similarity of 0 still counts: the descriptor is what this step does
/// not trust). In query-node order, then by rank. Of more than @p max_pairs, the most similar are kept (ties to the
/// earlier), in that order.
std::vector<NodeMatch> hypothesisPairs(const DescribedFrame& query, const DescribedFrame& match, int per_node,
                                       const AssociationConfig& association, const DescriptorConfig& descriptor,
                                       int max_pairs = 256);
/// The same, from the similarities already computed (association.h).
std::vector<NodeMatch> hypothesisPairs(const NodeSimilarities& similarities, int per_node, int max_pairs = 256);

/// The largest set of pairs (source_k, target_k) that are one-to-one (no source or target point used twice; the
/// caller gives each point one index, @p source_ids and @p target_ids) and pairwise consistent: every two of them
/// have source and target distances that differ by less than @p tolerance (m). A rigid motion keeps distances, so
/// the true pairs of a revisit form such a set whatever their descriptors said. Exact branch and bound over at most
/// 256 pairs (more are cut, in order), stopped after @p max_steps expansions (then the best set so far); ties go to
/// the set found first, so the result is a pure function of the input order. Indices ascending.
std::vector<int> largestConsistentSet(const std::vector<Eigen::Vector3d>& source,
                                      const std::vector<Eigen::Vector3d>& target, const std::vector<int>& source_ids,
                                      const std::vector<int>& target_ids, double tolerance, int max_steps = 20000);

}  // namespace sgtllc
