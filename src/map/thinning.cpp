#include "sgtllc/map/thinning.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sgtllc/point_kdtree.h"

namespace sgtllc::map {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Map frames looked at around a session frame, nearest first: a street seen by many sessions keeps a frame every
/// few metres per direction, so the covering frames are among the nearest few.
constexpr int kNearest = 32;

}  // namespace

std::vector<int> frameSessions(const Map& map) {
  std::vector<int> session(static_cast<size_t>(map.size()), 0);
  for (size_t s = 0; s < map.sessions.size(); ++s) {
    const MapSession& m = map.sessions[s];
    for (int f = m.first; f < m.first + m.frames && f < map.size(); ++f) {
      session[static_cast<size_t>(f)] = static_cast<int>(s);
    }
  }
  return session;
}

std::vector<bool> framesThatAdd(const std::vector<Eigen::Matrix4d>& map_poses, const std::vector<int>& map_session,
                                const std::vector<Eigen::Isometry3d>& frames, const std::vector<bool>& recognised,
                                const ThinningRule& rule) {
  std::vector<bool> keep(frames.size(), true);
  if (!(rule.distance_m > 0.0) || map_poses.empty()) return keep;
  std::vector<float> xyz;
  xyz.reserve(3 * map_poses.size());
  for (const Eigen::Matrix4d& T : map_poses) {
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(T(k, 3)));
  }
  const PointKdTree tree(&xyz);
  const double min_cos = std::cos(rule.heading_deg * kPi / 180.0);
  std::vector<uint32_t> near;
  std::vector<int> drives;  // the drives whose frames cover the session frame
  for (size_t f = 0; f < frames.size(); ++f) {
    const bool known = f < recognised.size() && recognised[f];
    const Eigen::Vector3d at = frames[f].translation();
    const Eigen::Vector3d forward = frames[f].linear().col(0);
    const float query[3] = {static_cast<float>(at.x()), static_cast<float>(at.y()), static_cast<float>(at.z())};
    tree.knn(query, kNearest, &near);
    drives.clear();
    for (uint32_t m : near) {
      const Eigen::Matrix4d& T = map_poses[m];
      if ((T.topRightCorner<3, 1>() - at).norm() > rule.distance_m) break;  // nearest first: the rest are farther
      if (T.topLeftCorner<3, 3>().col(0).dot(forward) < min_cos) continue;
      const int drive = m < map_session.size() ? map_session[m] : 0;
      if (std::find(drives.begin(), drives.end(), drive) == drives.end()) drives.push_back(drive);
      if (known || static_cast<int>(drives.size()) >= rule.max_covering_sessions) {
        keep[f] = false;
        break;
      }
    }
  }
  return keep;
}

}  // namespace sgtllc::map
