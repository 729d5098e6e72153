// The top of the sensor's view (view_ceiling.h): a high quantile of the elevation slopes of the points above the
// sensor, found with nth_element on the points that lie above it (about a sixth of a KITTI scan).
#include "sgtllc/label/view_ceiling.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace sgtllc::label {

float viewCeiling(const std::vector<Eigen::Vector3f>& points, const std::vector<uint8_t>& use, double share) {
  std::vector<float> slopes;
  size_t counted = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f& p = points[i];
    if (!use[i] || !p.allFinite()) continue;
    ++counted;
    if (p.z() <= 0.0f) continue;
    const float r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    if (r >= 1.0f) slopes.push_back(p.z() / r);
  }
  const auto above = static_cast<size_t>(share * static_cast<double>(counted));
  if (above >= slopes.size()) return std::numeric_limits<float>::infinity();
  const auto nth = slopes.end() - 1 - static_cast<std::ptrdiff_t>(above);
  std::nth_element(slopes.begin(), nth, slopes.end());
  return *nth;
}

}  // namespace sgtllc::label
