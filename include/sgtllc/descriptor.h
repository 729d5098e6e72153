/// @file descriptor.h
/// @brief 147-D local descriptors: one triangle sub-vector per class-pair slot (spec §4).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/graph.h"

namespace sgtllc {

/// Des_i ∈ R^{49×3}: slot α = 7m + n holds the triangle (i, j*, k*) of T_i[m][n] as one entry per vertex: by
/// default the raw dot products a_i, a_j, a_k (m²), see DescriptorConfig::kind.
struct LocalDescriptor {
  LocalDescriptor() {
    for (Eigen::Vector3f& s : slots) s.setZero();
  }

  std::array<Eigen::Vector3f, kNumSlots> slots;  ///< zero where the slot is empty
  uint64_t valid = 0;                            ///< bit α set iff slot α holds a triangle

  bool isValid(int alpha) const { return (valid >> alpha) & 1u; }
  int numValid() const;
  /// The 147 values in slot-major order (α, then entry), as the paper's Des_i.
  std::array<float, 3 * kNumSlots> flat() const;
};

/// The vertex-rooted products of a triangle: a_i = (p_j − p_i)·(p_k − p_i), and likewise a_j, a_k (spec §4).
Eigen::Vector3d triangleTerms(const Eigen::Vector3d& pi, const Eigen::Vector3d& pj, const Eigen::Vector3d& pk);

/// The per-vertex entries (e_i, e_j, e_k) of a triangle for a sub-vector kind, from its dot products @p t: the dot
/// products themselves, the cosines of the interior angles, or the lengths of the opposite sides.
Eigen::Vector3d vertexEntries(const Eigen::Vector3d& t, SubVectorKind kind);

/// (e_i, e_j, e_k) of a stored slot, whatever the sub-vector order.
Eigen::Vector3d slotTerms(const Eigen::Vector3f& slot, SubVectorOrder order);

/// Where the entry of vertex @p v (0 = i, 1 = j, 2 = k) is stored: (e_i, e_j, e_k) in the paper order,
/// (e_i, e_k, −e_j) in the code order.
inline int storedIndex(int v, SubVectorOrder order) {
  return order == SubVectorOrder::kPaper || v == 0 ? v : 3 - v;
}

/// Index of the v_j term within a stored slot (1 in the paper order; 2, negated, in the code order).
inline int vjEntry(SubVectorOrder order) { return storedIndex(1, order); }

/// Local descriptors of every node of @p graph (isolated nodes get an empty descriptor).
std::vector<LocalDescriptor> computeLocalDescriptors(const SemanticGraph& graph, const DescriptorConfig& config);

}  // namespace sgtllc
