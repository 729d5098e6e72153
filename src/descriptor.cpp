#include "sgtllc/descriptor.h"

#include <algorithm>
#include <bitset>
#include <cmath>

namespace sgtllc {

int SlotMask::count() const {
  int n = 0;
  for (uint64_t w : words) n += static_cast<int>(std::bitset<64>(w).count());
  return n;
}

std::vector<float> LocalDescriptor::flat() const {
  std::vector<float> out(3 * static_cast<size_t>(slots.size()));
  for (int a = 0; a < numSlots(); ++a) {
    for (int e = 0; e < 3; ++e) out[3 * a + e] = slots[a][e];
  }
  return out;
}

Eigen::Vector3d triangleTerms(const Eigen::Vector3d& pi, const Eigen::Vector3d& pj, const Eigen::Vector3d& pk) {
  return {(pj - pi).dot(pk - pi), (pi - pj).dot(pk - pj), (pi - pk).dot(pj - pk)};
}

Eigen::Vector3d vertexEntries(const Eigen::Vector3d& t, SubVectorKind kind) {
  if (kind == SubVectorKind::kDotProducts) return t;
  // Squared sides from the dot products: |ij|² = a_i + a_j, |ik|² = a_i + a_k, |jk|² = a_j + a_k (algorithm §4).
  const double ij = std::sqrt(std::max(0.0, t[0] + t[1]));
  const double ik = std::sqrt(std::max(0.0, t[0] + t[2]));
  const double jk = std::sqrt(std::max(0.0, t[1] + t[2]));
  if (kind == SubVectorKind::kLengths) return {jk, ik, ij};
  const auto cosine = [](double dot, double a, double b) { return a * b > 0.0 ? dot / (a * b) : 0.0; };
  return {cosine(t[0], ij, ik), cosine(t[1], ij, jk), cosine(t[2], ik, jk)};
}

Eigen::Vector3d slotTerms(const Eigen::Vector3f& slot, SubVectorOrder order) {
  const Eigen::Vector3d s = slot.cast<double>();
  if (order == SubVectorOrder::kPaper) return s;
  return {s[0], -s[2], s[1]};  // code order (a_i, a_k, −a_j)
}

std::vector<LocalDescriptor> computeLocalDescriptors(const SemanticGraph& graph, const DescriptorConfig& config) {
  const int num_slots = graph.numSlots();
  std::vector<LocalDescriptor> out(static_cast<size_t>(graph.size()), LocalDescriptor(num_slots));
  for (int i = 0; i < graph.size(); ++i) {
    LocalDescriptor& des = out[i];
    Eigen::Vector3f* slots = des.slots.data();
    const SlotRow<const TwoStepPath> paths = graph.paths[i];
    for (int a = 0; a < num_slots; ++a) {
      const TwoStepPath& path = paths[a];
      // A k = i winner (only with graph.allow_k_equals_i) blocks the slot but is degenerate (a_i = a_k = 0): the
      // authors' code never enables it on the query side (algorithm §3, §4), so it stays empty here.
      if (!path.exists() || path.k == i) continue;
      const Eigen::Vector3d e = vertexEntries(
          triangleTerms(graph.nodes[i].centre, graph.nodes[path.j].centre, graph.nodes[path.k].centre), config.kind);
      slots[a] = (config.order == SubVectorOrder::kPaper ? e : Eigen::Vector3d(e[0], e[2], -e[1])).cast<float>();
      des.valid.set(a);
    }
  }
  return out;
}

}  // namespace sgtllc
