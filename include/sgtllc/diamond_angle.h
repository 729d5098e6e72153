/// @file diamond_angle.h
/// @brief The "diamond angle": a monotone stand-in for atan2(y, x) in [0, 4], shared by the labeller's ground grid
///        and side view and by the sight profile (sight.h). Equal steps of it are not equal angles (at most 1.5×
///        apart), which binning does not need; it is a division and a few comparisons, where atan2 is a library call.
#pragma once

#include <cmath>

namespace sgtllc {

/// Diamond angle of (@p x, @p y): 0 along +x, 1 along +y, 2 along −x, 3 along −y; just below 4 just clockwise of
/// +x (rounding can give 4 itself, which binning must clamp); 0 at the origin.
template <typename T>
T diamondAngle(T x, T y) {
  const T s = std::abs(x) + std::abs(y);
  if (s == T(0)) return T(0);
  const T t = y / s;  // [-1, 1]
  return x >= T(0) ? (t >= T(0) ? t : T(4) + t) : T(2) - t;
}

}  // namespace sgtllc
