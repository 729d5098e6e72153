/// @file ivf_index.h
/// @brief An inverted file over the stored retrieval keys (RetrievalMethod::kIvf, internal): FAISS k-means gives
///        the coarse centroids, every frame sits in its nearest centroid's list, and a query scans the frames of
///        its nearest lists exactly (docs/algorithm.md §5, "Retrieval at scale").
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sgtllc/database.h"

namespace sgtllc::internal {

/// Indexes rows 0..size()-1 of a row-major key matrix owned elsewhere (it may grow and reallocate between calls).
/// The centroids are the only approximate part: list assignment and the scan use the database's own squared
/// distance, so a frame inside a scanned list is ranked exactly as the linear scan ranks it.
class IvfIndex {
 public:
  /// @p rows is read through this pointer at every call; it must outlive the index.
  IvfIndex(const std::vector<float>* rows, int dim, const RetrievalConfig& config, int threads);

  /// Brings the index up to the matrix's current rows: trains once the matrix holds config.ivf_train_frames rows
  /// (and again at four times the rows of the last training when config.ivf_lists is 0, so lists stay short),
  /// then files every new row in its nearest list. A pure function of the rows, at any thread count.
  void update();
  bool trained() const { return !state_.centroids.empty(); }
  /// Rows filed in lists.
  int size() const { return static_cast<int>(state_.list_of_frame.size()); }

  /// The k rows among 0..last nearest to @p query (squared L2) among those in the @p probe lists whose centroids
  /// are nearest, nearest first, ties to the lower row. Requires trained(). Appends (row, distance²) pairs.
  void knn(const float* query, int last, int k, int probe, std::vector<std::pair<int, float>>* out) const;

  /// The index's state (for a map file) and its restoration; restore() throws std::invalid_argument if @p state
  /// does not fit the rows (list numbers out of range, more frames than rows, centroids of the wrong length).
  const IvfState& state() const { return state_; }
  void restore(IvfState state);

 private:
  void train();
  int nearestList(const float* row) const;
  void rebuildLists();

  const std::vector<float>* rows_;
  int dim_;
  RetrievalConfig config_;
  int threads_;
  IvfState state_;
  std::vector<std::vector<int32_t>> lists_;  ///< frames of each list, ascending
};

/// Whether this build of sgtllc can train an inverted file (it was built with FAISS).
bool ivfAvailable();

}  // namespace sgtllc::internal
