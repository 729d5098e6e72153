/// @file clustering.h
/// @brief Voxel downsampling and Fast Euclidean Clustering (FEC), the building blocks of node extraction (algorithm §2).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc {

/// Points reduced to one centroid per occupied voxel.
struct VoxelizedCloud {
  std::vector<Eigen::Vector3f> centroids;  ///< mean of each voxel's points, voxels in order of first appearance
  std::vector<Eigen::Vector3d> sums;       ///< sum of each voxel's points (for centres from original points)
  std::vector<uint32_t> counts;            ///< number of points in each voxel
};

/// Averages the points in each cubic voxel of edge @p leaf (m), like PCL's VoxelGrid, but lists voxels in the order
/// their first point appears so the output never depends on hashing. O(n).
VoxelizedCloud voxelDownsample(const std::vector<Eigen::Vector3f>& points, double leaf);

/// Fast Euclidean Clustering (algorithm §2, authors' FEC.h): points are visited in index order; a point not yet reached
/// becomes a seed and joins, with every cluster they belong to, its (at most @p max_neighbors nearest) neighbours
/// within @p radius, itself included. Equivalent to union-find over the (seed, neighbour) edges; O(n) expected with
/// a hash grid of cell @p radius.
///
/// @return the clusters with at least @p min_size points, each a list of point indices in ascending order, clusters
///         ordered by their first seed (= smallest point index).
std::vector<std::vector<uint32_t>> fastEuclideanClustering(const std::vector<Eigen::Vector3f>& points, double radius,
                                                          int max_neighbors, int min_size);

}  // namespace sgtllc
