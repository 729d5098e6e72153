/// @file graph.h
/// @brief Semantic graph: σ_d adjacency and second-order topology T_i[m][n] (algorithm §3).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/types.h"

namespace sgtllc {

/// Number of class-pair slots α = C·m + n per node with the paper's seven classes (algorithm §4).
inline constexpr int kNumPaperSlots = kNumPaperClasses * kNumPaperClasses;
/// Most slots a node can have (kMaxClasses²).
inline constexpr int kMaxSlots = kMaxClasses * kMaxClasses;

/// A view of one row of SlotRows: `row[α]` and range-for over its slots.
template <typename T>
struct SlotRow {
  T* first;
  int count;
  T& operator[](int a) const { return first[a]; }
  T* begin() const { return first; }
  T* end() const { return first + count; }
  int size() const { return count; }
};

/// One row of slot values per node (C² class-pair slots, or C classes), stored in one array: rows[i][α].
template <typename T>
class SlotRows {
 public:
  void assign(int rows, int slots, const T& value) {
    slots_ = slots;
    data_.assign(static_cast<size_t>(rows) * slots, value);
  }
  SlotRow<T> operator[](int i) { return {data_.data() + static_cast<size_t>(i) * slots_, slots_}; }
  SlotRow<const T> operator[](int i) const { return {data_.data() + static_cast<size_t>(i) * slots_, slots_}; }
  int slots() const { return slots_; }

 private:
  std::vector<T> data_;
  int slots_ = 0;
};

/// The longest two-step path i→j→k for one class pair, or j = k = −1 if there is none.
struct TwoStepPath {
  int j = -1;
  int k = -1;
  bool exists() const { return j >= 0; }
};

/// Nodes with their adjacency and, per node and class pair, the longest two-step path.
struct SemanticGraph {
  int num_classes = kNumPaperClasses;  ///< C: node labels lie in 0..C−1
  std::vector<Node> nodes;
  Eigen::MatrixXd distance;          ///< N×N centre distances (m)
  std::vector<uint8_t> adjacency;    ///< N×N row-major, 1 iff p ≠ q and distance < σ_d
  std::vector<uint8_t> isolated;     ///< 1 iff the node has no neighbour (no descriptor content, algorithm §3)
  SlotRows<TwoStepPath> paths;       ///< paths[i][C·m + n] = T_i[m][n]

  int size() const { return static_cast<int>(nodes.size()); }
  int numSlots() const { return num_classes * num_classes; }
  bool adjacent(int p, int q) const { return adjacency[static_cast<size_t>(p) * nodes.size() + q] != 0; }
  /// Undirected edges (p < q), in row-major order.
  std::vector<std::pair<int, int>> edges() const;
};

/// Throws sgtllc::Error "WHAT has N nodes, more than graph.max_nodes = M …" if @p count > config.max_nodes: the
/// graph is dense, so a frame of 10,000 nodes would take ~1 GB and most of a minute (GraphConfig::max_nodes).
/// Readers of node files call it with the file name as @p what.
void checkNodeCount(size_t count, const GraphConfig& config, const std::string& what = "the frame");

/// Builds the graph of @p nodes over @p num_classes classes C (LabelConfig::numClasses(); the paper's seven by
/// default) (algorithm §3): A[p][q] = 1 iff ‖c_p − c_q‖ < σ_d; for every node i and class pair (m, n) the path
/// i→j→k with l_j = m, l_k = n maximising d_ij + d_jk, ties to the lowest j then the lowest k, with k ≠ i unless
/// allow_k_equals_i. O(N² · C). Throws sgtllc::Error for more than config.max_nodes nodes (checkNodeCount), a
/// label outside 0..C−1, a non-finite centre, or C outside 1..kMaxClasses.
SemanticGraph buildGraph(std::vector<Node> nodes, const GraphConfig& config, int num_classes = kNumPaperClasses);

}  // namespace sgtllc
