/// @file voxel_hash.h
/// @brief Integer cell coordinates and a small open-addressing map from cell to dense index (internal).
///
/// Node extraction hashes ~60k points per scan twice (downsampling and the FEC neighbour grid); std::unordered_map
/// allocates per entry and costs several times more here, and no flat hash map ships in Debian's C++ set.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::internal {

/// Integer coordinates of a cubic cell.
struct Cell {
  int32_t x, y, z;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};

/// Largest |cell coordinate|: coordinates are clamped here so the float → int conversion is always defined.
/// Node extraction drops points beyond ±1e6 m and configs need leaves ≥ 1 mm, so real cells stay below it.
inline constexpr float kMaxCell = 1073741824.0f;  // 2^30

/// The cell of a point for cells of edge 1 / inv_size.
inline Cell cellOf(const Eigen::Vector3f& p, float inv_size) {
  const Eigen::Array3f c = (p.array() * inv_size).floor().max(-kMaxCell).min(kMaxCell);
  return Cell{static_cast<int32_t>(c.x()), static_cast<int32_t>(c.y()), static_cast<int32_t>(c.z())};
}

inline Cell offset(const Cell& c, int dx, int dy, int dz) { return Cell{c.x + dx, c.y + dy, c.z + dz}; }

/// Map from a cell to a dense index 0..size()-1 in order of first insertion (so results never depend on
/// the hash function). Linear probing over a power-of-two table kept at most half full.
class KeyIndex {
 public:
  static constexpr uint32_t kMissing = 0xFFFFFFFFu;

  explicit KeyIndex(size_t expected_keys) {
    size_t capacity = 16;
    while (capacity < 2 * expected_keys) capacity *= 2;
    slots_.assign(capacity, Slot{Cell{0, 0, 0}, kMissing});
    mask_ = capacity - 1;
  }

  /// Index of @p key, inserting it with the next dense index if absent.
  uint32_t insert(const Cell& key) {
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
  uint32_t find(const Cell& key) const {
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
    Cell key;
    uint32_t index;
  };

  // splitmix64 finaliser over the packed coordinates: neighbouring cells differ in few low bits, so they need
  // mixing before masking. Full keys are compared, so distant cells never collide.
  static uint64_t hash(const Cell& c) {
    uint64_t x = static_cast<uint32_t>(c.x) * 0x9E3779B97F4A7C15ull ^ static_cast<uint64_t>(static_cast<uint32_t>(c.y)) << 21 ^
                 static_cast<uint64_t>(static_cast<uint32_t>(c.z)) << 42;
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
    slots_.assign(old.size() * 2, Slot{Cell{0, 0, 0}, kMissing});
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
