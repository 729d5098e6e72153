// Private helpers shared by the sgtllc_io readers and writers: opening and reading files (public in
// sgtllc/io/input_file.h, named here too), line and token splitting, and locale-independent number conversion.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "sgtllc/io/input_file.h"
#include "sgtllc/types.h"

namespace sgtllc::io::detail {

using io::FilePtr;
using io::gibText;
using io::loadableBytes;
using io::openForReading;
using io::readWholeFile;

// The binary formats (KITTI .bin/.label, PCD binary) are little-endian; big-endian hosts swap after reading and
// before writing.
inline constexpr bool kHostLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

/// Converts 4-byte words between host and little-endian order (nothing to do on little-endian hosts).
template <typename T>
void swapWordsIfBigEndian(std::vector<T>& words) {
  static_assert(sizeof(T) == 4);
  if constexpr (!kHostLittleEndian) {
    for (T& w : words) {
      uint32_t u;
      std::memcpy(&u, &w, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&w, &u, 4);
    }
  }
}

/// Throws `cannot write PATH: node I has label L, not a stable class index 0..C−1` (C = @p num_classes) for the
/// first node whose label is not a stable class index. Writers call it before creating the file.
void checkNodeLabels(const std::string& path, const std::vector<Node>& nodes, int num_classes);

/// Next line of @p text starting at @p pos (without its '\n'); advances @p pos past the newline.
std::string_view nextLine(std::string_view text, size_t& pos);

/// Splits a line on blanks (space, tab); also drops the '\r' of CRLF files.
std::vector<std::string_view> splitBlanks(std::string_view line);

/// Parses a whole token as a double, independently of the C locale (strtod follows the process locale's decimal
/// point). A leading '+' is accepted; "nan" and "inf" parse, so callers that need finite values check.
bool parseReal(std::string_view token, double& value);

/// Parses a whole token as an integer of type @p Int (decimal, no sign for unsigned types, no leading '+').
template <typename Int>
bool parseInteger(std::string_view token, Int& value) {
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

/// Converts a stored label (PCD, PLY) to the raw uint32 id. Floats are rounded to the nearest integer. Negative
/// values wrap (−1 → 0xFFFFFFFF, as a C cast would), so a "−1 = unlabelled" convention never matches a stable class.
/// Non-finite values and values outside [−2³¹, 2³²) give nullopt.
std::optional<uint32_t> labelFromReal(double value);

/// Appends the shortest text that reads back to exactly @p value (std::to_chars).
void appendShortest(std::string& out, float value);
void appendShortest(std::string& out, double value);

}  // namespace sgtllc::io::detail
