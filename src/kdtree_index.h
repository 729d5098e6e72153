/// @file kdtree_index.h
/// @brief The project's one nanoflann wrapper (with sgtllc/point_kdtree.h, which kdtree_index.cpp implements too):
///        an exact, growing kd-tree over rows of a float matrix (internal).
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
  /// Bytes the tree holds beside the rows: its nodes (nanoflann's pools) and index arrays.
  size_t bytes() const;

 private:
  struct Tree;
  int indexed_ = 0;
  std::unique_ptr<Tree> tree_;
};

}  // namespace sgtllc::internal
