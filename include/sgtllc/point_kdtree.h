/// @file point_kdtree.h
/// @brief A static kd-tree over 3-D points: the nearest-point search of fine registration and of the map's frame
///        positions (nanoflann behind it, not in this header).
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace sgtllc {

/// Built once, then nearest and k-nearest queries with no tie rule (among points at exactly equal distance the
/// tree's visiting order decides, a function of the points).
class PointKdTree {
 public:
  /// @p xyz holds x, y, z of each point in turn; it must outlive the tree.
  explicit PointKdTree(const std::vector<float>* xyz);
  ~PointKdTree();
  PointKdTree(const PointKdTree&) = delete;
  PointKdTree& operator=(const PointKdTree&) = delete;
  /// The nearest point and its squared distance, or (−1, +inf) for an empty tree.
  std::pair<int, float> nearest(const float* query) const;
  /// The nearest point if its squared distance is at most @p max_d2 (as a double, the comparison registration
  /// makes), else (−1, +inf). The same point as nearest() whenever that one is this close, found without searching
  /// the tree beyond the bound: the far query points, which pair with nothing, cost the most otherwise.
  std::pair<int, float> nearestWithin(const float* query, double max_d2) const;
  /// Indices of the (at most) @p k nearest points, nearest first.
  void knn(const float* query, int k, std::vector<uint32_t>* out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace sgtllc
