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

/// floor(t) clamped to ±kMaxCell, as an integer. Truncation then a step down for negative non-integers: the build's
/// baseline x86-64 has no rounding instruction, and std::floor compiles there to a much longer sequence; node
/// extraction takes this for every point of a scan (BENCHMARKS.md "Time per frame"). NaN maps to −kMaxCell.
inline int32_t floorCell(float t) {
  const float c = t > -kMaxCell ? (t < kMaxCell ? t : kMaxCell) : -kMaxCell;
  const int32_t i = static_cast<int32_t>(c);
  return i - (c < static_cast<float>(i) ? 1 : 0);
}

/// The cell of a point for cells of edge 1 / inv_size.
inline Cell cellOf(const Eigen::Vector3f& p, float inv_size) {
  return Cell{floorCell(p.x() * inv_size), floorCell(p.y() * inv_size), floorCell(p.z() * inv_size)};
}

/// cellOf for a point within ±kMaxCoordinate and cells of at least 1 mm (node extraction's points and configs), whose
/// cell coordinates stay below 2^30 without clamping.
inline int32_t floorBounded(float t) {
  const int32_t i = static_cast<int32_t>(t);
  return i - (t < static_cast<float>(i) ? 1 : 0);
}
inline Cell boundedCellOf(const Eigen::Vector3f& p, float inv_size) {
  return Cell{floorBounded(p.x() * inv_size), floorBounded(p.y() * inv_size), floorBounded(p.z() * inv_size)};
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

  /// Index of @p key, inserting it with the next dense index if absent. Consecutive scan points (and voxels in
  /// order of first appearance) mostly share a cell, so the last key is remembered and the table is probed only
  /// when the key changes.
  uint32_t insert(const Cell& key) {
    if (key == last_key_) return last_index_;
    last_key_ = key;
    size_t pos = hash(key) & mask_;
    for (uint32_t slot = slots_[pos]; slot != kMissing; slot = slots_[pos]) {
      if (keys_[slot] == key) return last_index_ = slot;
      pos = (pos + 1) & mask_;
    }
    const uint32_t index = size_;
    slots_[pos] = index;
    keys_.push_back(key);
    ++size_;
    if (2 * static_cast<size_t>(size_) > mask_) grow();  // at most half full
    return last_index_ = index;
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

  uint32_t size() const { return size_; }
  /// The key of index @p index (< size()).
  const Cell& key(uint32_t index) const { return keys_[index]; }

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
  uint32_t size_ = 0;            // keys_.size()
  // The key of the last insert and its index. No cell coordinate is INT32_MIN (both cellOf variants stay within
  // ±2^30), so the first insert always probes.
  Cell last_key_{INT32_MIN, INT32_MIN, INT32_MIN};
  uint32_t last_index_ = 0;
};

/// Builds a VoxelizedCloud one point at a time (voxelDownsample, and node extraction straight from the class split
/// so that no per-class copy of the points is made): indices, sums and their order of accumulation are those of one
/// insert per point. absorb() joins two accumulators; its sums can then differ from one pass in the last bit.
class VoxelAccumulator {
 public:
  VoxelAccumulator(double leaf, size_t expected_points)
      : inv_leaf_(static_cast<float>(1.0 / leaf)), index_(expected_points / 4 + 16) {
    out_.sums.reserve(expected_points / 4 + 16);
    out_.counts.reserve(expected_points / 4 + 16);
  }

  /// Any point (cell coordinates clamped, cellOf).
  void add(const Eigen::Vector3f& p) { addIn(cellOf(p, inv_leaf_), p); }
  /// A point within ±kMaxCoordinate, for a leaf of at least 1 mm (boundedCellOf): node extraction's hot loop.
  void addBounded(const Eigen::Vector3f& p) { addIn(boundedCellOf(p, inv_leaf_), p); }

  /// Adds the voxels of @p later, which accumulated the points that come after this one's: each voxel's sum gains
  /// the later sum, and voxels new here follow in their order of first appearance there. The voxels are those of one
  /// accumulator over all the points; a sum can differ from it only where a double sum of floats rounds (BENCHMARKS.md
  /// "Time per frame": never on the report sequences).
  void absorb(const VoxelAccumulator& later) {
    for (uint32_t v = 0; v < later.voxels_; ++v) {
      const uint32_t w = index_.insert(later.index_.key(v));
      if (w == voxels_) {
        out_.sums.push_back(later.out_.sums[v]);
        out_.counts.push_back(later.out_.counts[v]);
        ++voxels_;
      } else {
        out_.sums[w] += later.out_.sums[v];
        out_.counts[w] += later.out_.counts[v];
      }
    }
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
  void addIn(const Cell& c, const Eigen::Vector3f& p) {
    const uint32_t v = index_.insert(c);
    if (v == voxels_) {
      out_.sums.emplace_back(Eigen::Vector3d::Zero());
      out_.counts.push_back(0);
      ++voxels_;
    }
    out_.sums[v] += p.cast<double>();
    ++out_.counts[v];
  }

  float inv_leaf_;
  KeyIndex index_;
  VoxelizedCloud out_;
  uint32_t voxels_ = 0;  // out_.sums.size()
};

}  // namespace sgtllc::internal
