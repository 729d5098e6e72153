/// @file rng.h
/// @brief Deterministic random numbers for the simulator: seeded streams and stateless hashes.
///
/// Every random decision derives from (seed, purpose, index): a world element, a frame, a ray. No generator is ever
/// shared between threads, so the output is the same at any thread count. The distributions are implemented here
/// rather than taken from <random>, whose distributions differ between standard libraries.
///
/// Rule: one draw per statement. C++ leaves the order in which function arguments and the operands of + or * are
/// evaluated unspecified, so `Vec(rng.uniform(), rng.uniform())`, `f(rng.uniform(), drawsToo(rng))` or
/// `rng.uniform() * rng.uniform()` draw in one order under GCC and another under clang, and the same seed builds
/// another world. Draw into named locals in separate statements (separate declarators of one declaration, `&&`,
/// `?:` and braced init lists `T{a, b}` are sequenced and fine). tests/test_sim_pinned.cpp pins reference worlds.
#pragma once

#include <cstdint>

namespace sgtllc::sim {

/// What a random stream is used for; part of every stream's seed so streams never overlap.
enum class Stream : uint64_t {
  kRoads = 1,
  kBuildings,
  kVegetation,
  kStreetFurniture,
  kVehicles,
  kAgents,
  kRoute,
  kTrajectory,
  kScan,
  kLabelNoise,
  kLoopPairs,
  kGround,
  kOdometry,
};

/// SplitMix64 finaliser: a strong 64-bit mix (Steele et al.).
inline uint64_t mix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// Hash of several words, order-sensitive.
inline uint64_t hashWords(uint64_t a, uint64_t b, uint64_t c = 0, uint64_t d = 0) {
  return mix64(mix64(mix64(mix64(a) ^ b) ^ c) ^ d);
}

/// A uniform number in [0, 1) from a hash (53 bits).
inline double hashUniform(uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

/// xoshiro256** (Blackman & Vigna) seeded through SplitMix64.
class Rng {
 public:
  explicit Rng(uint64_t seed);
  /// The stream for one purpose and index (e.g. Stream::kScan, frame 17) of a run seeded with @p seed.
  Rng(uint64_t seed, Stream purpose, uint64_t index = 0);

  uint64_t next();
  /// Uniform in [0, 1).
  double uniform() { return hashUniform(next()); }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [lo, hi] (inclusive); lo ≤ hi.
  int uniformInt(int lo, int hi);
  /// True with probability p.
  bool chance(double p) { return uniform() < p; }
  /// Standard normal (Box–Muller; one value per call, no cached state).
  double normal();
  double normal(double mean, double sigma) { return mean + sigma * normal(); }

 private:
  uint64_t s_[4];
};

}  // namespace sgtllc::sim
