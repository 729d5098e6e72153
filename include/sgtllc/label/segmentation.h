/// @file segmentation.h
/// @brief Segments of the non-ground points: connected components of occupied voxels under 26-neighbourhood
///        (docs/labeller.md §2), the voxel-grid form of Euclidean clustering (Rusu 2009, §4.2).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::label {

/// Voxels and segments of one scan; ids are dense and numbered in the order of their first point.
struct Segmentation {
  std::vector<int> point_voxel;    ///< voxel of each point, −1 if the point was not segmented
  std::vector<int> voxel_segment;  ///< segment of each voxel
  int num_voxels = 0;
  int num_segments = 0;
};

/// Largest |coordinate| (m) of a segmented point: voxel keys pack 21 bits per axis. LiDAR scans reach ~200 m.
inline constexpr float kMaxSegmentCoordinate = 1000.0f;

/// Segments the points with @p use[i] != 0 (and finite, within ±kMaxSegmentCoordinate) in voxels of @p voxel m
/// (≥ 0.001). Deterministic: a pure function of the points, in their order.
Segmentation segmentVoxels(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use, double voxel);

}  // namespace sgtllc::label
