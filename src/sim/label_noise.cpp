#include "sgtllc/sim/label_noise.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "sgtllc/sim/rng.h"
#include "sgtllc/sim/world.h"

namespace sgtllc::sim {
namespace {

namespace id = semantic;

/// Which points of a part a confusion takes: all, those above a cut at 30–80 % of the part's visible height, or
/// those in a band of up to 1.2 m above the ground (a wall's base, the low leaves of a bush).
enum class Extent { kWhole, kTop, kBottom };
constexpr float kBottomBand = 1.2f;  // m

struct Confusion {
  uint16_t from, to;
  double probability;  ///< per part and scan at the default rate, for a part at ~20 m
  Extent extent;
};

// Per-part confusions at the default rate. Thin and small classes go wrong most, as in RangeNet++'s per-class
// IoUs (pole 48, sign 56, trunk 55, fence 59, terrain 65 vs building 87, road 92 %).
constexpr Confusion kConfusions[] = {
    {id::kTrunk, id::kVegetation, 0.10, Extent::kWhole},
    {id::kTrunk, id::kVegetation, 0.25, Extent::kTop},
    {id::kTrunk, id::kPole, 0.04, Extent::kWhole},
    {id::kPole, id::kTrafficSign, 0.06, Extent::kWhole},
    {id::kPole, id::kTrafficSign, 0.10, Extent::kTop},
    {id::kPole, id::kTrunk, 0.05, Extent::kWhole},
    {id::kPole, id::kBuilding, 0.04, Extent::kWhole},
    {id::kTrafficSign, id::kPole, 0.14, Extent::kWhole},
    {id::kTrafficSign, id::kBuilding, 0.04, Extent::kWhole},
    {id::kFence, id::kBuilding, 0.10, Extent::kWhole},
    {id::kFence, id::kVegetation, 0.08, Extent::kWhole},
    {id::kBuilding, id::kFence, 0.03, Extent::kBottom},
    {id::kBuilding, id::kOtherStructure, 0.01, Extent::kWhole},
    {id::kBuilding, id::kVegetation, 0.01, Extent::kWhole},
    {id::kVegetation, id::kTerrain, 0.06, Extent::kBottom},
    {id::kVegetation, id::kFence, 0.03, Extent::kWhole},
    {id::kVegetation, id::kBuilding, 0.02, Extent::kWhole},
    {id::kTerrain, id::kVegetation, 0.10, Extent::kWhole},
    {id::kTerrain, id::kSidewalk, 0.08, Extent::kWhole},
    {id::kSidewalk, id::kTerrain, 0.02, Extent::kWhole},
    {id::kSidewalk, id::kRoad, 0.04, Extent::kWhole},
    {id::kSidewalk, id::kParking, 0.04, Extent::kWhole},
    {id::kRoad, id::kParking, 0.03, Extent::kWhole},
    {id::kRoad, id::kSidewalk, 0.01, Extent::kWhole},
    {id::kParking, id::kRoad, 0.15, Extent::kWhole},
    {id::kParking, id::kSidewalk, 0.08, Extent::kWhole},
    {id::kCar, id::kOtherVehicle, 0.015, Extent::kWhole},
    {id::kCar, id::kTruck, 0.01, Extent::kWhole},
    {id::kOtherObject, id::kPole, 0.05, Extent::kWhole},
    {id::kOtherObject, id::kBuilding, 0.05, Extent::kWhole},
    {id::kOtherObject, id::kUnlabeled, 0.10, Extent::kWhole},
};

constexpr double kBleed = 0.12;        // per differing range-image neighbour at the default rate
constexpr double kRangeBucket = 10.0;  // m: part errors persist while the part's distance stays in one bucket

/// The class a network outputs for a true id (moving objects become static ones).
uint16_t networkClass(uint16_t raw) {
  if (raw == id::kMovingCar) return id::kCar;
  if (raw == id::kMovingPerson) return id::kPerson;
  if (raw >= 252 && raw <= 259) return id::kOtherVehicle;
  return raw;
}

bool isThing(uint16_t raw) { return (raw >= 10 && raw <= 32) || raw >= 252; }

struct PartStats {
  double range_sum = 0.0;
  float lo = 1e9f, hi = -1e9f;
  uint32_t count = 0;
  uint16_t label = 0;
};

/// The decided error of one part: new label for the points it covers (label 0xFFFF = no change).
struct PartError {
  uint16_t to = 0xFFFF;
  Extent extent = Extent::kWhole;
  float cut = 0.0f;  ///< height splitting top from bottom
};

}  // namespace

std::vector<uint32_t> trueLabels(const RawScan& scan) {
  std::vector<uint32_t> out(scan.semantic.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = scan.semantic[i] | (static_cast<uint32_t>(scan.instance[i]) << 16);
  return out;
}

std::vector<uint32_t> predictLabels(const RawScan& scan, double rate, uint64_t seed, int64_t scan_index) {
  if (rate <= 0.0) return trueLabels(scan);
  const size_t n = scan.points.size();
  const double scale = rate / kDefaultLabelNoise;
  const uint64_t base = hashWords(seed, static_cast<uint64_t>(Stream::kLabelNoise), static_cast<uint64_t>(scan_index));
  const uint64_t persistent = hashWords(seed, static_cast<uint64_t>(Stream::kLabelNoise), 0xC0FFEE);

  // 1. Part confusions, decided once per part from a hash of its key (independent of visiting order).
  std::unordered_map<uint64_t, PartStats> parts;
  for (size_t i = 0; i < n; ++i) {
    PartStats& s = parts[scan.part[i]];
    s.range_sum += scan.points[i].norm();
    s.lo = std::min(s.lo, scan.height[i]);
    s.hi = std::max(s.hi, scan.height[i]);
    ++s.count;
    s.label = networkClass(scan.semantic[i]);
  }
  std::unordered_map<uint64_t, PartError> errors;
  for (const auto& [key, s] : parts) {
    const double range = s.range_sum / s.count;
    // Far and small parts are harder: ×0.6 at close range up to ×1.6 beyond 40 m, and up to ×1.5 for few points.
    const double difficulty = (0.6 + std::min(1.0, range / 40.0)) * (s.count < 30 ? 1.5 : 1.0);
    // The same part seen from about the same distance is mislabelled the same way in every frame (a network's
    // error depends on how the object looks, not on the frame number): no flicker between neighbouring frames,
    // and a revisit from a similar range sees the same errors.
    const uint64_t look = hashWords(persistent, key, static_cast<uint64_t>(range / kRangeBucket));
    double u = hashUniform(hashWords(look, 1));
    for (const Confusion& c : kConfusions) {
      if (c.from != s.label) continue;
      const double p = std::min(0.9, c.probability * scale * difficulty);
      if (u < p) {
        const float cut = static_cast<float>(hashUniform(hashWords(look, 2)));
        const float top = s.lo + (0.3f + 0.5f * cut) * (s.hi - s.lo);
        const float bottom = s.lo + std::min(0.5f * (1.0f + cut) * kBottomBand, 0.5f * (s.hi - s.lo));
        errors[key] = PartError{c.to, c.extent, c.extent == Extent::kBottom ? bottom : top};
        break;
      }
      u -= p;
    }
  }
  std::vector<uint16_t> label(n);
  for (size_t i = 0; i < n; ++i) {
    label[i] = networkClass(scan.semantic[i]);
    const auto it = errors.find(scan.part[i]);
    if (it == errors.end()) continue;
    const PartError& e = it->second;
    const bool covered = e.extent == Extent::kWhole || (e.extent == Extent::kTop && scan.height[i] >= e.cut) ||
                         (e.extent == Extent::kBottom && scan.height[i] < e.cut);
    if (covered) label[i] = e.to;
  }

  // 2. Boundary bleeding across range-image neighbours (decided from the labels of step 1 only: no cascades).
  std::vector<int32_t> point_of(static_cast<size_t>(scan.rows) * scan.columns, -1);
  for (size_t i = 0; i < n; ++i) point_of[static_cast<size_t>(scan.ray[i])] = static_cast<int32_t>(i);
  const double bleed = std::min(0.5, kBleed * scale);
  std::vector<uint16_t> out = label;
  for (size_t i = 0; i < n; ++i) {
    const int ray = scan.ray[i], row = ray % scan.rows, col = ray / scan.rows;
    const int rays[4] = {
        row > 0 ? ray - 1 : -1,
        row + 1 < scan.rows ? ray + 1 : -1,
        col > 0 ? ray - scan.rows : (scan.wraps ? ray + (scan.columns - 1) * scan.rows : -1),
        col + 1 < scan.columns ? ray + scan.rows : (scan.wraps ? ray - (scan.columns - 1) * scan.rows : -1),
    };
    for (int k = 0; k < 4; ++k) {
      if (rays[k] < 0) continue;
      const int32_t q = point_of[static_cast<size_t>(rays[k])];
      if (q < 0 || label[q] == label[i]) continue;
      if (hashUniform(hashWords(base, static_cast<uint64_t>(ray), 3 + k)) < bleed) {
        out[i] = label[q];
        break;
      }
    }
  }
  std::vector<uint32_t> words(n);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t inst = isThing(out[i]) && isThing(scan.semantic[i]) ? scan.instance[i] : 0;
    words[i] = out[i] | (inst << 16);
  }
  return words;
}

}  // namespace sgtllc::sim
