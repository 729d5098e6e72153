// Range checks of Config::validate() and the settings table (config.cpp, settings.cpp): ConfigError messages of
// the form "KEY = VALUE is out of range [LO, HI]". Internal to the core library.
#pragma once

#include <charconv>
#include <cmath>
#include <string>

#include "sgtllc/config.h"

namespace sgtllc::detail {

/// Shortest text that reads back to @p v, in plain decimals unless that is long: "5", "0.0005", "1e-300", "nan".
inline std::string text(double v) {
  char buf[400];  // fixed notation of the largest double has 309 digits
  auto res = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::fixed);
  if (res.ptr - buf > 24) res = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, res.ptr);
}

inline std::string text(long long v) { return std::to_string(v); }

/// One bound of an interval: its value and whether it is included.
struct Bound {
  double value;
  bool closed = true;
};

inline std::string interval(Bound lo, Bound hi) {
  return (lo.closed ? "[" : "(") + text(lo.value) + ", " + text(hi.value) + (hi.closed ? "]" : ")");
}

inline bool inside(double v, Bound lo, Bound hi) {
  return std::isfinite(v) && (lo.closed ? v >= lo.value : v > lo.value) && (hi.closed ? v <= hi.value : v < hi.value);
}

[[noreturn]] inline void outOfRange(const std::string& key, const std::string& value, const std::string& range) {
  throw ConfigError(key, key + " = " + value + " is out of range " + range);
}

inline void checkReal(const std::string& key, double v, Bound lo, Bound hi) {
  if (!inside(v, lo, hi)) outOfRange(key, text(v), interval(lo, hi));
}

inline void checkInt(const std::string& key, int v, long long lo, long long hi) {
  if (v < lo || v > hi) outOfRange(key, text(static_cast<long long>(v)), "[" + text(lo) + ", " + text(hi) + "]");
}

// Counts of frames: far beyond any recorded sequence (KITTI 00 has 4,541 frames).
constexpr long long kMaxFrames = 1000000;

/// The labeller's rules that tie its settings together (labeller_config.cpp), and the class set it needs.
void validateLabellerRules(const LabellerConfig& labeller, const LabelConfig& labels);

}  // namespace sgtllc::detail
