// Nearest first-session frames (include/sgtllc/sim/cross_session.h).
#include "sgtllc/sim/cross_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>

#include "sgtllc/types.h"

namespace sgtllc::sim {

std::vector<NearestFrame> nearestFrames(const std::vector<Eigen::Vector3d>& map,
                                        const std::vector<Eigen::Vector3d>& queries, double cell) {
  if (!(cell > 0.0)) throw Error("the grid cell of a nearest-frame search must be positive");
  using Key = std::pair<long, long>;
  auto key = [&](const Eigen::Vector3d& p) {
    return Key(static_cast<long>(std::floor(p.x() / cell)), static_cast<long>(std::floor(p.y() / cell)));
  };
  std::map<Key, std::vector<int>> grid;
  long x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (size_t i = 0; i < map.size(); ++i) {
    const Key k = key(map[i]);
    grid[k].push_back(static_cast<int>(i));
    x0 = i == 0 ? k.first : std::min(x0, k.first);
    x1 = i == 0 ? k.first : std::max(x1, k.first);
    y0 = i == 0 ? k.second : std::min(y0, k.second);
    y1 = i == 0 ? k.second : std::max(y1, k.second);
  }
  std::vector<NearestFrame> out(queries.size());
  if (map.empty()) return out;
  for (size_t q = 0; q < queries.size(); ++q) {
    const Key c = key(queries[q]);
    NearestFrame& best = out[q];
    double best_d = std::numeric_limits<double>::infinity();
    // Ring r holds the cells r steps from c; a point in ring r or beyond is at least (r − 1)·cell away in xy, so
    // the search stops once the best distance is below that (ties at exactly that distance still look further).
    const long last = std::max({std::abs(c.first - x0), std::abs(c.first - x1), std::abs(c.second - y0),
                                std::abs(c.second - y1)});
    for (long r = 0; r <= last && !(best_d < (r - 1) * cell); ++r) {
      for (long dx = -r; dx <= r; ++dx) {
        for (long dy = -r; dy <= r; ++dy) {
          if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
          const auto it = grid.find(Key(c.first + dx, c.second + dy));
          if (it == grid.end()) continue;
          for (int i : it->second) {
            const double d = (map[static_cast<size_t>(i)] - queries[q]).norm();
            if (d < best_d || (d == best_d && i < best.frame)) {
              best_d = d;
              best.frame = i;
            }
          }
        }
      }
    }
    best.distance = best_d;
  }
  return out;
}

void writeCrossSession(const std::string& path, const std::vector<NearestFrame>& nearest, io::Overwrite overwrite) {
  std::string text;
  char line[64];
  for (size_t i = 0; i < nearest.size(); ++i) {
    std::snprintf(line, sizeof(line), "%06zu %06d %.3f\n", i, nearest[i].frame, nearest[i].distance);
    text += line;
  }
  io::writeFileAtomically(path, text, overwrite);
}

}  // namespace sgtllc::sim
