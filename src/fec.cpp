#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

#include "internal/fec_search.h"
#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"

namespace sgtllc {
namespace {

/// Points bucketed by cubic cell: members of cell c are members[start[c] .. start[c+1]) in ascending index order.
/// A copy of the points is kept in the same order, so a neighbour search reads each cell's points contiguously.
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
    sorted_.resize(points.size());
    for (size_t k = 0; k < members_.size(); ++k) sorted_[k] = points[members_[k]];
  }

  /// The block of cells that holds every point within @p half cells of @p p along each axis (half = 0.5 for cells
  /// of 2r), widened by the float rounding of cell coordinates (2⁻²⁴ relative per operation): 2 cells per axis, 3
  /// when p lies near a cell's middle plane. The widening stays below half a cell so a block never exceeds 3 × 3 × 3.
  struct Block {
    internal::Cell lo, hi;
    bool operator==(const Block& o) const { return lo == o.lo && hi == o.hi; }
  };
  Block blockAround(const Eigen::Vector3f& p, float half) const {
    const Eigen::Array3f t = p.array() * inv_cell_;
    const float reach = std::min(0.999f, half + 1e-4f + 1e-6f * t.abs().maxCoeff());
    using internal::floorCell;
    return Block{internal::Cell{floorCell(t.x() - reach), floorCell(t.y() - reach), floorCell(t.z() - reach)},
                 internal::Cell{floorCell(t.x() + reach), floorCell(t.y() + reach), floorCell(t.z() + reach)}};
  }

  /// The occupied cells of a block of at most 3 × 3 × 3; returns their number.
  int cellsIn(const Block& b, uint32_t cells[27]) const {
    int count = 0;
    for (int32_t z = b.lo.z; z <= b.hi.z; ++z) {
      for (int32_t y = b.lo.y; y <= b.hi.y; ++y) {
        for (int32_t x = b.lo.x; x <= b.hi.x; ++x) {
          const uint32_t cell = index_.find(internal::Cell{x, y, z});
          if (cell != internal::KeyIndex::kMissing) cells[count++] = cell;
        }
      }
    }
    return count;
  }

  /// Points in a cell.
  uint32_t cellSize(uint32_t cell) const { return start_[cell + 1] - start_[cell]; }

  /// Calls f(index, point) for every point of @p cell.
  template <typename F>
  void forEachIn(uint32_t cell, F&& f) const {
    for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(members_[k], sorted_[k]);
  }

  /// The cell of a point.
  internal::Cell cellOf(const Eigen::Vector3f& p) const { return internal::cellOf(p, inv_cell_); }

  /// Calls f(index, point) for every point in the cells whose coordinates differ from cell @p c by exactly @p ring in
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
  std::vector<Eigen::Vector3f> sorted_;  // points[members_[k]]
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
  const size_t cap = max_neighbors > 0 ? static_cast<size_t>(max_neighbors) : 1;
  return internal::fastEuclideanClustering(points, radius, max_neighbors, min_size,
                                           std::max<size_t>(8 * cap, internal::kDenseCandidates));
}

