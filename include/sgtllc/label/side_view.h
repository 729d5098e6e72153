/// @file side_view.h
/// @brief What lies beside a segment as the sensor sees it (docs/labeller.md §4, "Seen whole"). A thin upright
///        segment whose sides are hidden behind nearer points may be a strip of a wall or a crown seen through a
///        gap, and its centre moves with the gap; a pole is seen against what lies behind it on both sides.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::label {

/// For each candidate of @p candidates (indices into @p points): the points just beside it — within @p beside m
/// of its left or right edge in azimuth about the sensor (the origin), at its mean horizontal range (at most half
/// a radian), and within its span of elevation — that lie more than @p nearer m nearer the sensor, as a share of
/// the points beside that side; the larger of the two sides' shares. Only points with @p use[i] != 0 (one flag per
/// point) and finite coordinates count, as members or beside them. A side with no point beside it counts 0 (open
/// sky or beyond the range); fewer than 2 members, or a mean range under 1 m, give 0.
/// The candidates are answered together so that only the azimuths their windows reach are indexed: the cost is a
/// pass over the points and memory for the points beside them, not for the scan (BENCHMARKS.md, "Poles seen whole").
std::vector<double> occludedSides(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use,
                                  const std::vector<std::vector<int>>& candidates, double beside, double nearer);

}  // namespace sgtllc::label
