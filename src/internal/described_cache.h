/// @file described_cache.h
/// @brief A bounded store of stored frames' descriptions for verification (internal).
///
/// Verification needs each candidate's graph and local descriptors (describeFrame), which the database does not
/// keep (database.h: ~2 KB of nodes per frame instead of ~25 KB). Consecutive queries retrieve largely the same
/// frames, so re-describing all K candidates per query mostly repeats work: this keeps the
/// descriptions of the most recently verified frames. describeFrame is a pure function of the nodes and the
/// configuration, so a cached description is the one a fresh describeFrame would give and results do not change.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "sgtllc/frame.h"

namespace sgtllc::internal {

class DescribedCache {
 public:
  /// Keeps at most @p capacity frames (0 keeps none).
  explicit DescribedCache(size_t capacity) : capacity_(capacity) {}

  /// Frame @p index's description, or nullptr if it is not held. Counts as a use.
  std::shared_ptr<const DescribedFrame> find(int index);
  /// Stores frame @p index's description, dropping the least recently used frame when full.
  void insert(int index, std::shared_ptr<const DescribedFrame> frame);

  size_t size() const { return entries_.size(); }
  size_t capacity() const { return capacity_; }

 private:
  struct Entry {
    std::shared_ptr<const DescribedFrame> frame;
    uint64_t last_use = 0;
  };
  size_t capacity_;
  uint64_t clock_ = 0;
  std::unordered_map<int, Entry> entries_;
};

}  // namespace sgtllc::internal
