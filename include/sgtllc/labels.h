/// @file labels.h
/// @brief Mapping of raw per-point semantic ids to the stable classes: the paper's seven (algorithm §1, §8) and the
///        configuration's extra classes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sgtllc/config.h"

namespace sgtllc {

/// Class assigned to ids that are dropped (not one of the stable classes).
inline constexpr int8_t kDropped = -1;

/// Lookup table from a raw id to a stable class index (0..C−1: the preset's seven classes, then
/// LabelConfig::extra_classes) or kDropped. Only the low 16 bits of an id are used,
/// so SemanticKITTI instance ids in the high half are ignored for every preset.
class LabelMap {
 public:
  explicit LabelMap(const LabelConfig& config = {});

  /// Stable class of a raw id, or kDropped.
  int8_t classOf(uint32_t raw) const { return table_[raw & 0xFFFFu]; }
  /// True if the id belongs to the preset's label space (a dropped class such as road is known; 12345 is not).
  bool isKnown(uint32_t raw) const { return known_[raw & 0xFFFFu] != 0; }

 private:
  std::vector<int8_t> table_;
  std::vector<uint8_t> known_;
};

/// For each stable class index, whether an id of @p labels' label space maps to it (nuScenes-lidarseg has no pole,
/// trunk or traffic-sign class, for instance).
std::array<bool, kMaxClasses> presentClasses(const LabelConfig& labels);

/// What labeller.source hybrid splits off by geometry for the label set @p labels (docs/labeller.md §6): poles
/// from its building class when it has no pole class, trunks from its vegetation class when it has no trunk class.
struct HybridSplits {
  bool pole = false;
  bool trunk = false;
  bool any() const { return pole || trunk; }
};
HybridSplits hybridSplits(const LabelConfig& labels);

}  // namespace sgtllc
