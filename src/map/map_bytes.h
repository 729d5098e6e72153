// Little-endian words in and out of a map file's bytes (internal to src/map; docs/map-format.md). Reading streams:
// a section is parsed from a small buffer refilled from its source (a file or memory) while its crc32 is computed,
// so loading a map never holds its bytes and its decoded contents at once.
#pragma once

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sgtllc/map/map.h"

namespace sgtllc::map::detail {

inline constexpr std::string_view kMagic("SGTLLMAP", 8);
inline constexpr size_t kHeaderBytes = 40;       // magic, version, sections, file bytes, fingerprint, flags, crc
inline constexpr size_t kSectionHeadBytes = 16;  // tag, section version, payload bytes
inline constexpr uint32_t kSectionVersion = 1;   // of every section this version writes

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

/// zlib's crc32 of @p bytes, continuing from @p crc (a fresh one by default).
inline uint32_t crc32Of(std::string_view bytes, uint32_t crc = 0) {
  return static_cast<uint32_t>(crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

/// The bytes of a map, in order: a file (map_file.cpp) or memory.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  /// Copies up to @p n next bytes to @p out; fewer only at the end. Throws sgtllc::Error on a read error.
  virtual size_t read(char* out, size_t n) = 0;
  /// How many bytes there are in all (a file's size when it was opened).
  virtual uint64_t size() const = 0;
};

class MemorySource final : public ByteSource {
 public:
  explicit MemorySource(std::string_view bytes) : bytes_(bytes) {}
  size_t read(char* out, size_t n) override {
    n = std::min(n, bytes_.size() - pos_);
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
    return n;
  }
  uint64_t size() const override { return bytes_.size(); }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
};

/// Reads values from the next `bytes` of a source, computing their crc32 on the way; an overrun or a bad value is
/// reported (MapError kCorrupted, message prefixed by `what`), never trusted.
class Reader {
 public:
  Reader(ByteSource& source, uint64_t bytes, std::string what, uint32_t crc = 0)
      : source_(&source), unread_(bytes), what_(std::move(what)), crc_(crc),
        buffer_(static_cast<size_t>(std::min<uint64_t>(bytes, kBufferBytes)) + sizeof(uint64_t)) {}

  template <typename T>
  T get() {
    if (end_ - pos_ < sizeof(T)) refill(sizeof(T));
    T value;
    std::memcpy(&value, buffer_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  std::string text() {
    const uint32_t size = get<uint32_t>();
    if (size > remaining()) fail("ends early");
    std::string s;
    s.reserve(size);
    while (s.size() < size) {
      if (pos_ == end_) refill(1);
      const size_t n = std::min<size_t>(end_ - pos_, size - s.size());
      s.append(buffer_.data() + pos_, n);
      pos_ += n;
    }
    return s;
  }
  /// A count of items of at least @p item_bytes each: at most what the remaining bytes can hold (so no huge
  /// allocation follows a bad count).
  uint64_t count(size_t item_bytes) {
    const uint64_t n = get<uint64_t>();
    if (n > remaining() / item_bytes) fail("a count of " + std::to_string(n) + " does not fit in the section");
    return n;
  }
  uint64_t remaining() const { return unread_ + (end_ - pos_); }
  void end() const {
    if (remaining() != 0) fail(std::to_string(remaining()) + " bytes left over");
  }
  /// Skips what is left; returns the crc32 of all the bytes this reader covered.
  uint32_t drain() {
    pos_ = end_;
    while (unread_ > 0) refill(0);
    pos_ = end_;
    return crc_;
  }
  [[noreturn]] void fail(const std::string& why) const { throw MapError(MapProblem::kCorrupted, what_ + why); }

 private:
  static constexpr uint64_t kBufferBytes = 1 << 16;

  /// Keeps the unread buffered bytes and reads more behind them, so that at least @p need are buffered.
  void refill(size_t need) {
    if (need > remaining()) fail("ends early");
    const size_t kept = end_ - pos_;
    std::memmove(buffer_.data(), buffer_.data() + pos_, kept);
    pos_ = 0;
    end_ = kept;
    const size_t want = static_cast<size_t>(std::min<uint64_t>(unread_, buffer_.size() - kept));
    const size_t got = source_->read(buffer_.data() + kept, want);
    crc_ = crc32Of(std::string_view(buffer_.data() + kept, got), crc_);
    unread_ -= got;
    end_ += got;
    if (got < want) {
      unread_ = 0;  // the source ended before the declared bytes did
      if (need > end_) fail("ends early");
    }
  }

  ByteSource* source_;
  uint64_t unread_;  ///< bytes of this reader still in the source
  std::string what_;
  uint32_t crc_;
  std::vector<char> buffer_;
  size_t pos_ = 0, end_ = 0;
};

}  // namespace sgtllc::map::detail
