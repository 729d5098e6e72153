/// @file view_ceiling.h
/// @brief Where the sensor's view ends upwards (docs/labeller.md §4, "Standing taller than a person"). Near the
///        sensor the view ends low (KITTI's 64-beam sensor, 1.73 m up, sees 2–4° above the horizontal: up to
///        about 2 m above the ground at 5 m), so an object's highest point there is where the view ends.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::label {

/// The elevation slope (z / horizontal range, sensor frame) that a share @p share of the points flagged in @p use
/// reach or pass: the top of the sensor's view in this scan, robust to a few stray points above it. Only points
/// above the sensor (z > 0) and at least 1 m away horizontally count towards the slopes; the share is of every
/// flagged finite point. +inf when fewer flagged points lie above the sensor than the share asks for (nothing then
/// reaches the view's top). Deterministic: a pure function of the points.
float viewCeiling(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use, double share);

}  // namespace sgtllc::label
