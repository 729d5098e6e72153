#include "internal/class_split.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <utility>

#include "sgtllc/parallel.h"

namespace sgtllc::internal {
namespace {

/// Smallest voxel leaf (m) whose cells take boundedCellOf: a validated config's lower bound.
constexpr double kMinFastLeaf = 0.001;

/// True if every coordinate of points [begin, end) is finite and within ±kMaxCoordinate. On IEEE-754 bits with the
/// sign cleared, non-negative floats order as their values and Inf and NaN above every finite value, so K − |bits|
/// wraps to a value with the top bit set exactly when a coordinate is out of bounds. The loop has no branch and
/// vectorizes; the per-point bound test of the split is then needed only for the rare scan that fails it.
bool allWithinBounds(const std::vector<Eigen::Vector3f>& points, size_t begin, size_t end) {
  if (begin >= end) return true;
  uint32_t bound;
  std::memcpy(&bound, &kMaxCoordinate, sizeof bound);
  const float* values = points[begin].data();  // Vector3f is three packed floats
  const size_t count = 3 * (end - begin);
  uint32_t out = 0;
  for (size_t k = 0; k < count; ++k) {
    uint32_t bits;
    std::memcpy(&bits, values + k, sizeof bits);
    out |= bound - (bits & 0x7FFFFFFFu);
  }
  return (out >> 31) == 0;
}

void addCounts(ExtractionStats& to, const ExtractionStats& from) {
  to.nonfinite_points += from.nonfinite_points;
  to.far_points += from.far_points;
  to.unknown_label_points += from.unknown_label_points;
  for (int c = 0; c < kMaxClasses; ++c) to.class_points[c] += from.class_points[c];
}

}  // namespace

ClassSplit::ClassSplit(const LabeledCloud& cloud, const LabelMap& labels, const ClusterConfig& cluster, int threads,
                       ExtractionStats& stats, const FootprintMarker* footprint)
    : chunks_(kSplitChunks) {
  if (footprint && !footprint->enabled()) footprint = nullptr;
  const size_t n = cloud.points.size();
  const size_t classes = cluster.classes.size();
  const size_t expected = n / (classes * kSplitChunks) + 16;  // points per class and range, if spread evenly
  for (Chunk& chunk : chunks_) {
    chunk.voxels.resize(classes);
    chunk.points.resize(classes);
    for (size_t c = 0; c < classes; ++c) {
      const double leaf = cluster.classes[c].voxel;
      if (leaf > 0.0) chunk.voxels[c].emplace(leaf, expected);
      if (leaf >= kMinFastLeaf) chunk.bounded[c] = &*chunk.voxels[c];
    }
    if (footprint) chunk.footprint = footprint->grid().bits;
  }
  std::array<std::exception_ptr, kSplitChunks> errors;
  parallelFor(kSplitChunks, threads, [&](int k) {
    const size_t begin = n * static_cast<size_t>(k) / kSplitChunks;
    const size_t end = n * static_cast<size_t>(k + 1) / kSplitChunks;
    try {
      if (allWithinBounds(cloud.points, begin, end)) {
        split<false>(cloud, labels, begin, end, footprint, chunks_[k]);
      } else {
        split<true>(cloud, labels, begin, end, footprint, chunks_[k]);
      }
    } catch (...) {
      errors[k] = std::current_exception();  // out of memory; rethrown on the caller's thread
    }
  });
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  for (const Chunk& chunk : chunks_) addCounts(stats, chunk.stats);
}

/// Points [begin, end) into @p chunk's sinks, in scan order. kCheck: test each point's bounds (allWithinBounds failed).
/// With @p footprint, each point also sets its footprint cell, as computeFootprint would: the footprint reads x and
/// y only, so a point the split drops for a bad z still sets its cell.
template <bool kCheck>
void ClassSplit::split(const LabeledCloud& cloud, const LabelMap& labels, size_t begin, size_t end,
                       const FootprintMarker* footprint, Chunk& chunk) {
  const Eigen::Vector3f* points = cloud.points.data();
  const uint32_t* ids = cloud.labels.data();
  ExtractionStats& stats = chunk.stats;
  for (size_t i = begin; i < end; ++i) {
    const Eigen::Vector3f& p = points[i];
    if (kCheck && !(std::abs(p.x()) <= kMaxCoordinate && std::abs(p.y()) <= kMaxCoordinate &&
                    std::abs(p.z()) <= kMaxCoordinate)) {
      ++(p.allFinite() ? stats.far_points : stats.nonfinite_points);
      if (footprint) footprint->mark(p, labels.classOf(ids[i]), chunk.footprint);
      continue;
    }
    const int8_t c = labels.classOf(ids[i]);  // an id with a class is known (LabelMap)
    if (c == kDropped) {
      if (!labels.isKnown(ids[i])) ++stats.unknown_label_points;
      continue;
    }
    if (footprint) footprint->mark(p, c, chunk.footprint);
    ++stats.class_points[c];
    if (chunk.bounded[c]) {
      chunk.bounded[c]->addBounded(p);
    } else if (chunk.voxels[c]) {
      chunk.voxels[c]->add(p);
    } else {
      chunk.points[c].push_back(p);
    }
  }
}

void ClassSplit::footprint(Footprint* f) const {
  for (const Chunk& chunk : chunks_) {
    for (size_t w = 0; w < chunk.footprint.size() && w < f->bits.size(); ++w) f->bits[w] |= chunk.footprint[w];
  }
}

VoxelizedCloud ClassSplit::voxels(int c) {
  VoxelAccumulator& first = *chunks_.front().voxels[c];
  for (size_t k = 1; k < chunks_.size(); ++k) first.absorb(*chunks_[k].voxels[c]);
  return std::move(first).finish();
}

std::vector<Eigen::Vector3f> ClassSplit::points(int c) {
  size_t total = 0;
  for (const Chunk& chunk : chunks_) total += chunk.points[c].size();
  std::vector<Eigen::Vector3f> out = std::move(chunks_.front().points[c]);
  out.reserve(total);
  for (size_t k = 1; k < chunks_.size(); ++k) out.insert(out.end(), chunks_[k].points[c].begin(), chunks_[k].points[c].end());
  return out;
}

}  // namespace sgtllc::internal