namespace internal {

std::vector<std::vector<uint32_t>> fastEuclideanClustering(const std::vector<Eigen::Vector3f>& points, double radius,
                                                          int max_neighbors, int min_size, size_t dense_candidates) {
  if (!(radius > 0.0)) throw std::invalid_argument("fastEuclideanClustering: radius must be positive");
  if (max_neighbors < 1) throw std::invalid_argument("fastEuclideanClustering: max_neighbors must be >= 1");
  const size_t n = points.size();
  // Cells of 2r: a ball of radius r spans 2 of them per axis, so a query probes 8 cells instead of the 27 of
  // r-cells, over about the same points on the surfaces that LiDAR samples. Which cells are probed does not change
  // the neighbours found, only how fast (every point within r lies in them).
  const HashGrid grid(points, 2.0 * radius);
  const float r2 = static_cast<float>(radius * radius);
  const size_t cap = static_cast<size_t>(max_neighbors);

  // Dense neighbourhoods: classes clustered without downsampling (trunk, pole, sign; algorithm §2) can put thousands of
  // points within r of a seed, and every seed would scan them all to keep its nearest max_neighbors. Above
  // dense_candidates (kDenseCandidates, fec_search.h) a finer grid is searched ring by ring around the seed, and the
  // search stops once the max_neighbors-th nearest point found is closer than any point outside the rings searched
  // can be. The kept set, and so the clusters, are exactly those of the full scan (pairs are ordered by (distance²,
  // index)).
  constexpr int kFineDivisions = 16;  // fine cell = r / 16
  constexpr int kMaxFineRing = 5;     // fine rings searched before falling back to the full scan
  const float fine_cell = static_cast<float>(radius / kFineDivisions);
  std::optional<HashGrid> fine;  // built at the first dense seed

  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<uint8_t> reached(n, 0);
  std::vector<std::pair<float, uint32_t>> near;
  // The full scan of a block writes every candidate here and advances past those within r: no branch on the
  // distance, which a LiDAR surface makes unpredictable. Grows to the largest block and is never shrunk.
  std::vector<std::pair<float, uint32_t>> scanned;
  // Consecutive seeds often share a block (points come in scan order): its cells are looked up once.
  uint32_t cells[27];
  int num_cells = 0;
  HashGrid::Block seed_block{};
  size_t candidates = 0;
  bool have_cells = false;
  bool rings_failed = false;  // a seed of this block searched the fine rings without settling
  for (uint32_t seed = 0; seed < n; ++seed) {
    if (reached[seed]) continue;  // only points no earlier seed reached become seeds (algorithm §2)
    const Eigen::Vector3f& p = points[seed];
    near.clear();
    const auto consider = [&](uint32_t q, const Eigen::Vector3f& point) {
      const float d2 = (point - p).squaredNorm();
      if (d2 <= r2) near.emplace_back(d2, q);
    };
    const HashGrid::Block block = grid.blockAround(p, 0.5f);
    if (!have_cells || !(block == seed_block)) {
      seed_block = block;
      have_cells = true;
      num_cells = grid.cellsIn(block, cells);
      rings_failed = false;
      candidates = 0;
      for (int c = 0; c < num_cells; ++c) candidates += grid.cellSize(cells[c]);
    }
    bool settled = false;
    // Seeds of one block share its density: once the rings fail to settle there (a sparse trunk: the nearest
    // max_neighbors reach beyond them), the next seeds of the block go straight to the full scan.
    if (candidates > dense_candidates && !rings_failed) {
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
      if (!settled) {
        near.clear();
        rings_failed = true;
      }
    }
    if (!settled) {
      if (scanned.size() < candidates) scanned.resize(candidates);
      std::pair<float, uint32_t>* out = scanned.data();
      size_t count = 0;
      for (int c = 0; c < num_cells; ++c) {
        grid.forEachIn(cells[c], [&](uint32_t q, const Eigen::Vector3f& point) {
          const float d2 = (point - p).squaredNorm();
          out[count] = {d2, q};
          count += d2 <= r2 ? 1 : 0;
        });
      }
      near.assign(out, out + count);
    }
    if (near.size() > cap) {
      // The radius query returns at most max_neighbors nearest points; ties go to the lower index.
      std::nth_element(near.begin(), near.begin() + (cap - 1), near.end());
      near.resize(cap);
    }
    // The seed's root is tracked across the unions instead of looked up per neighbour; every root stays the
    // smallest index of its component either way, and only the components are read below.
    uint32_t a = findRoot(parent, seed);
    for (const auto& [d2, q] : near) {
      reached[q] = 1;
      const uint32_t b = findRoot(parent, q);
      if (a != b) {
        parent[std::max(a, b)] = std::min(a, b);
        a = std::min(a, b);
      }
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

}  // namespace internal
}  // namespace sgtllc
