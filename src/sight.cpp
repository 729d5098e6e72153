// The sight profile and the seen-through comparison (sight.h; docs/algorithm.md §7.7, "Seen through").
#include "sgtllc/sight.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "internal/rigid_inverse.h"
#include "sgtllc/diamond_angle.h"

namespace sgtllc {
namespace {

constexpr int kMaxReach = 255;
/// Only returns within this range are compared (m): the footprint's reach, where the sight is dense.
constexpr double kCompareRange = 40.0;

/// How far from the other frame's sight a return still counts as seen there (m): the pose's error (RANSAC's inlier
/// threshold and more), the sight's rounding, and the rotation's error growing with the range.
double sightMargin(double range) { return 1.0 + 0.03 * range; }

/// The sector of direction (@p x, @p y), in the arithmetic of T: float for a scan's points, double for a pose's.
template <typename T>
int sectorOf(T x, T y) {
  return std::min(kSightSectors - 1, static_cast<int>(diamondAngle(x, y) * (T(0.25) * kSightSectors)));
}

/// The unit direction in the middle of sector @p s (the diamond angle, inverted).
Eigen::Vector2d sectorDirection(int s) {
  const double d = (s + 0.5) * 4.0 / kSightSectors;
  Eigen::Vector2d v;
  if (d < 1.0) {
    v = {1.0 - d, d};
  } else if (d < 2.0) {
    v = {1.0 - d, 2.0 - d};
  } else if (d < 3.0) {
    v = {d - 3.0, 2.0 - d};
  } else {
    v = {d - 3.0, d - 4.0};
  }
  return v.normalized();
}

/// The structure range of sector @p s (in steps): the high layer's nearest return, something standing taller than
/// the sensor; 0 = none. Returns of the low layer alone are not judged: a hedge, a car or a person whose top lies
/// in that layer is grazed by one scan's beams and passed over by the other's (BENCHMARKS.md, "Seen through").
int structureOf(const Sight& sight, size_t s) {
  const int high = sight.high[s];
  return high == kMaxReach ? 0 : high;
}

/// The nearest return of either layer in sector @p s (in steps); 0 = neither layer saw anything come back.
int nearestOf(const Sight& sight, size_t s) {
  const int low = sight.low[s], high = sight.high[s];
  if (low == 0 || high == 0) return std::max(low, high);
  return std::min(low, high);
}

/// Adds to @p out the comparison of @p from's structure with @p to's sight, @p T mapping from's frame into to's.
/// The other frame's sight is read as the nearest of the sector and its two neighbours: structure near a sector's
/// edge, or moved across it by the pose's error, is not judged against a neighbour's longer view.
void compare(const Sight& from, const Sight& to, const Eigen::Matrix4d& T, SeenThrough* out) {
  const Eigen::Matrix2d R = T.topLeftCorner<2, 2>();
  const Eigen::Vector2d t = T.topRightCorner<2, 1>();
  for (int s = 0; s < kSightSectors; ++s) {
    const int q = structureOf(from, static_cast<size_t>(s));
    if (q == 0) continue;
    const double r = (q + 0.5) * kSightStep;
    if (r > kCompareRange) continue;
    const Eigen::Vector2d p = R * (r * sectorDirection(s)) + t;
    const double d = p.norm();
    if (!(d >= kSightMinRange && d <= kCompareRange)) continue;  // a NaN pose judges nothing
    const int b = sectorOf(p.x(), p.y());
    int seen = kMaxReach;
    for (int k = -1; k <= 1; ++k) {
      seen = std::min(seen, nearestOf(to, static_cast<size_t>((b + k + kSightSectors) % kSightSectors)));
    }
    if (seen == 0) continue;  // a sector that saw nothing come back says nothing
    const double sight = seen * kSightStep;
    const double margin = sightMargin(d);
    if (d > sight + margin) continue;  // hidden behind what the other frame saw
    ++out->judged;
    if (d < sight - margin) ++out->seen_through;
  }
}

}  // namespace

Sight computeSight(const std::vector<Eigen::Vector3f>& points) {
  constexpr float kNone = std::numeric_limits<float>::infinity();
  std::vector<float> nearest(2 * kSightSectors, kNone);  // squared ranges, [layer * sectors + sector]
  const float min2 = kSightMinRange * kSightMinRange;
  for (const Eigen::Vector3f& p : points) {
    if (!(p.z() >= -kSightBelow && p.z() <= kSightAbove)) continue;  // also drops NaN
    const float r2 = p.x() * p.x() + p.y() * p.y();
    if (!(r2 >= min2 && r2 <= std::numeric_limits<float>::max())) continue;  // no sector for an infinite one
    const int s = sectorOf(p.x(), p.y());
    float& slot = nearest[static_cast<size_t>((p.z() >= 0.0f ? kSightSectors : 0) + s)];
    slot = std::min(slot, r2);
  }
  Sight sight;
  sight.low.assign(kSightSectors, 0);
  sight.high.assign(kSightSectors, 0);
  for (size_t k = 0; k < nearest.size(); ++k) {
    if (nearest[k] == kNone) continue;
    const float steps = std::floor(std::sqrt(nearest[k]) / kSightStep);
    std::vector<uint8_t>& layer = k < static_cast<size_t>(kSightSectors) ? sight.low : sight.high;
    layer[k % kSightSectors] = static_cast<uint8_t>(std::min(steps, static_cast<float>(kMaxReach)));
  }
  return sight;
}

SeenThrough seenThrough(const Sight& query, const Sight& match, const Eigen::Matrix4d& T_match_query) {
  SeenThrough out;
  for (const Sight* sight : {&query, &match}) {
    if (sight->low.size() != kSightSectors || sight->high.size() != kSightSectors) return out;
  }
  compare(query, match, T_match_query, &out);
  compare(match, query, internal::rigidInverse(T_match_query), &out);
  return out;
}

}  // namespace sgtllc
