// Little-endian words in and out of a map file's bytes (internal to src/map; docs/map-format.md).
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "sgtllc/map/map.h"

namespace sgtllc::map::detail {

template <typename T>
void put(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

inline void putText(std::string& out, const std::string& text) {
  put<uint32_t>(out, static_cast<uint32_t>(text.size()));
  out += text;
}

/// Reads values from bytes whose checksum passed; an overrun or a bad value is still reported, never trusted.
class Reader {
 public:
  Reader(std::string_view bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}

  template <typename T>
  T get() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  std::string text() {
    const uint32_t size = get<uint32_t>();
    need(size);
    std::string s(bytes_.substr(pos_, size));
    pos_ += size;
    return s;
  }
  /// A count of items of at least @p item_bytes each: at most what the remaining bytes can hold (so no huge
  /// allocation follows a bad count).
  uint64_t count(size_t item_bytes) {
    const uint64_t n = get<uint64_t>();
    if (n > remaining() / item_bytes) fail("a count of " + std::to_string(n) + " does not fit in the section");
    return n;
  }
  size_t remaining() const { return bytes_.size() - pos_; }
  void end() const {
    if (remaining() != 0) fail(std::to_string(remaining()) + " bytes left over");
  }
  [[noreturn]] void fail(const std::string& why) const { throw MapError(MapProblem::kCorrupted, what_ + why); }

 private:
  void need(size_t n) const {
    if (n > remaining()) fail("ends early");
  }
  std::string_view bytes_;
  size_t pos_ = 0;
  std::string what_;
};

}  // namespace sgtllc::map::detail
