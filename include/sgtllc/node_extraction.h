/// @file node_extraction.h
/// @brief From a labelled scan to semantic-graph nodes: class split, voxel downsampling, FEC, centres and
///        same-class duplicate suppression (algorithm §1–§2).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/footprint.h"
#include "sgtllc/labels.h"
#include "sgtllc/types.h"

namespace sgtllc {

/// What happened to a scan's points on their way to nodes.
struct ExtractionStats {
  size_t input_points = 0;        ///< points given
  size_t nonfinite_points = 0;    ///< points with a NaN or Inf coordinate, dropped
  size_t far_points = 0;          ///< points beyond ±kMaxCoordinate on an axis, dropped
  size_t unknown_label_points = 0;  ///< points whose id is not in the preset's label space, dropped
  std::array<size_t, kMaxClasses> class_points{};  ///< kept points per stable class (0 beyond the class count C)
  std::array<int, kMaxClasses> clusters{};          ///< clusters of at least min_size per class (0 beyond C)
  int duplicates_suppressed = 0;  ///< clusters skipped because an accepted same-class centre was too close
  /// Nodes dropped because the scan had more than max_nodes: the ones with the fewest points (GraphConfig::max_nodes).
  int capped_nodes = 0;
};

/// Largest |coordinate| (m) a point may have: far beyond any LiDAR range, small enough for exact voxel cells.
inline constexpr float kMaxCoordinate = 1.0e6f;

/// Nodes of one scan in class order (building first … traffic-sign, then the extra classes), each class in FEC
/// order (algorithm §2 node order).
struct NodeExtractionResult {
  std::vector<Node> nodes;
  ExtractionStats stats;
};

/// Turns labelled scans into nodes. Immutable after construction; safe to share between threads.
class NodeExtractor {
 public:
  /// A scan with more than @p max_nodes nodes (after duplicate suppression) keeps the max_nodes whose clusters
  /// have the most original points, ties to the earlier node, in node order; 0 = no limit. Pass
  /// Config::graph.max_nodes so that every scan's graph stays within the limit buildGraph enforces. The classes
  /// are those of @p labels (LabelConfig::numClasses()); throws sgtllc::Error unless @p cluster has one
  /// ClassClusterConfig per class. Up to @p threads threads cluster the classes in parallel (Config::threads; the
  /// nodes do not depend on it; inside another parallelFor they run on the calling thread).
  NodeExtractor(const ClusterConfig& cluster, const LabelConfig& labels, int max_nodes = GraphConfig{}.max_nodes,
                int threads = 1);

  /// Throws sgtllc::Error if points and labels differ in length.
  NodeExtractionResult extract(const LabeledCloud& cloud) const;
  /// The same, and the scan's footprint in @p footprint from the same pass over its points: what
  /// computeFootprint(cloud, labelMap(), @p verification) gives, bit for bit, without reading the scan again.
  NodeExtractionResult extract(const LabeledCloud& cloud, const VerificationConfig& verification,
                               Footprint* footprint) const;
  /// How this extractor reads the scans' ids (the footprint of a scan reads them the same way).
  const LabelMap& labelMap() const { return label_map_; }

 private:
  NodeExtractionResult extract(const LabeledCloud& cloud, const FootprintMarker* marker, Footprint* footprint) const;

  ClusterConfig config_;
  LabelMap label_map_;
  int num_classes_;
  int max_nodes_;
  int threads_;
};

}  // namespace sgtllc
