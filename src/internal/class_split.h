/// @file class_split.h
/// @brief A scan's kept points routed to their stable classes, split over fixed index ranges in parallel (internal).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"
#include "sgtllc/config.h"
#include "sgtllc/footprint.h"
#include "sgtllc/labels.h"
#include "sgtllc/node_extraction.h"
#include "sgtllc/types.h"

namespace sgtllc::internal {

/// Index ranges the class split cuts a scan into. A fixed number, never the thread count, so that the voxel sums
/// (each range's sum, then the ranges' sums in scan order) and so the nodes are the same at any thread count.
inline constexpr int kSplitChunks = 2;

/// One pass over a scan routes each kept point to its class: into the class's voxel accumulator, or for a class
/// clustered without downsampling onto its point list. The scan is cut into kSplitChunks ranges done in parallel;
/// voxels() and points() join a class's ranges in scan order, so voxels keep their order of first appearance and
/// point lists their scan order (algorithm §2 node order), and classes can be joined in parallel.
class ClassSplit {
 public:
  /// Splits @p cloud (points and labels of equal length) on up to @p threads threads; adds the counts to @p stats.
  /// With an enabled @p footprint, the same pass sets the scan's footprint cells (footprint()).
  ClassSplit(const LabeledCloud& cloud, const LabelMap& labels, const ClusterConfig& cluster, int threads,
             ExtractionStats& stats, const FootprintMarker* footprint = nullptr);

  /// True if class @p c is downsampled (voxel leaf > 0).
  bool voxelized(int c) const { return chunks_.front().voxels[c].has_value(); }
  /// Class @p c's voxels in order of first appearance, as voxelDownsample of its points gives them (the sums joined
  /// range by range, so they can differ from one pass in the last bit; the same at any thread count); call once,
  /// voxelized(c) only.
  VoxelizedCloud voxels(int c);
  /// Class @p c's points in scan order; call once, !voxelized(c) only.
  std::vector<Eigen::Vector3f> points(int c);
  /// The cells the pass set, joined over the ranges (an OR: the same at any thread count), in @p f's bits, which
  /// must be the marker's grid(); nothing without a marker.
  void footprint(Footprint* f) const;

 private:
  struct Chunk {
    std::vector<std::optional<VoxelAccumulator>> voxels;
    std::array<VoxelAccumulator*, kMaxClasses> bounded{};  // voxels on the fast cell path (leaf ≥ 1 mm)
    std::vector<std::vector<Eigen::Vector3f>> points;
    std::vector<uint64_t> footprint;  // this range's footprint cells
    ExtractionStats stats;
  };
  template <bool kCheck>
  static void split(const LabeledCloud& cloud, const LabelMap& labels, size_t begin, size_t end,
                    const FootprintMarker* footprint, Chunk& chunk);

  std::vector<Chunk> chunks_;
};

}  // namespace sgtllc::internal
