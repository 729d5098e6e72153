// What lies beside a segment as the sensor sees it (docs/labeller.md §4, "Seen whole"). The points are binned by
// the diamond angle (diamond_angle.h, the ground grid's stand-in for atan2); a query turns its window's edges, found
// in true angle from the members' mean range, into diamond angles and reads only the bins between them. Those edges
// come from std::cos and std::sin, whose last bit may differ between maths libraries: the same on every run and
// thread count, not necessarily bit for bit across platforms.
#include "sgtllc/label/side_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "diamond_angle.h"

namespace sgtllc::label {
namespace {

constexpr int kBins = 2048;
constexpr double kPi = 3.14159265358979323846;
/// The widest window beside a side (radians): at 1.2 m, 0.6 m beside is already half a radian.
constexpr double kMaxWindow = 0.5;

float diamondOf(double x, double y) { return static_cast<float>(diamondAngle(x, y)); }

/// The true azimuth (radians, (−π, π]) of diamond angle @p d.
double azimuthOf(float d) {
  const int q = std::min(3, static_cast<int>(d));
  const double t = d - q;
  static constexpr double kX[4][2] = {{1, -1}, {0, -1}, {-1, 1}, {0, 1}};  // x = a + b·t per quadrant
  static constexpr double kY[4][2] = {{0, 1}, {1, -1}, {0, -1}, {-1, 1}};
  return std::atan2(kY[q][0] + kY[q][1] * t, kX[q][0] + kX[q][1] * t);
}

int binOf(float d) { return std::min(kBins - 1, std::max(0, static_cast<int>(d * (kBins / 4.0f)))); }

/// Wraps an angle difference into (−π, π].
double wrap(double a) {
  while (a > kPi) a -= 2.0 * kPi;
  while (a <= -kPi) a += 2.0 * kPi;
  return a;
}

}  // namespace

SideView::SideView(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use)
    : angle_(points.size(), 0.0f),
      range_(points.size(), std::numeric_limits<float>::quiet_NaN()),
      slope_(points.size(), 0.0f),
      bin_start_(kBins + 1, 0) {
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f& p = points[i];
    if (!use[i] || !p.allFinite()) continue;
    const float r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    angle_[i] = diamondOf(p.x(), p.y());
    range_[i] = r;
    slope_[i] = r > 0.0f ? p.z() / r : 0.0f;
    if (r > 0.0f) ++bin_start_[binOf(angle_[i]) + 1];
  }
  for (int b = 0; b < kBins; ++b) bin_start_[b + 1] += bin_start_[b];
  order_.resize(static_cast<size_t>(bin_start_[kBins]));
  std::vector<int> next(bin_start_.begin(), bin_start_.end() - 1);
  for (size_t i = 0; i < points.size(); ++i) {
    if (range_[i] > 0.0f) order_[next[binOf(angle_[i])]++] = static_cast<int>(i);
  }
}

double SideView::occludedSide(const std::vector<int>& members, double beside, double nearer) const {
  // The members' mean range and azimuth, their azimuth interval about it and their span of elevation.
  double range = 0.0, cx = 0.0, cy = 0.0;
  int count = 0;
  for (int i : members) {
    if (!(range_[i] > 0.0f)) continue;
    const double a = azimuthOf(angle_[i]);
    range += range_[i];
    cx += std::cos(a);
    cy += std::sin(a);
    ++count;
  }
  if (count < 2) return 0.0;
  range /= count;
  if (range < 1.0) return 0.0;
  const double centre = std::atan2(cy, cx);
  double lo = 0.0, hi = 0.0;
  float slope_lo = std::numeric_limits<float>::infinity(), slope_hi = -slope_lo;
  for (int i : members) {
    if (!(range_[i] > 0.0f)) continue;
    const double a = wrap(azimuthOf(angle_[i]) - centre);
    lo = std::min(lo, a);
    hi = std::max(hi, a);
    slope_lo = std::min(slope_lo, slope_[i]);
    slope_hi = std::max(slope_hi, slope_[i]);
  }
  const double width = std::min(kMaxWindow, beside / range);  // radians
  const float near_range = static_cast<float>(range - nearer);
  double worst = 0.0;
  const std::pair<double, double> sides[2] = {{centre + lo - width, centre + lo}, {centre + hi, centre + hi + width}};
  for (const auto& [from, to] : sides) {
    const float d0 = diamondOf(std::cos(from), std::sin(from));
    const float d1 = diamondOf(std::cos(to), std::sin(to));
    const bool wraps = d1 < d0;  // the window crosses the diamond angle's 0
    int beside_points = 0, nearer_points = 0;
    const int b0 = binOf(d0), b1 = binOf(d1);
    for (int b = b0;; b = (b + 1) % kBins) {
      for (int k = bin_start_[b]; k < bin_start_[b + 1]; ++k) {
        const int i = order_[k];
        const float d = angle_[i];
        const bool inside = wraps ? (d > d0 || d < d1) : (d > d0 && d < d1);
        if (!inside || slope_[i] < slope_lo || slope_[i] > slope_hi) continue;
        ++beside_points;
        nearer_points += range_[i] < near_range;
      }
      if (b == b1) break;
    }
    if (beside_points > 0) worst = std::max(worst, static_cast<double>(nearer_points) / beside_points);
  }
  return worst;
}

}  // namespace sgtllc::label
