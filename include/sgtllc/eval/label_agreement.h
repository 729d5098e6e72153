/// @file label_agreement.h
/// @brief Point-wise agreement of a labelling with a reference labelling of the same scan: per-class precision,
///        recall and IoU (the geometric labeller against a dataset's labels; docs/labeller.md §5).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/labels.h"

namespace sgtllc::eval {

/// Which stable class a class counts as when two labellings are compared: the identity, except where one side
/// cannot tell classes apart (the geometric labeller gives trunk as pole; a nuScenes reference has one class for
/// buildings, poles and signs). Classes mapped to kDropped are ignored on both sides.
using ClassMerge = std::array<int8_t, kMaxClasses>;

/// The identity merge, with @p from mapped to @p to for every pair given.
ClassMerge classMerge(const std::vector<std::pair<int, int>>& from_to = {});

/// The merge for comparing the geometric labeller with a reference of @p reference's label preset: trunk counts
/// as pole, and where the preset has no pole, trunk or traffic-sign class of its own (nuScenes: all are
/// static.manmade) those count as building.
ClassMerge labellerMerge(const LabelConfig& reference);

/// Per-class point counts of a predicted against a reference labelling, summed over any number of scans.
struct ClassAgreement {
  std::array<uint64_t, kMaxClasses> tp{};  ///< points of class c in both
  std::array<uint64_t, kMaxClasses> fp{};  ///< predicted c, reference another class or dropped
  std::array<uint64_t, kMaxClasses> fn{};  ///< reference c, predicted another class or dropped

  /// Adds one scan: @p predicted and @p reference hold a stable class (0..kMaxClasses−1) or kDropped per point,
  /// compared after @p merge. Throws sgtllc::Error if the lengths differ or a class is out of range.
  void add(const std::vector<int8_t>& predicted, const std::vector<int8_t>& reference, const ClassMerge& merge);
  void add(const ClassAgreement& other);

  /// tp / (tp + fp), tp / (tp + fn), tp / (tp + fp + fn); 0 where the denominator is 0.
  double precision(int c) const;
  double recall(int c) const;
  double iou(int c) const;
  /// Points of class c in the reference (tp + fn).
  uint64_t referencePoints(int c) const { return tp.at(c) + fn.at(c); }
};

/// Stable class of each raw id under @p map (kDropped for dropped and unknown ids).
std::vector<int8_t> stableClasses(const std::vector<uint32_t>& ids, const LabelMap& map);

}  // namespace sgtllc::eval
