// Poles and trunks (docs/labeller.md §4): what makes a thin upright a pole, shared by the whole-segment rule
// (geometric_labeller.cpp) and the slice search for poles inside larger segments (pole_slices.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config/labeller_config.h"
#include "sgtllc/label/geometric_labeller.h"

namespace sgtllc::label {

/// A pole or trunk stands taller than a person: it reaches pole_min_top above the ground, or the top of the
/// sensor's view (within kViewTopMargin of the slope that kViewTopShare of the non-ground points reach), where what
/// it reaches is the view's end, not its own. The margin is wide because KITTI's highest beams lie a degree or more
/// apart in elevation around the azimuth (docs/labeller.md §4, "Standing taller than a person").
constexpr double kViewTopShare = 0.001;
constexpr float kViewTopMargin = 0.035f;  // a slope of about 2 degrees
/// A pole is seen whole if, within kBeside m beside each side of it, at most pole_max_occluded of the points lie
/// more than kNearer m nearer the sensor (docs/labeller.md §4, "Seen whole").
constexpr double kBeside = 0.6;
constexpr double kNearer = 0.5;

/// Whether @p p (sensor frame) lies at or above the elevation slope @p view_top (z / horizontal range).
inline bool atViewTop(const Eigen::Vector3f& p, float view_top) {
  return p.z() > 0.0f && p.z() >= view_top * std::sqrt(p.x() * p.x() + p.y() * p.y());
}

/// Poles and trunks inside larger segments (a trunk under its crown or in a bush, a pole touching a hedge): the
/// points of a horizontal slice of the scene, pole_slice_low..pole_slice_high above the ground (@p height), are
/// segmented on their own, and again kUpperSliceLift higher; a slice component that is thin (4 std devs ≤
/// pole_max_width), spans pole_min_span of height and is seen whole against the points flagged in @p seen (none:
/// every thin component is) is a pole section. If the points of its segment within pole_radius of its axis, at any
/// height, reach pole_min_top or @p view_top, those up to kPoleAboveSlice above its slice become kPole in @p out.
/// @p standing flags the segments that reach either at all; the others' points are left out of the slices, as no
/// pole can stand in them (cars, people, low bushes: a quarter or more of a street's slice points).
/// After the slicing pole extraction of Schaefer et al., "Long-term urban vehicle localization using pole
/// landmarks extracted from 3-D lidar scans", ECMR 2019.
void markPoles(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& height,
               const std::vector<uint8_t>* seen, float view_top, const std::vector<uint8_t>& standing,
               const SegmentRuleConfig& r, Labelling* out);

}  // namespace sgtllc::label
