#include "kdtree_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nanoflann.hpp>

#include "sgtllc/point_kdtree.h"

namespace sgtllc::internal {
namespace {

/// nanoflann dataset concept over the external row-major matrix.
struct RowsAdaptor {
  const std::vector<float>* rows;
  int dim;
  int count;
  size_t kdtree_get_point_count() const { return static_cast<size_t>(count); }
  float kdtree_get_pt(uint32_t idx, size_t d) const { return (*rows)[static_cast<size_t>(idx) * dim + d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

}  // namespace

struct KdTreeIndex::Tree {
  using Index = nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<float, RowsAdaptor>,
                                                           RowsAdaptor, -1, uint32_t>;
  RowsAdaptor adaptor;
  Index index;
  Tree(const std::vector<float>* rows, int dim)
      : adaptor{rows, dim, 0}, index(dim, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
};

KdTreeIndex::KdTreeIndex(const std::vector<float>* rows, int dim)
    : tree_(std::make_unique<Tree>(rows, dim)) {}

KdTreeIndex::~KdTreeIndex() = default;

void KdTreeIndex::extendTo(int last) {
  if (last < indexed_) return;
  tree_->adaptor.count = last + 1;
  tree_->index.addPoints(static_cast<uint32_t>(indexed_), static_cast<uint32_t>(last));
  indexed_ = last + 1;
}

size_t KdTreeIndex::bytes() const {
  // The adaptor's per-row tree numbers (one int a row) are private to nanoflann: counted at their size.
  size_t bytes = sizeof(Tree) + static_cast<size_t>(indexed_) * sizeof(int);
  for (const auto& sub : tree_->index.getAllIndices()) {
    bytes += sizeof(sub) + sub.pool.usedMemory + sub.pool.wastedMemory + sub.vAcc.capacity() * sizeof(uint32_t);
  }
  return bytes;
}

void KdTreeIndex::knn(const float* query, int k, std::vector<std::pair<int, float>>* out) const {
  const size_t want = std::min<size_t>(static_cast<size_t>(k), static_cast<size_t>(indexed_));
  if (want == 0) return;
  std::vector<uint32_t> idx(want);
  std::vector<float> d2(want);
  nanoflann::KNNResultSet<float, uint32_t> result(want);
  result.init(idx.data(), d2.data());
  tree_->index.findNeighbors(result, query, nanoflann::SearchParams());
  // nanoflann admits a point only if it is strictly closer than the current k-th, so among points tied with the
  // k-th distance it keeps whichever it met first. Collect every point up to that distance (inclusive) and keep
  // the k best by (distance, index), as the linear scan does; frames without nodes tie at the zero descriptor.
  const float worst = d2[result.size() - 1];
  std::vector<std::pair<uint32_t, float>> within;
  nanoflann::RadiusResultSet<float, uint32_t> ball(std::nextafter(worst, std::numeric_limits<float>::infinity()),
                                                   within);
  tree_->index.findNeighbors(ball, query, nanoflann::SearchParams());
  std::sort(within.begin(), within.end(), [](const auto& a, const auto& b) {
    return a.second < b.second || (a.second == b.second && a.first < b.first);
  });
  within.resize(std::min(within.size(), want));
  for (const auto& [i, d] : within) out->emplace_back(static_cast<int>(i), d);
}

}  // namespace sgtllc::internal

namespace sgtllc {

struct PointKdTree::Tree {
  using RowsAdaptor = internal::RowsAdaptor;
  using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, RowsAdaptor>, RowsAdaptor, 3,
                                                    uint32_t>;
  RowsAdaptor adaptor;
  Index index;
  explicit Tree(const std::vector<float>* xyz)
      : adaptor{xyz, 3, static_cast<int>(xyz->size() / 3)},
        index(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    index.buildIndex();
  }
};

PointKdTree::PointKdTree(const std::vector<float>* xyz) : tree_(std::make_unique<Tree>(xyz)) {}

PointKdTree::~PointKdTree() = default;

namespace {

/// One nearest point, admitted only below a bound from the start: nanoflann prunes every branch farther than
/// worstDist(), so the search never leaves the bound's ball. Points are admitted, and ties decided, as by a
/// KNNResultSet of one (strictly closer than the best so far, visiting order), so the point found is nearest()'s.
class BoundedNearest {
 public:
  explicit BoundedNearest(float bound) : dist_(bound) {}
  bool full() const { return true; }
  bool addPoint(float dist, uint32_t index) {
    if (dist < dist_) {
      dist_ = dist;
      index_ = static_cast<int>(index);
    }
    return true;
  }
  float worstDist() const { return dist_; }
  int index() const { return index_; }

 private:
  float dist_;
  int index_ = -1;
};

}  // namespace

std::pair<int, float> PointKdTree::nearestWithin(const float* query, double max_d2) const {
  if (tree_->adaptor.count == 0 || !(max_d2 >= 0.0)) return {-1, std::numeric_limits<float>::infinity()};
  // The smallest float above every float d with double(d) <= max_d2: "d < bound" is then "double(d) <= max_d2"
  // (beyond the largest float, every distance is within: the bound is +inf, and no cast out of range happens).
  constexpr float kInf = std::numeric_limits<float>::infinity();
  float bound = kInf;
  if (max_d2 < static_cast<double>(std::numeric_limits<float>::max())) {
    float largest = static_cast<float>(max_d2);
    if (static_cast<double>(largest) > max_d2) largest = std::nextafter(largest, 0.0f);
    bound = std::nextafter(largest, kInf);
  }
  BoundedNearest result(bound);
  tree_->index.findNeighbors(result, query, nanoflann::SearchParams());
  if (result.index() < 0) return {-1, std::numeric_limits<float>::infinity()};
  return {result.index(), result.worstDist()};
}

std::pair<int, float> PointKdTree::nearest(const float* query) const {
  if (tree_->adaptor.count == 0) return {-1, std::numeric_limits<float>::infinity()};
  uint32_t idx = 0;
  float d2 = 0.0f;
  nanoflann::KNNResultSet<float, uint32_t> result(1);
  result.init(&idx, &d2);
  tree_->index.findNeighbors(result, query, nanoflann::SearchParams());
  return {static_cast<int>(idx), d2};
}

void PointKdTree::knn(const float* query, int k, std::vector<uint32_t>* out) const {
  const size_t want = std::min<size_t>(static_cast<size_t>(k), static_cast<size_t>(tree_->adaptor.count));
  out->assign(want, 0);
  std::vector<float> d2(want);
  if (want == 0) return;
  nanoflann::KNNResultSet<float, uint32_t> result(want);
  result.init(out->data(), d2.data());
  tree_->index.findNeighbors(result, query, nanoflann::SearchParams());
  out->resize(result.size());
}

}  // namespace sgtllc
