/// @file voxel_hash.h
/// @brief Integer voxel keys and a small open-addressing map from key to dense index (internal).
///
/// Node extraction hashes ~60k points per scan twice (downsampling and the FEC neighbour grid); std::unordered_map
/// allocates per entry and costs several times more here, and no flat hash map ships in Debian's C++ set.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::internal {

/// Packs the integer cell coordinates (21 bits each, two's complement) of a point into one 64-bit key.
inline uint64_t packCell(int64_t ix, int64_t iy, int64_t iz) {
  constexpr uint64_t kMask = (1ull << 21) - 1;
  return (static_cast<uint64_t>(ix) & kMask) | ((static_cast<uint64_t>(iy) & kMask) << 21) |
         ((static_cast<uint64_t>(iz) & kMask) << 42);
}

/// Integer cell coordinates of a point for cells of edge 1 / inv_size.
inline Eigen::Array3i cellOf(const Eigen::Vector3f& p, float inv_size) {
  return (p.array() * inv_size).floor().cast<int>();
}

/// Map from a 64-bit key to a dense index 0..size()-1 in order of first insertion (so results never depend on
/// the hash function). Linear probing over a power-of-two table kept at most half full.
class KeyIndex {
 public:
  static constexpr uint32_t kMissing = 0xFFFFFFFFu;

  explicit KeyIndex(size_t expected_keys) {
    size_t capacity = 16;
    while (capacity < 2 * expected_keys) capacity *= 2;
    slots_.assign(capacity, Slot{0, kMissing});
    mask_ = capacity - 1;
  }

  /// Index of @p key, inserting it with the next dense index if absent.
  uint32_t insert(uint64_t key) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    size_t pos = hash(key) & mask_;
    while (slots_[pos].index != kMissing) {
      if (slots_[pos].key == key) return slots_[pos].index;
      pos = (pos + 1) & mask_;
    }
    slots_[pos] = Slot{key, size_};
    return size_++;
  }

  /// Index of @p key, or kMissing.
  uint32_t find(uint64_t key) const {
    size_t pos = hash(key) & mask_;
    while (slots_[pos].index != kMissing) {
      if (slots_[pos].key == key) return slots_[pos].index;
      pos = (pos + 1) & mask_;
    }
    return kMissing;
  }

  uint32_t size() const { return size_; }

 private:
  struct Slot {
    uint64_t key;
    uint32_t index;
  };

  // splitmix64 finaliser: packed keys differ in few low bits per axis, so they need mixing before masking.
  static uint64_t hash(uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
  }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(old.size() * 2, Slot{0, kMissing});
    mask_ = slots_.size() - 1;
    for (const Slot& s : old) {
      if (s.index == kMissing) continue;
      size_t pos = hash(s.key) & mask_;
      while (slots_[pos].index != kMissing) pos = (pos + 1) & mask_;
      slots_[pos] = s;
    }
  }

  std::vector<Slot> slots_;
  size_t mask_ = 0;
  uint32_t size_ = 0;
};

}  // namespace sgtllc::internal
