#include "sgtllc/node_extraction.h"

#include <algorithm>
#include <exception>
#include <numeric>
#include <string>

#include "internal/class_split.h"
#include "sgtllc/clustering.h"
#include "sgtllc/parallel.h"

namespace sgtllc {
namespace {

/// One cluster: its centre and the number of original points in it.
struct Cluster {
  Eigen::Vector3d centre;
  size_t points = 0;
};

/// One class's clusters of voxel centroids in FEC order; sets *num_clusters. Minimum sizes count voxels (algorithm
/// §2); the centre is the mean of the original points by default, which an axis-aligned grid cannot move under
/// rotation (algorithm §11), or of the voxel centroids as in the authors' code.
std::vector<Cluster> voxelClusterCentres(const VoxelizedCloud& voxels, const ClassClusterConfig& params,
                                         const ClusterConfig& config, int* num_clusters) {
  std::vector<Cluster> centres;
  if (voxels.centroids.empty()) return centres;
  const auto clusters = fastEuclideanClustering(voxels.centroids, params.radius, config.max_neighbors, params.min_size);
  for (const auto& members : clusters) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double count = 0.0;
    size_t original = 0;
    for (uint32_t v : members) {
      original += voxels.counts[v];
      if (config.centre == CentreSource::kPoints) {
        sum += voxels.sums[v];
        count += voxels.counts[v];
      } else {
        sum += voxels.centroids[v].cast<double>();
        count += 1.0;
      }
    }
    centres.push_back(Cluster{sum / count, original});
  }
  *num_clusters = static_cast<int>(clusters.size());
  return centres;
}

/// One class's clusters of its points (no downsampling) in FEC order; sets *num_clusters.
std::vector<Cluster> pointClusterCentres(const std::vector<Eigen::Vector3f>& points, const ClassClusterConfig& params,
                                         const ClusterConfig& config, int* num_clusters) {
  std::vector<Cluster> centres;
  if (points.empty()) return centres;
  const auto clusters = fastEuclideanClustering(points, params.radius, config.max_neighbors, params.min_size);
  for (const auto& members : clusters) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (uint32_t i : members) sum += points[i].cast<double>();
    centres.push_back(Cluster{sum / static_cast<double>(members.size()), members.size()});
  }
  *num_clusters = static_cast<int>(clusters.size());
  return centres;
}

/// Keeps the @p max_nodes nodes with the most points (ties: the earlier node), in their original order.
void keepLargest(std::vector<Node>& nodes, const std::vector<size_t>& points, int max_nodes) {
  std::vector<size_t> order(nodes.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return points[a] > points[b]; });
  std::vector<uint8_t> keep(nodes.size(), 0);
  for (int k = 0; k < max_nodes; ++k) keep[order[k]] = 1;
  size_t out = 0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (keep[i]) nodes[out++] = nodes[i];
  }
  nodes.resize(out);
}

}  // namespace

NodeExtractor::NodeExtractor(const ClusterConfig& cluster, const LabelConfig& labels, int max_nodes, int threads)
    : config_(cluster),
      label_map_(labels),
      num_classes_(labels.numClasses()),
      max_nodes_(max_nodes),
      threads_(std::max(1, threads)) {
  if (static_cast<int>(config_.classes.size()) != num_classes_ || num_classes_ > kMaxClasses) {
    throw Error("NodeExtractor: cluster parameters for " + std::to_string(config_.classes.size()) + " classes, but " +
                std::to_string(num_classes_) + " classes (at most " + std::to_string(kMaxClasses) +
                "); Config::addClass declares a class with its parameters");
  }
}

NodeExtractionResult NodeExtractor::extract(const LabeledCloud& cloud) const {
  return extract(cloud, nullptr, nullptr);
}

NodeExtractionResult NodeExtractor::extract(const LabeledCloud& cloud, const VerificationConfig& verification,
                                            Footprint* footprint) const {
  const FootprintMarker marker(verification);
  NodeExtractionResult result = extract(cloud, footprint ? &marker : nullptr, footprint);
  if (footprint) finishFootprint(cloud.points, verification, footprint);
  return result;
}

NodeExtractionResult NodeExtractor::extract(const LabeledCloud& cloud, const FootprintMarker* marker,
                                            Footprint* footprint) const {
  if (cloud.points.size() != cloud.labels.size()) {
    throw Error("labelled cloud has " + std::to_string(cloud.points.size()) + " points but " +
                std::to_string(cloud.labels.size()) + " labels");
  }
  NodeExtractionResult result;
  ExtractionStats& stats = result.stats;
  stats.input_points = cloud.points.size();

  internal::ClassSplit split(cloud, label_map_, config_, threads_, stats, marker);
  if (footprint) {
    *footprint = marker ? marker->grid() : Footprint{};
    split.footprint(footprint);
  }

  // Classes are clustered independently (algorithm §2), so they run in parallel, the largest first, each joining its
  // ranges of the split first; each writes only its own slot and the merge below is in class order, so the nodes
  // never depend on the thread count.
  std::vector<std::vector<Cluster>> clusters(static_cast<size_t>(num_classes_));
  std::vector<int> order(static_cast<size_t>(num_classes_));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return stats.class_points[a] > stats.class_points[b]; });
  std::vector<std::exception_ptr> errors(static_cast<size_t>(num_classes_));
  parallelFor(num_classes_, threads_, [&](int k) {
    const int c = order[k];
    try {
      const ClassClusterConfig& params = config_.classes[c];
      if (split.voxelized(c)) {
        clusters[c] = voxelClusterCentres(split.voxels(c), params, config_, &stats.clusters[c]);
      } else {
        clusters[c] = pointClusterCentres(split.points(c), params, config_, &stats.clusters[c]);
      }
    } catch (...) {
      errors[c] = std::current_exception();  // an unvalidated ClusterConfig; rethrown on the caller's thread
    }
  });
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }

  const double dup2 = config_.duplicate_radius * config_.duplicate_radius;
  std::vector<size_t> node_points;  // original points of each accepted node
  for (int c = 0; c < num_classes_; ++c) {
    const size_t first_of_class = result.nodes.size();
    for (const Cluster& cluster : clusters[c]) {
      Eigen::Vector3d centre = cluster.centre;
      // An upright object's node is where its axis crosses the sensor's horizontal plane (algorithm §2).
      if (config_.classes[c].centre_height == CentreHeight::kSensor) centre.z() = 0.0;
      // Same-class duplicate suppression against the centres accepted so far (algorithm §2).
      bool duplicate = false;
      for (size_t k = first_of_class; k < result.nodes.size() && !duplicate; ++k) {
        duplicate = (result.nodes[k].centre - centre).squaredNorm() < dup2;
      }
      if (duplicate) {
        ++stats.duplicates_suppressed;
        continue;
      }
      result.nodes.push_back(Node{centre, c});
      node_points.push_back(cluster.points);
    }
  }
  // Bounded graph size (GraphConfig::max_nodes): a dense scene must not fail a scan, so the smallest clusters go.
  // The ones with the most points are the large, well-sampled objects that a revisit sees again.
  if (max_nodes_ > 0 && result.nodes.size() > static_cast<size_t>(max_nodes_)) {
    stats.capped_nodes = static_cast<int>(result.nodes.size()) - max_nodes_;
    keepLargest(result.nodes, node_points, max_nodes_);
  }
  return result;
}

}  // namespace sgtllc
