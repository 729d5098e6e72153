/// @file voxel_hash.h
/// @brief Integer cell coordinates and a small open-addressing map from cell to dense index (internal).
///
/// Node extraction hashes ~60k points per scan twice (downsampling and the FEC neighbour grid); std::unordered_map
/// allocates per entry and costs several times more here, and no flat hash map ships in Debian's C++ set.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/clustering.h"

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
/// the hash function). Linear probing over a power-of-two table kept at most half full. The table holds only the
/// 4-byte indices and the keys sit densely in insertion order: a probe of an empty cell (most of a neighbour
/// search) touches one small table that stays in cache.
class KeyIndex {
 public:
  static constexpr uint32_t kMissing = 0xFFFFFFFFu;

  explicit KeyIndex(size_t expected_keys) {
    size_t capacity = 16;
    while (capacity < 2 * expected_keys) capacity *= 2;
    slots_.assign(capacity, kMissing);
    mask_ = capacity - 1;
    keys_.reserve(expected_keys);
  }

  /// Index of @p key, inserting it with the next dense index if absent.
  uint32_t insert(const Cell& key) {
    if (2 * (keys_.size() + 1) > slots_.size()) grow();
    size_t pos = hash(key) & mask_;
    while (slots_[pos] != kMissing) {
      if (keys_[slots_[pos]] == key) return slots_[pos];
      pos = (pos + 1) & mask_;
    }
    const uint32_t index = static_cast<uint32_t>(keys_.size());
    slots_[pos] = index;
    keys_.push_back(key);
    return index;
  }

  /// Index of @p key, or kMissing.
  uint32_t find(const Cell& key) const {
    size_t pos = hash(key) & mask_;
    while (slots_[pos] != kMissing) {
      if (keys_[slots_[pos]] == key) return slots_[pos];
      pos = (pos + 1) & mask_;
    }
    return kMissing;
  }

  uint32_t size() const { return static_cast<uint32_t>(keys_.size()); }

 private:
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
    slots_.assign(slots_.size() * 2, kMissing);
    mask_ = slots_.size() - 1;
    for (uint32_t index = 0; index < keys_.size(); ++index) {
      size_t pos = hash(keys_[index]) & mask_;
      while (slots_[pos] != kMissing) pos = (pos + 1) & mask_;
      slots_[pos] = index;
    }
  }

  std::vector<uint32_t> slots_;  // dense index per table position, kMissing when empty
  std::vector<Cell> keys_;       // keys_[index]: the cell of each index
  size_t mask_ = 0;
};

/// Builds a VoxelizedCloud one point at a time (voxelDownsample, and node extraction straight from the class split
/// so that no per-class copy of the points is made). Consecutive scan points mostly share a voxel, so the last
/// voxel is remembered and the hash table is probed only when the voxel changes; indices, sums and their order of
/// accumulation are those of one insert per point.
class VoxelAccumulator {
 public:
  VoxelAccumulator(double leaf, size_t expected_points)
      : inv_leaf_(static_cast<float>(1.0 / leaf)), index_(expected_points / 4 + 16) {
    out_.sums.reserve(expected_points / 4 + 16);
    out_.counts.reserve(expected_points / 4 + 16);
  }

  void add(const Eigen::Vector3f& p) {
    const Cell c = cellOf(p, inv_leaf_);
    if (!(has_last_ && c == last_)) {
      last_ = c;
      last_index_ = index_.insert(c);
      has_last_ = true;
      if (last_index_ == out_.sums.size()) {
        out_.sums.emplace_back(Eigen::Vector3d::Zero());
        out_.counts.push_back(0);
      }
    }
    out_.sums[last_index_] += p.cast<double>();
    ++out_.counts[last_index_];
  }

  /// The voxels in order of first appearance, with their centroids.
  VoxelizedCloud finish() && {
    out_.centroids.resize(out_.sums.size());
    for (size_t v = 0; v < out_.sums.size(); ++v) {
      out_.centroids[v] = (out_.sums[v] / static_cast<double>(out_.counts[v])).cast<float>();
    }
    return std::move(out_);
  }

 private:
  float inv_leaf_;
  KeyIndex index_;
  VoxelizedCloud out_;
  Cell last_{0, 0, 0};
  uint32_t last_index_ = 0;
  bool has_last_ = false;
};

}  // namespace sgtllc::internal
