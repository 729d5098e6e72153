// Voxel connected components (docs/labeller.md §2): an open-addressing hash of the occupied voxels, then union-find
// over each voxel's 13 forward neighbours (the other 13 of the 26 see it from their side).
#include "sgtllc/label/segmentation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace sgtllc::label {
namespace {

constexpr int kBits = 21;
constexpr int64_t kOffset = int64_t{1} << (kBits - 1);
constexpr uint64_t kEmpty = ~uint64_t{0};

uint64_t packKey(int64_t x, int64_t y, int64_t z) {
  return (static_cast<uint64_t>(x + kOffset) << (2 * kBits)) | (static_cast<uint64_t>(y + kOffset) << kBits) |
         static_cast<uint64_t>(z + kOffset);
}

/// Voxel key → voxel index; keys are never removed.
class VoxelHash {
 public:
  explicit VoxelHash(size_t expected) {
    size_t cap = 16;
    shift_ = 60;
    while (cap < 2 * expected) {
      cap *= 2;
      --shift_;
    }
    keys_.assign(cap, kEmpty);
    values_.assign(cap, -1);
    mask_ = cap - 1;
  }
  /// Index of @p key, inserting it as @p next if absent.
  int insert(uint64_t key, int next) {
    size_t slot = hash(key);
    while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask_;
    if (keys_[slot] == kEmpty) {
      keys_[slot] = key;
      values_[slot] = next;
    }
    return values_[slot];
  }
  int find(uint64_t key) const {
    size_t slot = hash(key);
    while (keys_[slot] != kEmpty) {
      if (keys_[slot] == key) return values_[slot];
      slot = (slot + 1) & mask_;
    }
    return -1;
  }

 private:
  // Fibonacci hashing: the top bits of the product mix every bit of the key.
  size_t hash(uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }
  std::vector<uint64_t> keys_;
  std::vector<int> values_;
  size_t mask_ = 0;
  int shift_ = 60;
};

int findRoot(std::vector<int>& parent, int v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

Segmentation segmentVoxels(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use, double voxel) {
  Segmentation s;
  const size_t n = points.size();
  s.point_voxel.assign(n, -1);
  const double inv = 1.0 / voxel;
  size_t used = 0;
  for (size_t i = 0; i < n; ++i) used += use[i] != 0;
  VoxelHash hash(used);
  std::vector<uint64_t> voxel_keys;
  std::vector<std::array<int64_t, 3>> cells;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = points[i];
    if (!use[i] || !(p.cwiseAbs().maxCoeff() <= kMaxSegmentCoordinate)) continue;  // NaN fails the test too
    const std::array<int64_t, 3> c = {static_cast<int64_t>(std::floor(p.x() * inv)),
                                      static_cast<int64_t>(std::floor(p.y() * inv)),
                                      static_cast<int64_t>(std::floor(p.z() * inv))};
    const int v = hash.insert(packKey(c[0], c[1], c[2]), static_cast<int>(cells.size()));
    if (v == static_cast<int>(cells.size())) cells.push_back(c);
    s.point_voxel[i] = v;
  }
  s.num_voxels = static_cast<int>(cells.size());
  std::vector<int> parent(cells.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (int v = 0; v < s.num_voxels; ++v) {
    const auto& c = cells[v];
    for (int dx = 0; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          // Forward half of the 26-neighbourhood: dx > 0, or dx = 0 and (dy > 0, or dy = 0 and dz > 0).
          if (dx == 0 && (dy < 0 || (dy == 0 && dz <= 0))) continue;
          const int w = hash.find(packKey(c[0] + dx, c[1] + dy, c[2] + dz));
          if (w < 0) continue;
          const int a = findRoot(parent, v), b = findRoot(parent, w);
          if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
      }
    }
  }
  // Dense segment ids in the order of first appearance (voxels are numbered by their first point).
  s.voxel_segment.assign(cells.size(), -1);
  std::vector<int> root_segment(cells.size(), -1);
  for (int v = 0; v < s.num_voxels; ++v) {
    const int r = findRoot(parent, v);
    if (root_segment[r] < 0) root_segment[r] = s.num_segments++;
    s.voxel_segment[v] = root_segment[r];
  }
  return s;
}

}  // namespace sgtllc::label
