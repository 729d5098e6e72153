#include "internal/described_cache.h"

#include <utility>

namespace sgtllc::internal {

std::shared_ptr<const DescribedFrame> DescribedCache::find(int index) {
  const auto it = entries_.find(index);
  if (it == entries_.end()) return nullptr;
  it->second.last_use = ++clock_;
  return it->second.frame;
}

void DescribedCache::insert(int index, std::shared_ptr<const DescribedFrame> frame) {
  if (capacity_ == 0) return;
  if (entries_.size() >= capacity_ && entries_.count(index) == 0) {
    // A linear scan for the oldest use: capacity is a few hundred and at most K frames are inserted per query.
    auto oldest = entries_.begin();
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (it->second.last_use < oldest->second.last_use) oldest = it;
    }
    entries_.erase(oldest);
  }
  entries_[index] = Entry{std::move(frame), ++clock_};
}

}  // namespace sgtllc::internal
