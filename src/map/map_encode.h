// A map file's bytes as pieces in order (internal to src/map; docs/map-format.md): most are small encoded sections,
// the keys are views of the map's own memory, so a writer streams a map of gigabytes without a copy of it.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "sgtllc/map/map.h"

namespace sgtllc::map::detail {

class EncodedMap {
 public:
  EncodedMap() = default;
  // A copy's views would point into the original's strings: moves only (a moved deque keeps its elements where
  // they are, so the views stay valid).
  EncodedMap(const EncodedMap&) = delete;
  EncodedMap& operator=(const EncodedMap&) = delete;
  EncodedMap(EncodedMap&&) = default;
  EncodedMap& operator=(EncodedMap&&) = default;

  /// The file's bytes in order; valid while this object and the map it was encoded from live.
  const std::vector<std::string_view>& pieces() const { return pieces_; }
  uint64_t size() const { return size_; }

  void add(std::string_view bytes) {
    pieces_.push_back(bytes);
    size_ += bytes.size();
  }
  /// Keeps @p bytes here (a deque: the strings never move, so their views stay valid) and adds them.
  void own(std::string bytes) {
    owned_.push_back(std::move(bytes));
    add(owned_.back());
  }
  /// Puts @p bytes first.
  void prepend(std::string bytes) {
    owned_.push_back(std::move(bytes));
    pieces_.insert(pieces_.begin(), owned_.back());
    size_ += owned_.back().size();
  }

 private:
  std::deque<std::string> owned_;
  std::vector<std::string_view> pieces_;
  uint64_t size_ = 0;
};

/// The bytes of @p map (checkFrames first: throws MapError(kInvalid) naming @p source); encodeMap() joins them.
EncodedMap encodeMapPieces(const Map& map, const std::string& source);

}  // namespace sgtllc::map::detail
