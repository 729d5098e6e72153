/// @file ground.h
/// @brief Ground segmentation of one scan in the sensor frame (z up): a polar grid of sectors and range bins, each
///        sector's lowest points followed outwards as a line of bounded slope and step, after Himmelsbach, Hundelshausen
///        and Wuensche, "Fast segmentation of 3D point clouds for ground vehicles", IEEE IV 2010 (docs/labeller.md §1).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config/labeller_config.h"

namespace sgtllc::label {

/// Per-point result of segmentGround().
struct GroundResult {
  std::vector<uint8_t> ground;  ///< 1 = ground (within tolerance of the local ground height, or below it)
  /// Height of the point above its bin's ground height (m); NaN for a non-finite point. Without ground it is the
  /// height above the lowest finite point of the scan.
  std::vector<float> height;
  bool found = false;  ///< false: too few bins near the sensor to estimate the ground (no point is ground)
  float sensor_ground_z = 0.0f;  ///< estimated ground height below the sensor (m, sensor frame)
};

/// Marks the ground points of @p points. Non-finite points are never ground. Deterministic; O(points + bins).
GroundResult segmentGround(const std::vector<Eigen::Vector3f>& points, const GroundConfig& config);

}  // namespace sgtllc::label
