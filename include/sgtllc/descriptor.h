/// @file descriptor.h
/// @brief 147-D local descriptors: one triangle sub-vector per class-pair slot (algorithm §4).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/graph.h"

namespace sgtllc {

/// The set of slots of a local descriptor that hold a triangle: bit α for slot α < kMaxSlots.
struct SlotMask {
  static constexpr int kWords = kMaxSlots / 64;
  std::array<uint64_t, kWords> words{};

  SlotMask() = default;
  /// The mask whose first 64 slots are the bits of @p first (all the slots of the paper's seven classes).
  SlotMask(uint64_t first) { words[0] = first; }  // NOLINT: implicit, so that a 49-slot mask reads as one word

  void set(int alpha) { words[static_cast<size_t>(alpha >> 6)] |= uint64_t{1} << (alpha & 63); }
  bool test(int alpha) const { return (words[static_cast<size_t>(alpha >> 6)] >> (alpha & 63)) & 1u; }
  int count() const;
  SlotMask& operator|=(const SlotMask& o) {
    for (int w = 0; w < kWords; ++w) words[w] |= o.words[w];
    return *this;
  }
  friend bool operator==(const SlotMask& a, const SlotMask& b) { return a.words == b.words; }
  friend bool operator!=(const SlotMask& a, const SlotMask& b) { return !(a == b); }
};

/// The C² slot sub-vectors of one local descriptor, zero-initialised. Up to 49 slots (the paper's seven classes)
/// live inline, so that describing a default frame allocates nothing per node; larger class sets use the heap.
class SlotArray {
 public:
  explicit SlotArray(int size) : size_(size) {
    if (size > kNumPaperSlots) {
      heap_.assign(static_cast<size_t>(size), Eigen::Vector3f::Zero());
    } else {
      for (Eigen::Vector3f& v : inline_) v.setZero();
    }
  }

  int size() const { return size_; }
  Eigen::Vector3f* data() { return size_ > kNumPaperSlots ? heap_.data() : inline_.data(); }
  const Eigen::Vector3f* data() const { return size_ > kNumPaperSlots ? heap_.data() : inline_.data(); }
  Eigen::Vector3f& operator[](int a) { return data()[a]; }
  const Eigen::Vector3f& operator[](int a) const { return data()[a]; }
  Eigen::Vector3f* begin() { return data(); }
  Eigen::Vector3f* end() { return data() + size_; }
  const Eigen::Vector3f* begin() const { return data(); }
  const Eigen::Vector3f* end() const { return data() + size_; }

 private:
  std::array<Eigen::Vector3f, kNumPaperSlots> inline_;
  std::vector<Eigen::Vector3f> heap_;
  int size_;
};

/// Des_i ∈ R^{C²×3} (49×3 = 147 values with the paper's seven classes): slot α = C·m + n holds the triangle
/// (i, j*, k*) of T_i[m][n] as one entry per vertex: by default the raw dot products a_i, a_j, a_k (m²), see
/// DescriptorConfig::kind.
struct LocalDescriptor {
  /// An empty descriptor of @p num_slots = C² slots.
  explicit LocalDescriptor(int num_slots = kNumPaperSlots) : slots(num_slots) {}

  SlotArray slots;  ///< C² entries, zero where the slot is empty
  SlotMask valid;   ///< bit α set iff slot α holds a triangle

  int numSlots() const { return slots.size(); }
  bool isValid(int alpha) const { return valid.test(alpha); }
  int numValid() const { return valid.count(); }
  /// The 3·C² values in slot-major order (α, then entry), as the paper's Des_i.
  std::vector<float> flat() const;
};

/// The vertex-rooted products of a triangle: a_i = (p_j − p_i)·(p_k − p_i), and likewise a_j, a_k (algorithm §4).
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
