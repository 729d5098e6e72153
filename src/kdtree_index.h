/// @file kdtree_index.h
/// @brief The project's one nanoflann wrapper: an exact, growing kd-tree over rows of a float matrix (internal).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace sgtllc::internal {

/// Indexes rows 0..size()-1 of a row-major matrix owned elsewhere (it may grow and reallocate between calls).
class KdTreeIndex {
 public:
  /// @p rows is read through this pointer at every call; it must outlive the index.
  KdTreeIndex(const std::vector<float>* rows, int dim);
  ~KdTreeIndex();

  /// Adds rows size()..last to the tree.
  void extendTo(int last);
  /// Rows in the tree.
  int size() const { return indexed_; }
  /// The k nearest rows (squared L2), nearest first, ties to the lower index. Appends (index, distance²) pairs.
  void knn(const float* query, int k, std::vector<std::pair<int, float>>* out) const;

 private:
  struct Tree;
  int indexed_ = 0;
  std::unique_ptr<Tree> tree_;
};

/// A static kd-tree over 3-D points (fine registration): built once, then nearest and k-nearest queries with no
/// tie rule (among points at exactly equal distance the tree's visiting order decides, a function of the points).
class PointKdTree {
 public:
  /// @p xyz holds x, y, z of each point in turn; it must outlive the tree.
  explicit PointKdTree(const std::vector<float>* xyz);
  ~PointKdTree();
  /// The nearest point and its squared distance, or (−1, +inf) for an empty tree.
  std::pair<int, float> nearest(const float* query) const;
  /// Indices of the (at most) @p k nearest points, nearest first.
  void knn(const float* query, int k, std::vector<uint32_t>* out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace sgtllc::internal
