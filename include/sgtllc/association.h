/// @file association.h
/// @brief Node association between two frames by counting similar sub-vectors (algorithm §6, paper Algorithm 1).
#pragma once

#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/frame.h"

namespace sgtllc {

/// One associated node pair: query node index, match node index and their similarity S.
struct NodeMatch {
  int query = 0;
  int match = 0;
  double similarity = 0.0;
  /// Paired by guided matching under the verified pose (algorithm §7.2), not by the descriptors; similarity 0.
  bool guided = false;
};

/// Similarity S[i][j] of query node i and match node j (algorithm §6): over the slots valid in the query, the share
/// (or, with NodeScore::kCount, the number) whose sub-vectors are valid in both with cos > σ_1 over the kept
/// entries (AssociationConfig::entries) and, for dot-product slots, |Δa_j| below max_delta_aj. Returns 0 if
/// node i has no valid slot.
double nodeSimilarity(const LocalDescriptor& query, const LocalDescriptor& match, const AssociationConfig& config,
                      const DescriptorConfig& descriptor);

/// The similarity of every non-isolated query node to every same-class match node: the pairs of query node i are
/// pairs[start[k]] … pairs[start[k + 1] − 1] for the k-th non-isolated node, in match-node order. Computed once
/// per candidate, it serves both the association and the consistency path (consistent_matching.h).
struct NodeSimilarities {
  std::vector<int> start;        ///< one more entry than there are non-isolated query nodes
  std::vector<NodeMatch> pairs;  ///< query, match, similarity
};
NodeSimilarities nodeSimilarities(const DescribedFrame& query, const DescribedFrame& match,
                                  const AssociationConfig& config, const DescriptorConfig& descriptor);

/// LA: for every non-isolated query node, its most similar same-class match node (ties to the lowest index),
/// kept iff S ≥ σ_2. Several query nodes may share a match node, as in Algorithm 1. In query-node order.
std::vector<NodeMatch> associateNodes(const DescribedFrame& query, const DescribedFrame& match,
                                      const AssociationConfig& config, const DescriptorConfig& descriptor);
/// The same, from the similarities already computed.
std::vector<NodeMatch> associateNodes(const NodeSimilarities& similarities, const AssociationConfig& config);

}  // namespace sgtllc
