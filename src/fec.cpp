#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <optional>
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

  /// The occupied cells among the 27 around @p p; returns their number.
  int nearCells(const Eigen::Vector3f& p, uint32_t cells[27]) const {
    const internal::Cell c = internal::cellOf(p, inv_cell_);
    int count = 0;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const uint32_t cell = index_.find(internal::offset(c, dx, dy, dz));
          if (cell != internal::KeyIndex::kMissing) cells[count++] = cell;
        }
      }
    }
    return count;
  }

  /// Points in a cell.
  uint32_t cellSize(uint32_t cell) const { return start_[cell + 1] - start_[cell]; }

  /// Calls f(index) for every point of @p cell.
  template <typename F>
  void forEachIn(uint32_t cell, F&& f) const {
    for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(members_[k]);
  }

  /// The cell of a point.
  internal::Cell cellOf(const Eigen::Vector3f& p) const { return internal::cellOf(p, inv_cell_); }

  /// Calls f(index) for every point in the cells whose coordinates differ from cell @p c by exactly @p ring in
  /// their largest component (ring 0: c itself).
  template <typename F>
  void forEachInRing(const internal::Cell& c, int ring, F&& f) const {
    for (int dz = -ring; dz <= ring; ++dz) {
      for (int dy = -ring; dy <= ring; ++dy) {
        const bool face = std::abs(dz) == ring || std::abs(dy) == ring;  // always true at ring 0
        for (int dx = -ring; dx <= ring; dx += face ? 1 : 2 * ring) {
          const uint32_t cell = index_.find(internal::offset(c, dx, dy, dz));
          if (cell != internal::KeyIndex::kMissing) forEachIn(cell, f);
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
  const size_t cap = static_cast<size_t>(max_neighbors);

  // Dense neighbourhoods: classes clustered without downsampling (trunk, pole, sign; spec §2) can put thousands of
  // points within r of a seed, and every seed would scan them all to keep its nearest max_neighbors. There a finer
  // grid is searched ring by ring around the seed, and the search stops once the max_neighbors-th nearest point
  // found is closer than any point outside the rings searched can be. The kept set, and so the clusters, are
  // exactly those of the full scan (pairs are ordered by (distance², index)).
  constexpr int kFineDivisions = 16;  // fine cell = r / 16
  constexpr int kMaxFineRing = 5;     // fine rings searched before falling back to the full scan
  const size_t dense_count = std::max<size_t>(8 * cap, 256);
  const float fine_cell = static_cast<float>(radius / kFineDivisions);
  std::optional<HashGrid> fine;  // built at the first dense seed

  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<uint8_t> reached(n, 0);
  std::vector<std::pair<float, uint32_t>> near;
  for (uint32_t seed = 0; seed < n; ++seed) {
    if (reached[seed]) continue;  // only points no earlier seed reached become seeds (spec §2)
    const Eigen::Vector3f& p = points[seed];
    near.clear();
    const auto consider = [&](uint32_t q) {
      const float d2 = (points[q] - p).squaredNorm();
      if (d2 <= r2) near.emplace_back(d2, q);
    };
    uint32_t cells[27];
    const int num_cells = grid.nearCells(p, cells);
    size_t candidates = 0;
    for (int c = 0; c < num_cells; ++c) candidates += grid.cellSize(cells[c]);
    bool settled = false;
    if (candidates > dense_count) {
      if (!fine) fine.emplace(points, fine_cell);
      const float slack = 1e-3f + 1e-6f * p.cwiseAbs().maxCoeff();
      const internal::Cell fine_cell_of_p = fine->cellOf(p);
      for (int ring = 0; ring <= kMaxFineRing && !settled; ++ring) {
        fine->forEachInRing(fine_cell_of_p, ring, consider);
        if (ring == 0 || near.size() < cap) continue;
        // A point outside rings 0..ring is more than ring fine cells from p along some axis, less the float
        // rounding of cell coordinates (slack). If at least max_neighbors points found lie closer than that, the
        // nearest max_neighbors are among them.
        const float bound = static_cast<float>(ring) * fine_cell - slack;
        if (!(bound > 0.0f)) continue;
        const float bound2 = bound * bound;
        const auto inside =
            std::partition(near.begin(), near.end(), [bound2](const auto& e) { return e.first < bound2; });
        if (static_cast<size_t>(inside - near.begin()) < cap) continue;
        std::nth_element(near.begin(), near.begin() + (cap - 1), inside);
        near.resize(cap);
        settled = true;
      }
      if (!settled) near.clear();
    }
    if (!settled) {
      for (int c = 0; c < num_cells; ++c) grid.forEachIn(cells[c], consider);
    }
    if (near.size() > cap) {
      // The radius query returns at most max_neighbors nearest points; ties go to the lower index.
      std::nth_element(near.begin(), near.begin() + (cap - 1), near.end());
      near.resize(cap);
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
