#include "sgtllc/sim/loop_pairs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>

#include "sgtllc/sim/rng.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {

std::vector<LoopPair> loopPairs(const std::vector<Eigen::Matrix4d>& lidar_poses, const LoopPairOptions& o) {
  const int n = static_cast<int>(lidar_poses.size());
  std::vector<Eigen::Vector3d> pos(n);
  for (int i = 0; i < n; ++i) pos[i] = lidar_poses[i].topRightCorner<3, 1>();
  auto distance = [&](int a, int b) { return (pos[a] - pos[b]).norm(); };

  // Positives through a grid of cells as large as the positive distance: only the 3×3 cells around a query.
  const double cell = std::max(o.positive_distance, 1e-3);
  auto key = [&](int i, int dx, int dy) {
    return std::pair<long, long>(static_cast<long>(std::floor(pos[i].x() / cell)) + dx,
                                 static_cast<long>(std::floor(pos[i].y() / cell)) + dy);
  };
  std::map<std::pair<long, long>, std::vector<int>> grid;
  std::vector<LoopPair> pairs;
  for (int q = 0; q < n; ++q) {
    std::vector<int> found;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = grid.find(key(q, dx, dy));
        if (it == grid.end()) continue;
        for (int c : it->second) {
          if (distance(q, c) <= o.positive_distance) found.push_back(c);
        }
      }
    }
    std::sort(found.begin(), found.end());
    for (int c : found) pairs.push_back(LoopPair{q, c, true});
    // Frame q may serve as a candidate once the gap has passed.
    if (q - o.min_gap + 1 >= 0 && q + 1 < n) {
      const int ready = q - o.min_gap + 1;
      grid[key(ready, 0, 0)].push_back(ready);
    }
  }
  // Negatives: uniform random (query, candidate) pairs farther apart than the negative distance.
  const size_t positives = pairs.size();
  const size_t wanted = std::max(positives * o.negatives_per_positive, static_cast<size_t>(o.min_negatives));
  std::set<std::pair<int, int>> chosen;
  Rng rng(o.seed, Stream::kLoopPairs);
  if (n > o.min_gap) {
    for (size_t attempt = 0; chosen.size() < wanted && attempt < 50 * wanted; ++attempt) {
      const int q = rng.uniformInt(o.min_gap, n - 1);
      const int c = rng.uniformInt(0, q - o.min_gap);
      if (distance(q, c) > o.negative_distance) chosen.insert({q, c});
    }
  }
  for (const auto& [q, c] : chosen) pairs.push_back(LoopPair{q, c, false});
  std::sort(pairs.begin(), pairs.end(), [](const LoopPair& a, const LoopPair& b) {
    return a.query != b.query ? a.query < b.query : a.candidate < b.candidate;
  });
  return pairs;
}

void writeLoopPairs(const std::string& path, const std::vector<LoopPair>& pairs, io::Overwrite overwrite) {
  std::string text;
  char line[64];
  for (const LoopPair& p : pairs) {
    std::snprintf(line, sizeof(line), "%06d %06d %d\n", p.query, p.candidate, p.loop ? 1 : 0);
    text += line;
  }
  io::writeFileAtomically(path, text, overwrite);
}

}  // namespace sgtllc::sim
