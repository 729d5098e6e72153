/// @file database.h
/// @brief Frame store and global-descriptor retrieval (algorithm §5, §10).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/types.h"

namespace sgtllc {

/// One retrieved frame: its index and squared L2 distance between global descriptors.
struct RetrievedFrame {
  int frame = 0;
  float distance2 = 0.0f;
};

/// What the database keeps of a frame: its nodes and its global descriptor. Local descriptors are a pure function
/// of the nodes (describeFrame) and are rebuilt for the ≤ K candidates of a query, which costs microseconds and
/// keeps the store near 2 KB per frame (G2) instead of ~20 KB (algorithm §10).
struct StoredFrame {
  std::vector<Node> nodes;
  std::vector<float> global;
};

/// The state of an inverted file (RetrievalMethod::kIvf), as a map file keeps it: list count, the frames it was
/// trained on, the centroids (lists × key length, row-major) and the list of every indexed frame.
struct IvfState {
  int lists = 0;
  int trained_frames = 0;
  std::vector<float> centroids;
  std::vector<int32_t> list_of_frame;
};

/// Frames in insertion order, numbered 0, 1, 2, …, with exact K-nearest-neighbour search over global descriptors.
class FrameDatabase {
 public:
  explicit FrameDatabase(RetrievalMethod method = RetrievalMethod::kBruteForce);
  /// Searching with @p retrieval's method (and its inverted-file parameters); @p threads files frames in lists.
  explicit FrameDatabase(const RetrievalConfig& retrieval, int threads = 1);
  ~FrameDatabase();
  FrameDatabase(FrameDatabase&&) noexcept;
  FrameDatabase& operator=(FrameDatabase&&) noexcept;

  /// A deep copy: the frames (at their exact size), the search method and its parameters, and a trained inverted
  /// file's state, so the copy answers every query as this database does (a k-d tree is rebuilt at its first query).
  FrameDatabase copy() const;

  /// Appends a frame; returns its index. Throws std::invalid_argument if the global descriptor's length differs
  /// from the first frame's.
  int add(StoredFrame frame);
  /// Fills an empty database at once: frame i has @p nodes[i] and the key @p globals[i·d, (i+1)·d), d =
  /// globals.size() / nodes.size(). The key storage is taken over, not copied or grown, so loading a map costs
  /// its keys once (docs/map-format.md, "Reading"). Throws std::invalid_argument unless the database is empty and
  /// the keys divide evenly among the frames.
  void assign(std::vector<std::vector<Node>> nodes, std::vector<float> globals);

  /// Switches the search structure and its parameters (a loaded map is searched as the configuration says);
  /// results are unchanged up to the ties RetrievalMethod::kKdTree documents and, for kIvf, the lists a query
  /// scans. A trained inverted file is kept when the new method is kIvf too (a map file carries it).
  void setSearch(const RetrievalConfig& retrieval, int threads = 1);

  int size() const;
  /// Nodes of frame @p index.
  const std::vector<Node>& nodes(int index) const;
  /// Global descriptor of frame @p index (globalDimension() floats).
  const float* global(int index) const;
  int globalDimension() const;

  /// The @p k frames among 0..last (inclusive) nearest to @p global, nearest first; ties go to the lower index.
  /// Returns fewer if fewer frames are eligible, none if last < 0. With RetrievalMethod::kKdTree the tree is
  /// extended here, and with kIvf the inverted file (trained at retrieval.ivf_train_frames frames; until then the
  /// search is the exact scan), so concurrent queries on one database are not safe (the detector queries from one
  /// thread). kIvf is approximate: a frame outside the retrieval.ivf_probe nearest lists is not found, nor, rarely,
  /// one that the one-byte codes of the keys put behind 4·k others of the scanned lists.
  std::vector<RetrievedFrame> query(const std::vector<float>& global, int last, int k) const;

  /// The inverted file's state once trained (kIvf), else nothing; restoreIvf() puts a saved one back (a map
  /// file). restoreIvf throws std::invalid_argument if the state does not fit the stored frames or the database
  /// does not search with kIvf.
  std::optional<IvfState> ivfState() const;
  void restoreIvf(IvfState state);

  /// Bytes held for frame @p index: its nodes, its global descriptor and per-frame bookkeeping.
  size_t frameBytes(int index) const;
  /// Bytes held by the search structure beside the frames: the inverted file's centroids, lists and one-byte
  /// codes (kIvf; from the first query on, its lists once trained), the k-d tree's nodes (kKdTree, from the
  /// first query on); 0 for the linear scan.
  size_t searchBytes() const;
  /// Bytes held for all frames and the search structure.
  size_t totalBytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sgtllc
