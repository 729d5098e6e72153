/// @file ivf_index.h
/// @brief An inverted file over the stored retrieval keys (RetrievalMethod::kIvf, internal): FAISS k-means gives
///        the coarse centroids, every frame sits in its nearest centroid's list, and a query scans the frames of
///        its nearest lists exactly (docs/algorithm.md §5, "Retrieval at scale").
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "retrieval/scalar_codes.h"
#include "sgtllc/database.h"

namespace sgtllc::internal {

/// Indexes rows 0..size()-1 of a row-major key matrix owned elsewhere (it may grow and reallocate between calls).
/// Each list keeps its frames' keys as one-byte codes side by side (ScalarCodes), so a query reads a few
/// megabytes in order instead of gathering float keys from all over the matrix; the codes only choose which
/// frames to compare exactly: a frame found is ranked by the database's own squared distance, as the linear scan
/// ranks it.
class IvfIndex {
 public:
  /// Frames compared exactly per frame asked for (k): the codes' estimate is within a few steps of the exact
  /// distance, and the exact top-k of the scanned lists lies within their 4·k nearest estimates in all but a few
  /// queries (BENCHMARKS.md "Retrieval at scale").
  static constexpr int kRerank = 4;

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
  /// are nearest, nearest first, ties to the lower row: the kRerank·k nearest by their codes, ranked by the exact
  /// distance. Requires trained() and update() since the last restore() (update() makes the codes). Appends
  /// (row, distance²) pairs.
  void knn(const float* query, int last, int k, int probe, std::vector<std::pair<int, float>>* out) const;

  /// The index's state (for a map file) and its restoration; restore() throws std::invalid_argument if @p state
  /// does not fit the rows (list numbers out of range, more frames than rows, centroids of the wrong length).
  const IvfState& state() const { return state_; }
  void restore(IvfState state);

  /// Bytes the index holds beside the rows: centroids, each frame's list, the lists and their codes.
  size_t bytes() const;

 private:
  void train();
  int nearestList(const float* row) const;
  void rebuildLists();

  const std::vector<float>* rows_;
  int dim_;
  RetrievalConfig config_;
  int threads_;
  IvfState state_;
  void encodeLists();

  std::vector<std::vector<int32_t>> lists_;  ///< frames of each list, ascending
  ScalarCodes codes_;                        ///< trained with the centroids, on the same rows
  std::vector<std::vector<uint8_t>> list_codes_;  ///< each list's frames' codes, in the list's order
  bool coded_ = false;  ///< list_codes_ matches lists_ (made by update(), not by restore())
};

/// Whether this build of sgtllc can train an inverted file (it was built with FAISS).
bool ivfAvailable();

}  // namespace sgtllc::internal
