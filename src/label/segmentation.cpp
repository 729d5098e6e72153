// Voxel connected components (docs/labeller.md §2): an open-addressing hash of the occupied voxels, then union-find
// over each voxel's 13 forward neighbours (the other 13 of the 26 see it from their side).
#include "sgtllc/label/segmentation.h"

#include <algorithm>
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

/// The occupied voxels: their keys in the order of their first point (a voxel's index), and an open-addressing
/// table of indices. A slot holds only the index (4 bytes; the table stays in the L2 cache) and a probe compares
/// the key at that index: consecutive points mostly find a voxel inserted just before, whose key is in cache. The
/// table doubles whenever it is half full, so it stays about the size of the occupied voxels (a few per hundred
/// points), not of the points.
class VoxelHash {
 public:
  explicit VoxelHash(size_t expected) {
    keys_.reserve(expected);
    resize(std::max<size_t>(16, 2 * expected));
  }
  /// Index of @p key, inserting it as the next index if absent.
  int insert(uint64_t key) {
    int* slot = probe(key);
    if (*slot < 0) {
      filter_[filterWord(key)] |= uint64_t{1} << (key & 63);
      *slot = static_cast<int>(keys_.size());
      keys_.push_back(key);
      if (keys_.size() * 2 > slots_.size()) resize(slots_.size() * 2);
      return static_cast<int>(keys_.size()) - 1;
    }
    return *slot;
  }
  /// Index of @p key, or −1; call only where the filter said the key may be present.
  int find(uint64_t key) const {
    for (size_t i = hash(key);; i = (i + 1) & mask_) {
      const int v = slots_[i];
      if (v < 0) return -1;
      if (keys_[static_cast<size_t>(v)] == key) return v;
    }
  }
  /// Bit d (0, 1, 2) set if the key at height z − 1 + d of @p key's column may be present. Most neighbour lookups
  /// find no voxel; one 64-bit word per hashed column, a bit per height modulo 64, answers a column's three
  /// neighbours in one load without touching the slots (128 KB: the L2 cache). A false positive costs a probe.
  unsigned mayContainAround(uint64_t key) const {
    const uint64_t word = filter_[filterWord(key)];
    const unsigned below = static_cast<unsigned>((key - 1) & 63);
    return static_cast<unsigned>(((word >> below) | (word << ((64 - below) & 63))) & 7);  // rotate right
  }
  const std::vector<uint64_t>& keys() const { return keys_; }

 private:
  static constexpr int kFilterWordBits = 14;
  static size_t filterWord(uint64_t key) {
    return static_cast<size_t>(((key >> kBits) * 0xC2B2AE3D27D4EB4Full) >> (64 - kFilterWordBits));
  }
  // Fibonacci hashing: the top bits of the product mix every bit of the key.
  size_t hash(uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }
  int* probe(uint64_t key) {
    size_t i = hash(key);
    while (slots_[i] >= 0 && keys_[static_cast<size_t>(slots_[i])] != key) i = (i + 1) & mask_;
    return &slots_[i];
  }
  void resize(size_t at_least) {
    size_t cap = 16;
    int bits = 4;
    while (cap < at_least) {
      cap *= 2;
      ++bits;
    }
    slots_.assign(cap, -1);
    mask_ = cap - 1;
    shift_ = 64 - bits;
    for (size_t v = 0; v < keys_.size(); ++v) *probe(keys_[v]) = static_cast<int>(v);
  }
  std::vector<uint64_t> keys_;
  std::vector<int> slots_;
  std::vector<uint64_t> filter_ = std::vector<uint64_t>(size_t{1} << kFilterWordBits, 0);
  size_t mask_ = 0;
  int shift_ = 60;
};

/// std::floor for |x| < 2^53, as an integer, inline: without SSE4.1 the compiler calls the maths library for
/// std::floor, three calls a point.
int64_t floorToInt(double x) {
  const auto t = static_cast<int64_t>(x);  // rounds towards zero
  return t - static_cast<int64_t>(static_cast<double>(t) > x);
}

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
  VoxelHash hash(used / 8);  // voxels expected: KITTI has about one per ten non-ground points, nuScenes one per four
  uint64_t last_key = kEmpty;  // consecutive points of a scan line mostly share a voxel
  int last_voxel = -1;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = points[i];
    if (!use[i] || !(p.cwiseAbs().maxCoeff() <= kMaxSegmentCoordinate)) continue;  // NaN fails the test too
    // |coordinate · inv| ≤ 10^6: kMaxSegmentCoordinate over the smallest voxel, 0.001 m.
    const uint64_t key = packKey(floorToInt(p.x() * inv), floorToInt(p.y() * inv), floorToInt(p.z() * inv));
    if (key != last_key) {
      last_key = key;
      last_voxel = hash.insert(key);
    }
    s.point_voxel[i] = last_voxel;
  }
  const std::vector<uint64_t>& keys = hash.keys();
  s.num_voxels = static_cast<int>(keys.size());
  std::vector<int> parent(keys.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto join = [&](int v, int w) {
    const int a = findRoot(parent, v), b = findRoot(parent, w);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  // The forward half of the 26-neighbourhood: the voxel above, and the three heights z − 1..z + 1 of the columns
  // (x, y + 1), (x + 1, y − 1), (x + 1, y), (x + 1, y + 1). A neighbour's key is the voxel's key plus an offset:
  // no field overflows, as |cell| ≤ 10^6 + 1 < kOffset.
  constexpr uint64_t kY = uint64_t{1} << kBits, kX = uint64_t{1} << (2 * kBits);
  constexpr uint64_t kColumns[4] = {kY, kX - kY, kX, kX + kY};
  for (int v = 0; v < s.num_voxels; ++v) {
    const uint64_t key = keys[v];
    if (hash.mayContainAround(key) & 4) {
      const int w = hash.find(key + 1);
      if (w >= 0) join(v, w);
    }
    for (const uint64_t column : kColumns) {
      const uint64_t middle = key + column;
      const unsigned around = hash.mayContainAround(middle);
      for (uint64_t d = 0; around >> d != 0; ++d) {
        if (((around >> d) & 1) == 0) continue;
        const int w = hash.find(middle - 1 + d);
        if (w >= 0) join(v, w);
      }
    }
  }
  // Dense segment ids in the order of first appearance (voxels are numbered by their first point).
  s.voxel_segment.assign(keys.size(), -1);
  std::vector<int> root_segment(keys.size(), -1);
  for (int v = 0; v < s.num_voxels; ++v) {
    const int r = findRoot(parent, v);
    if (root_segment[r] < 0) root_segment[r] = s.num_segments++;
    s.voxel_segment[v] = root_segment[r];
  }
  return s;
}

}  // namespace sgtllc::label
