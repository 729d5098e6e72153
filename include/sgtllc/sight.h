/// @file sight.h
/// @brief A frame's sight: how far its sensor saw, direction by direction, at about its own height; and how much
///        of one frame's structure the other frame saw through under a pose (docs/algorithm.md §7.7, "Seen
///        through").
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc {

/// Per sector of azimuth (kSightSectors, by the diamond angle), the range of the nearest return in each of two
/// layers at about the sensor's height: up to kSightBelow under it (the low layer) and up to kSightAbove over it
/// (the high one). Nothing stood nearer in that direction at that height, since the beams went through. A return
/// of the high layer is structure standing taller than the sensor (a wall, a trunk, a pole, a crown); a car, a
/// person or a hedge, lower than the sensor, reaches the low layer only, and blocks the view all the same.
/// 720 bytes a frame.
struct Sight {
  /// Per sector, the nearest return's range in steps of kSightStep, rounded down (12..255 within the ranges
  /// kept, the last meaning that far or farther); 0 = no return in that layer.
  std::vector<uint8_t> low;
  std::vector<uint8_t> high;
  bool empty() const { return low.empty(); }
  size_t bytes() const { return low.size() + high.size(); }
};

constexpr int kSightSectors = 360;
constexpr float kSightStep = 0.25f;  ///< m per unit of Sight::low and high
/// The layers (m under and over the sensor): a sensor on a car is 1.7-1.9 m up, above most cars and people, so
/// only what stands taller reaches the high layer (BENCHMARKS.md, "Seen through").
constexpr float kSightBelow = 1.0f;
constexpr float kSightAbove = 1.0f;
constexpr float kSightMinRange = 3.0f;  ///< nearer returns are the vehicle itself, its mount or its driver

/// The sight of a scan (points in the sensor frame, z up). A pure function of the points.
Sight computeSight(const std::vector<Eigen::Vector3f>& points);

/// Of the structure one frame saw (its high layer's nearest returns) that the other frame's sensor could see under
/// the pose, how much it saw through (its beams, of either layer, went on well past), both ways.
struct SeenThrough {
  int judged = 0;        ///< structure sectors (of both frames) that fell in, or at the end of, the other's sight
  int seen_through = 0;  ///< of those, the ones the other frame's beams passed
  double share() const { return judged > 0 ? static_cast<double>(seen_through) / judged : 0.0; }
};

/// Each frame's structure (at its sector's middle azimuth, in the sensor's plane) is moved into the other frame
/// (p_match = T · p_query, and back) and compared with the nearest return of either layer there, over that sector
/// and its two neighbours. Empty sights judge nothing.
SeenThrough seenThrough(const Sight& query, const Sight& match, const Eigen::Matrix4d& T_match_query);

}  // namespace sgtllc
