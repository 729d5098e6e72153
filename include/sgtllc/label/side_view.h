/// @file side_view.h
/// @brief What lies beside a segment as the sensor sees it (docs/labeller.md §4, "Seen whole"). A thin upright
///        segment whose sides are hidden behind nearer points may be a strip of a wall or a crown seen through a
///        gap, and its centre moves with the gap; a pole is seen against what lies behind it on both sides.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::label {

/// The points of one scan indexed by azimuth around the sensor (the origin). Immutable after construction.
class SideView {
 public:
  /// Indexes the points with @p use[i] != 0 (and finite); @p use has one flag per point.
  SideView(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use);

  /// For the points @p members (indices of indexed points; others are ignored): the indexed points
  /// just beside them — within @p beside m of their left or right edge in azimuth, at their mean horizontal range
  /// (at most half a radian), and within their span of elevation — that lie more than @p nearer m nearer the sensor,
  /// as a share of the points beside that side. Returns the larger of the two sides' shares; a side with no point
  /// beside it counts 0 (open sky or beyond the range). Fewer than 2 members, or a mean range under 1 m, give 0.
  double occludedSide(const std::vector<int>& members, double beside, double nearer) const;

 private:
  // Per point (NaN range for a point not indexed): the diamond angle in [0, 4], a monotone stand-in
  // for the azimuth; the horizontal range; z / range, monotone in the elevation.
  std::vector<float> angle_;
  std::vector<float> range_;
  std::vector<float> slope_;
  std::vector<int> bin_start_;  ///< kBins + 1 offsets into order_
  std::vector<int> order_;      ///< the indexed points by azimuth bin, in point order within a bin
};

}  // namespace sgtllc::label
