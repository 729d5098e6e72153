#include "sgtllc/association.h"

#include <algorithm>
#include <cmath>

namespace sgtllc {

double nodeSimilarity(const LocalDescriptor& query, const LocalDescriptor& match, const AssociationConfig& config,
                      const DescriptorConfig& descriptor) {
  // Only the mask words that hold slots: one for up to 8 classes (64 slots).
  const int query_words = (query.numSlots() + 63) / 64;
  const int words = (std::min(query.numSlots(), match.numSlots()) + 63) / 64;
  int enable = 0;  // query.numValid()
  for (int w = 0; w < query_words; ++w) enable += __builtin_popcountll(query.valid.words[w]);
  if (enable == 0) return 0.0;
  // Entries compared (Table IV ablation drops one), in storage order.
  Eigen::Vector3f keep = Eigen::Vector3f::Zero();
  for (int v = 0; v < 3; ++v) {
    if (config.entries & (1u << v)) keep[storedIndex(v, descriptor.order)] = 1.0f;
  }
  const bool all = config.entries == 0b111;
  // The |Δa_j| test is in m² and belongs to dot-product slots (algorithm §6).
  const bool delta_test = descriptor.kind == SubVectorKind::kDotProducts && (config.entries & 0b010);
  const int vj = vjEntry(descriptor.order);
  const float sigma_1 = static_cast<float>(config.sigma_1);
  const float max_delta = static_cast<float>(config.max_delta_aj);
  int matches = 0;
  // Both slots must hold a triangle (algorithm §6 [CHOICE]); the code also matched empty candidate slots via NaN.
  const Eigen::Vector3f* query_slots = query.slots.data();
  const Eigen::Vector3f* match_slots = match.slots.data();
  for (int w = 0; w < words; ++w) {
    for (uint64_t both = query.valid.words[w] & match.valid.words[w]; both != 0; both &= both - 1) {
      const int a = 64 * w + __builtin_ctzll(both);
      const Eigen::Vector3f u = all ? query_slots[a] : query_slots[a].cwiseProduct(keep);
      const Eigen::Vector3f v = all ? match_slots[a] : match_slots[a].cwiseProduct(keep);
      if (delta_test && std::abs(u[vj] - v[vj]) >= max_delta) continue;
      // cos(u, v) > σ_1 without a division; a zero-length sub-vector never matches.
      if (u.dot(v) > sigma_1 * u.norm() * v.norm()) ++matches;
    }
  }
  return config.score == NodeScore::kRatio ? static_cast<double>(matches) / enable : matches;
}

NodeSimilarities nodeSimilarities(const DescribedFrame& query, const DescribedFrame& match,
                                  const AssociationConfig& config, const DescriptorConfig& descriptor) {
  NodeSimilarities out;
  // Sized once: the pairs of each query node are the match nodes of its class (a reservation only, so a label
  // outside the class indices just goes uncounted).
  std::vector<int> of_class;
  for (int j = 0; j < match.numNodes(); ++j) {
    const int label = match.graph.nodes[j].label;
    if (label < 0) continue;
    if (label >= static_cast<int>(of_class.size())) of_class.resize(static_cast<size_t>(label) + 1, 0);
    ++of_class[label];
  }
  size_t total = 0;
  int rows = 0;
  for (int i = 0; i < query.numNodes(); ++i) {
    if (query.graph.isolated[i]) continue;
    ++rows;
    const int label = query.graph.nodes[i].label;
    if (label >= 0 && label < static_cast<int>(of_class.size())) total += static_cast<size_t>(of_class[label]);
  }
  out.pairs.reserve(total);
  out.start.reserve(static_cast<size_t>(rows) + 1);
  out.start.push_back(0);
  for (int i = 0; i < query.numNodes(); ++i) {
    if (query.graph.isolated[i]) continue;
    const int label = query.graph.nodes[i].label;
    for (int j = 0; j < match.numNodes(); ++j) {
      if (match.graph.nodes[j].label != label) continue;
      out.pairs.push_back(NodeMatch{i, j, nodeSimilarity(query.local[i], match.local[j], config, descriptor)});
    }
    out.start.push_back(static_cast<int>(out.pairs.size()));
  }
  return out;
}

std::vector<NodeMatch> associateNodes(const NodeSimilarities& similarities, const AssociationConfig& config) {
  std::vector<NodeMatch> out;
  for (size_t k = 0; k + 1 < similarities.start.size(); ++k) {
    const NodeMatch* best = nullptr;
    for (int p = similarities.start[k]; p < similarities.start[k + 1]; ++p) {
      const NodeMatch& m = similarities.pairs[p];
      // Strict, starting from 0: ties keep the lowest match node (algorithm §6).
      if (m.similarity > (best ? best->similarity : 0.0)) best = &m;
    }
    if (best && best->similarity >= config.sigma_2) {
      out.push_back(NodeMatch{best->query, best->match, best->similarity});
    }
  }
  return out;
}

std::vector<NodeMatch> associateNodes(const DescribedFrame& query, const DescribedFrame& match,
                                      const AssociationConfig& config, const DescriptorConfig& descriptor) {
  return associateNodes(nodeSimilarities(query, match, config, descriptor), config);
}

}  // namespace sgtllc
