// Ground segmentation (docs/labeller.md §1), after Himmelsbach et al. 2010: the lowest point of each (sector, range
// bin) cell is a prototype; walking a sector outwards, a prototype continues the ground line if its height differs
// from the last ground prototype by at most step + max_slope · Δr. Cells whose prototype does not continue the line
// (the lowest point is on a car or a wall) keep the line's last height. Points within tolerance above their cell's
// ground height, or below it, are ground.
#include "sgtllc/label/ground.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Cholesky>

#include "sgtllc/diamond_angle.h"

namespace sgtllc::label {
namespace {

constexpr float kNoPoint = std::numeric_limits<float>::infinity();

}  // namespace

GroundResult segmentGround(const std::vector<Eigen::Vector3f>& points, const GroundConfig& config) {
  const size_t n = points.size();
  GroundResult result;
  result.ground.assign(n, 0);
  result.height.assign(n, std::numeric_limits<float>::quiet_NaN());
  const int sectors = config.sectors;
  const float bin = static_cast<float>(config.bin);
  const int bins = static_cast<int>(std::ceil(config.max_range / config.bin));
  std::vector<int> cell(n, -1);  // sector * bins + bin, or −1 (non-finite or out of range)
  std::vector<float> lowest(static_cast<size_t>(sectors) * bins, kNoPoint);
  std::vector<int> lowest_point(lowest.size(), -1);  // the first point at the cell's lowest height
  float scan_min = kNoPoint;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = points[i];
    if (!p.allFinite()) continue;
    scan_min = std::min(scan_min, p.z());
    const float r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    if (!(r < static_cast<float>(config.max_range))) continue;  // before the cast: a huge r is no int
    const int b = std::min(bins - 1, static_cast<int>(r / bin));
    const int s = std::min(sectors - 1, static_cast<int>(diamondAngle(p.x(), p.y()) * (0.25f * sectors)));
    const int c = s * bins + b;
    cell[i] = c;
    // Without a branch (a mask: GCC kept a branch for the conditional form): whether a point is its cell's lowest so
    // far is a coin toss the processor cannot predict; the branch was a fifth of the ground's time (BENCHMARKS.md,
    // "Within 10 ms at p99").
    const int lower = -static_cast<int>(p.z() < lowest[c]);
    lowest[c] = std::min(lowest[c], p.z());
    lowest_point[c] = (lowest_point[c] & ~lower) | (static_cast<int>(i) & lower);
  }

  // The ground height below the sensor: a plane fitted to the near cells' lowest points (most near cells see road),
  // started at their median and refitted to the cells within kPlaneBand of it, so that a tilted road is exact.
  std::vector<Eigen::Vector3f> near;
  const int first_bin = static_cast<int>(config.min_range / config.bin);
  const int last_bin = std::min(bins, static_cast<int>(20.0 / config.bin));
  for (int s = 0; s < sectors; ++s) {
    for (int b = first_bin; b < last_bin; ++b) {
      const size_t c = static_cast<size_t>(s) * bins + b;
      if (lowest[c] != kNoPoint) near.push_back(points[static_cast<size_t>(lowest_point[c])]);
    }
  }
  if (near.size() < 8) {
    // No ground to follow: heights are measured from the scan's lowest point so segments still have a height.
    for (size_t i = 0; i < n; ++i) {
      if (points[i].allFinite()) result.height[i] = points[i].z() - scan_min;
    }
    return result;
  }
  std::vector<float> zs(near.size());
  for (size_t k = 0; k < near.size(); ++k) zs[k] = near[k].z();
  std::nth_element(zs.begin(), zs.begin() + static_cast<std::ptrdiff_t>(zs.size() / 2), zs.end());
  Eigen::Vector3d plane(zs[zs.size() / 2], 0.0, 0.0);  // z = a + b x + c y
  constexpr double kPlaneBand = 0.3;
  for (int iteration = 0; iteration < 3; ++iteration) {
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3f& q : near) {
      const Eigen::Vector3d row(1.0, q.x(), q.y());
      if (std::abs(q.z() - row.dot(plane)) > kPlaneBand) continue;
      A += row * row.transpose();
      rhs += row * static_cast<double>(q.z());
    }
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(A);
    if (A(0, 0) < 8.0 || ldlt.info() != Eigen::Success || !ldlt.isPositive()) break;
    const Eigen::Vector3d next = ldlt.solve(rhs);
    if (!next.allFinite()) break;
    plane = next;
  }
  const float z0 = static_cast<float>(plane(0));
  result.found = true;
  result.sensor_ground_z = z0;

  // Each sector's ground line, walked outwards; ground_z holds every cell's ground height.
  std::vector<float> ground_z(lowest.size());
  const float step = static_cast<float>(config.step);
  const float slope = static_cast<float>(config.max_slope);
  // The anchor is the last ground prototype at least kAnchorDistance nearer: bounding the slope from it as well
  // stops a line from climbing a wall whose foot is hidden (each bin then adds only step + slope · bin).
  constexpr float kAnchorDistance = 2.0f;
  const float climb = static_cast<float>(config.max_climb);
  std::vector<std::pair<float, float>> line;  // accepted (r, z) of this sector, nearest first
  for (int s = 0; s < sectors; ++s) {
    line.assign(1, {0.0f, z0});
    size_t anchor = 0;
    for (int b = 0; b < bins; ++b) {
      const size_t c = static_cast<size_t>(s) * bins + b;
      const float r = (static_cast<float>(b) + 0.5f) * bin;
      const float z = lowest[c];
      while (anchor + 1 < line.size() && line[anchor + 1].first <= r - kAnchorDistance) ++anchor;
      const auto [last_r, last_z] = line.back();
      const auto [anchor_r, anchor_z] = line[anchor];
      if (z != kNoPoint && std::abs(z - last_z) <= step + slope * (r - last_r) &&
          std::abs(z - anchor_z) <= step + slope * (r - anchor_r) && std::abs(z - z0) <= step + climb * r) {
        line.emplace_back(r, z);
      }
      ground_z[c] = line.back().second;
    }
  }
  const float tolerance = static_cast<float>(config.tolerance);
  for (size_t i = 0; i < n; ++i) {
    if (!points[i].allFinite()) continue;
    // Beyond max_range the line is not followed; such points are measured against the sensor's ground height.
    const float g = cell[i] >= 0 ? ground_z[static_cast<size_t>(cell[i])] : z0;
    const float h = points[i].z() - g;
    result.height[i] = h;
    result.ground[i] = h <= tolerance ? 1 : 0;
  }
  return result;
}

}  // namespace sgtllc::label
