#include "sgtllc/map/thinning.h"

#include <cmath>
#include <cstdint>

#include "sgtllc/point_kdtree.h"

namespace sgtllc::map {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Map frames looked at around a session frame, nearest first: a street seen by many sessions keeps a frame every
/// few metres per direction, so the covering frame is among the nearest few.
constexpr int kNearest = 32;

}  // namespace

std::vector<bool> framesThatAdd(const std::vector<Eigen::Matrix4d>& map_poses,
                                const std::vector<Eigen::Isometry3d>& frames, const std::vector<bool>& recognised,
                                double distance_m, double heading_deg) {
  std::vector<bool> keep(frames.size(), true);
  if (!(distance_m > 0.0) || map_poses.empty()) return keep;
  std::vector<float> xyz;
  xyz.reserve(3 * map_poses.size());
  for (const Eigen::Matrix4d& T : map_poses) {
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(T(k, 3)));
  }
  const PointKdTree tree(&xyz);
  const double min_cos = std::cos(heading_deg * kPi / 180.0);
  std::vector<uint32_t> near;
  for (size_t f = 0; f < frames.size(); ++f) {
    if (f >= recognised.size() || !recognised[f]) continue;
    const Eigen::Vector3d at = frames[f].translation();
    const Eigen::Vector3d forward = frames[f].linear().col(0);
    const float query[3] = {static_cast<float>(at.x()), static_cast<float>(at.y()), static_cast<float>(at.z())};
    tree.knn(query, kNearest, &near);
    for (uint32_t m : near) {
      const Eigen::Matrix4d& T = map_poses[m];
      if ((T.topRightCorner<3, 1>() - at).norm() > distance_m) break;  // nearest first: the rest are farther
      if (T.topLeftCorner<3, 3>().col(0).dot(forward) >= min_cos) {
        keep[f] = false;
        break;
      }
    }
  }
  return keep;
}

}  // namespace sgtllc::map
