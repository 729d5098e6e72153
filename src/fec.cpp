#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"

namespace sgtllc {
namespace {

/// Points bucketed by cubic cell: members of cell c are members[start[c] .. start[c+1]) in ascending index order.
class HashGrid {
 public:
  HashGrid(const std::vector<Eigen::Vector3f>& points, double cell)
      : inv_cell_(static_cast<float>(1.0 / cell)), index_(points.size() / 2 + 16) {
    std::vector<uint32_t> cell_of(points.size());
    for (size_t i = 0; i < points.size(); ++i) cell_of[i] = index_.insert(internal::cellOf(points[i], inv_cell_));
    start_.assign(index_.size() + 1, 0);
    for (uint32_t c : cell_of) ++start_[c + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    members_.resize(points.size());
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < points.size(); ++i) members_[fill[cell_of[i]]++] = static_cast<uint32_t>(i);
  }

  /// Calls f(index) for every point in the 27 cells around @p p.
  template <typename F>
  void forEachNear(const Eigen::Vector3f& p, F&& f) const {
    const internal::Cell c = internal::cellOf(p, inv_cell_);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const uint32_t cell = index_.find(internal::offset(c, dx, dy, dz));
          if (cell == internal::KeyIndex::kMissing) continue;
          for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(members_[k]);
        }
      }
    }
  }

 private:
  float inv_cell_;
  internal::KeyIndex index_;
  std::vector<uint32_t> start_;
  std::vector<uint32_t> members_;
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];  // path halving
    x = parent[x];
  }
  return x;
}

}  // namespace

std::vector<std::vector<uint32_t>> fastEuclideanClustering(const std::vector<Eigen::Vector3f>& points, double radius,
                                                          int max_neighbors, int min_size) {
  if (!(radius > 0.0)) throw std::invalid_argument("fastEuclideanClustering: radius must be positive");
  if (max_neighbors < 1) throw std::invalid_argument("fastEuclideanClustering: max_neighbors must be >= 1");
  const size_t n = points.size();
  const HashGrid grid(points, radius);
  const float r2 = static_cast<float>(radius * radius);

  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<uint8_t> reached(n, 0);
  std::vector<std::pair<float, uint32_t>> near;
  for (uint32_t seed = 0; seed < n; ++seed) {
    if (reached[seed]) continue;  // only points no earlier seed reached become seeds (spec §2)
    const Eigen::Vector3f& p = points[seed];
    near.clear();
    grid.forEachNear(p, [&](uint32_t q) {
      const float d2 = (points[q] - p).squaredNorm();
      if (d2 <= r2) near.emplace_back(d2, q);
    });
    if (near.size() > static_cast<size_t>(max_neighbors)) {
      // The radius query returns at most max_neighbors nearest points; ties go to the lower index.
      std::nth_element(near.begin(), near.begin() + (max_neighbors - 1), near.end());
      near.resize(max_neighbors);
    }
    for (const auto& [d2, q] : near) {
      reached[q] = 1;
      const uint32_t a = findRoot(parent, seed);
      const uint32_t b = findRoot(parent, q);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }

  // Roots are the smallest index of each component, so scanning in index order yields clusters in first-seed order.
  std::vector<uint32_t> cluster_of_root(n, UINT32_MAX);
  std::vector<std::vector<uint32_t>> clusters;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t root = findRoot(parent, i);
    if (cluster_of_root[root] == UINT32_MAX) {
      cluster_of_root[root] = static_cast<uint32_t>(clusters.size());
      clusters.emplace_back();
    }
    clusters[cluster_of_root[root]].push_back(i);
  }
  clusters.erase(std::remove_if(clusters.begin(), clusters.end(),
                                [min_size](const auto& c) { return static_cast<int>(c.size()) < min_size; }),
                 clusters.end());
  return clusters;
}

}  // namespace sgtllc
