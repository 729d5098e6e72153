#include "sgtllc/node_extraction.h"

#include <stdexcept>
#include <string>

#include "sgtllc/clustering.h"

namespace sgtllc {
namespace {

/// Centres of one class's clusters in FEC order; sets *num_clusters.
std::vector<Eigen::Vector3d> clusterCentres(const std::vector<Eigen::Vector3f>& points,
                                            const ClassClusterConfig& params, const ClusterConfig& config,
                                            int* num_clusters) {
  std::vector<Eigen::Vector3d> centres;
  if (points.empty()) return centres;
  if (params.voxel > 0.0) {
    // Minimum sizes count voxels (spec §2); the centre is the mean of the original points by default, which an
    // axis-aligned grid cannot move under rotation (spec §11), or of the voxel centroids as in the authors' code.
    const VoxelizedCloud voxels = voxelDownsample(points, params.voxel);
    const auto clusters =
        fastEuclideanClustering(voxels.centroids, params.radius, config.max_neighbors, params.min_size);
    for (const auto& members : clusters) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double count = 0.0;
      for (uint32_t v : members) {
        if (config.centre == CentreSource::kPoints) {
          sum += voxels.sums[v];
          count += voxels.counts[v];
        } else {
          sum += voxels.centroids[v].cast<double>();
          count += 1.0;
        }
      }
      centres.push_back(sum / count);
    }
    *num_clusters = static_cast<int>(clusters.size());
  } else {
    const auto clusters = fastEuclideanClustering(points, params.radius, config.max_neighbors, params.min_size);
    for (const auto& members : clusters) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (uint32_t i : members) sum += points[i].cast<double>();
      centres.push_back(sum / static_cast<double>(members.size()));
    }
    *num_clusters = static_cast<int>(clusters.size());
  }
  return centres;
}

}  // namespace

NodeExtractor::NodeExtractor(const ClusterConfig& cluster, const LabelConfig& labels)
    : config_(cluster), label_map_(labels) {}

NodeExtractionResult NodeExtractor::extract(const LabeledCloud& cloud) const {
  if (cloud.points.size() != cloud.labels.size()) {
    throw std::invalid_argument("NodeExtractor: " + std::to_string(cloud.points.size()) + " points but " +
                                std::to_string(cloud.labels.size()) + " labels");
  }
  NodeExtractionResult result;
  ExtractionStats& stats = result.stats;
  stats.input_points = cloud.points.size();

  // Split by class in two passes so each class cloud is allocated once and keeps the scan's point order.
  std::vector<int8_t> cls(cloud.points.size(), kDropped);
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (!cloud.points[i].allFinite()) {
      ++stats.nonfinite_points;
      continue;
    }
    if (cloud.points[i].cwiseAbs().maxCoeff() > kMaxCoordinate) {
      ++stats.far_points;
      continue;
    }
    const uint32_t id = cloud.labels[i];
    if (!label_map_.isKnown(id)) {
      ++stats.unknown_label_points;
      continue;
    }
    cls[i] = label_map_.classOf(id);
    if (cls[i] != kDropped) ++stats.class_points[cls[i]];
  }
  std::array<std::vector<Eigen::Vector3f>, kNumClasses> by_class;
  for (int c = 0; c < kNumClasses; ++c) by_class[c].reserve(stats.class_points[c]);
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (cls[i] != kDropped) by_class[cls[i]].push_back(cloud.points[i]);
  }

  const double dup2 = config_.duplicate_radius * config_.duplicate_radius;
  for (int c = 0; c < kNumClasses; ++c) {
    const auto centres = clusterCentres(by_class[c], config_.classes[c], config_, &stats.clusters[c]);
    const size_t first_of_class = result.nodes.size();
    for (const Eigen::Vector3d& centre : centres) {
      // Same-class duplicate suppression against the centres accepted so far (spec §2).
      bool duplicate = false;
      for (size_t k = first_of_class; k < result.nodes.size() && !duplicate; ++k) {
        duplicate = (result.nodes[k].centre - centre).squaredNorm() < dup2;
      }
      if (duplicate) {
        ++stats.duplicates_suppressed;
        continue;
      }
      result.nodes.push_back(Node{centre, c});
    }
  }
  return result;
}

}  // namespace sgtllc
