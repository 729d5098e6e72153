// What lies beside a segment as the sensor sees it (docs/labeller.md §4, "Seen whole"). Points are placed by the
// diamond angle (diamond_angle.h, the ground grid's stand-in for atan2) in kBins bins. The candidates' windows are
// found first, in true angle from each candidate's mean range, and turned into diamond angles; one pass over the
// scan then keeps only the points in bins some window reaches, sorted by bin, and each window reads its bins. A
// scan-sized index (three floats and an index per point, 1.9 MB for a 120 k-point scan) cost more in fresh memory
// than the search itself (BENCHMARKS.md, "Poles seen whole"). The edges come from std::cos and std::sin, whose last
// bit may differ between maths libraries: the same on every run and thread count, not necessarily bit for bit
// across platforms.
#include "sgtllc/label/side_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sgtllc/diamond_angle.h"

namespace sgtllc::label {
namespace {

constexpr int kBins = 2048;
constexpr double kPi = 3.14159265358979323846;
/// The widest window beside a side (radians): at 1.2 m, 0.6 m beside is already half a radian.
constexpr double kMaxWindow = 0.5;

/// A point as the side view sees it: diamond angle in [0, 4] (monotone in the azimuth), horizontal range, and
/// z / range (monotone in the elevation).
struct Seen {
  float angle;
  float range;
  float slope;
};

/// @p p as seen from the origin; false if it is not to be seen (not used, not finite, or on the vertical axis).
bool see(const Eigen::Vector3f& p, uint8_t use, Seen* s) {
  if (!use || !p.allFinite()) return false;
  const float r = std::sqrt(p.x() * p.x() + p.y() * p.y());
  if (!(r > 0.0f)) return false;
  *s = {static_cast<float>(diamondAngle<double>(p.x(), p.y())), r, p.z() / r};
  return true;
}

/// The true azimuth (radians, (−π, π]) of diamond angle @p d.
double azimuthOf(float d) {
  const int q = std::min(3, static_cast<int>(d));
  const double t = d - q;
  static constexpr double kX[4][2] = {{1, -1}, {0, -1}, {-1, 1}, {0, 1}};  // x = a + b·t per quadrant
  static constexpr double kY[4][2] = {{0, 1}, {1, -1}, {0, -1}, {-1, 1}};
  return std::atan2(kY[q][0] + kY[q][1] * t, kX[q][0] + kX[q][1] * t);
}

float diamondOfAzimuth(double a) { return static_cast<float>(diamondAngle(std::cos(a), std::sin(a))); }

int binOf(float d) { return std::min(kBins - 1, std::max(0, static_cast<int>(d * (kBins / 4.0f)))); }

/// Wraps an angle difference into (−π, π].
double wrap(double a) {
  while (a > kPi) a -= 2.0 * kPi;
  while (a <= -kPi) a += 2.0 * kPi;
  return a;
}

/// One side of one candidate: the open interval (d0, d1) of diamond angles (across 0 when d1 < d0), the
/// members' span of z / range, and the range under which a point beside them is nearer.
struct Window {
  float d0, d1;
  float slope_lo, slope_hi;
  float near_range;
  int candidate;

  bool wraps() const { return d1 < d0; }
  bool contains(const Seen& s) const {
    const bool inside = wraps() ? (s.angle > d0 || s.angle < d1) : (s.angle > d0 && s.angle < d1);
    return inside && s.slope >= slope_lo && s.slope <= slope_hi;
  }
  /// Calls @p f(b) for the bins from d0's to d1's, across the last bin when the window wraps.
  template <typename F>
  void forEachBin(F f) const {
    const int b1 = binOf(d1);
    for (int b = binOf(d0);; b = (b + 1) % kBins) {
      f(b);
      if (b == b1) break;
    }
  }
};

/// The two windows of a candidate (none if it has fewer than 2 seen members or lies within 1 m).
void windowsOf(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use,
               const std::vector<int>& members, int candidate, double beside, double nearer,
               std::vector<Window>* out) {
  // The members' mean range and azimuth, their azimuth interval about it and their span of elevation.
  std::vector<double> azimuths;
  azimuths.reserve(members.size());
  float slope_lo = std::numeric_limits<float>::infinity(), slope_hi = -slope_lo;
  Seen s;
  double range = 0.0, cx = 0.0, cy = 0.0;
  for (int i : members) {
    if (!see(points[i], use[i], &s)) continue;
    const double a = azimuthOf(s.angle);
    range += s.range;
    cx += std::cos(a);
    cy += std::sin(a);
    slope_lo = std::min(slope_lo, s.slope);
    slope_hi = std::max(slope_hi, s.slope);
    azimuths.push_back(a);
  }
  if (azimuths.size() < 2) return;
  range /= static_cast<double>(azimuths.size());
  if (range < 1.0) return;
  const double centre = std::atan2(cy, cx);
  double lo = 0.0, hi = 0.0;
  for (double a : azimuths) {
    lo = std::min(lo, wrap(a - centre));
    hi = std::max(hi, wrap(a - centre));
  }
  const double width = std::min(kMaxWindow, beside / range);  // radians
  const float near_range = static_cast<float>(range - nearer);
  const std::pair<double, double> sides[2] = {{centre + lo - width, centre + lo}, {centre + hi, centre + hi + width}};
  for (const auto& [from, to] : sides) {
    out->push_back({diamondOfAzimuth(from), diamondOfAzimuth(to), slope_lo, slope_hi, near_range, candidate});
  }
}

}  // namespace

std::vector<double> occludedSides(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use,
                                  const std::vector<std::vector<int>>& candidates, double beside, double nearer) {
  std::vector<double> worst(candidates.size(), 0.0);
  std::vector<Window> windows;
  for (size_t c = 0; c < candidates.size(); ++c) {
    windowsOf(points, use, candidates[c], static_cast<int>(c), beside, nearer, &windows);
  }
  if (windows.empty()) return worst;
  std::vector<uint8_t> wanted(kBins, 0);
  for (const Window& w : windows) w.forEachBin([&](int b) { wanted[b] = 1; });

  // The seen points in wanted bins, sorted by bin (counting sort; in point order within a bin).
  std::vector<std::pair<int, Seen>> kept;
  Seen s;
  for (size_t i = 0; i < points.size(); ++i) {
    // The bin first: most points lie in no window, and their range and slope (a root and a division) are not needed.
    const Eigen::Vector3f& p = points[i];
    if (!use[i] || !p.allFinite()) continue;
    const int b = binOf(static_cast<float>(diamondAngle<double>(p.x(), p.y())));
    if (wanted[b] && see(p, use[i], &s)) kept.emplace_back(b, s);
  }
  std::vector<int> start(kBins + 1, 0);
  for (const auto& k : kept) ++start[k.first + 1];
  for (int b = 0; b < kBins; ++b) start[b + 1] += start[b];
  std::vector<Seen> by_bin(kept.size());
  std::vector<int> next(start.begin(), start.end() - 1);
  for (const auto& k : kept) by_bin[next[k.first]++] = k.second;

  for (const Window& w : windows) {
    int beside_points = 0, nearer_points = 0;
    w.forEachBin([&](int b) {
      for (int k = start[b]; k < start[b + 1]; ++k) {
        if (!w.contains(by_bin[k])) continue;
        ++beside_points;
        nearer_points += by_bin[k].range < w.near_range;
      }
    });
    if (beside_points > 0) {
      worst[w.candidate] = std::max(worst[w.candidate], static_cast<double>(nearer_points) / beside_points);
    }
  }
  return worst;
}

}  // namespace sgtllc::label
