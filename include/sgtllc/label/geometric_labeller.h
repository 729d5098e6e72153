/// @file geometric_labeller.h
/// @brief Per-point stable classes from a scan's geometry alone (docs/labeller.md): ground segmentation
///        (ground.h), voxel segments (segmentation.h), eigenvalue shape features (shape_features.h) and rules.
///
/// Loop closing needs classes that come out the same on every visit more than correct semantics, so the rules
/// use only what a second visit from another viewpoint sees alike: a segment's extent, height above the ground
/// and the share of its voxels that are vertical planes or scattered. Trunk and pole are one class here
/// (kPole): thin vertical segments look the same whatever they are; kTrunk is never given. Terrain and
/// traffic-sign are not given either (docs/labeller.md §4, "Merged and missing classes").
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config/labeller_config.h"
#include "sgtllc/labels.h"
#include "sgtllc/types.h"

namespace sgtllc::label {

/// Output of GeometricLabeller::classify for one scan.
struct Labelling {
  /// Stable class per point (building, fence, vegetation or pole) or kDropped (−1): ground,
  /// segments no rule claims (cars, people, clutter), non-finite points.
  std::vector<int8_t> classes;
  std::vector<uint8_t> ground;  ///< 1 = the point is ground (ground.h)
  std::vector<int> segment;     ///< voxel segment of each point (0..segments−1), −1 for ground and dropped input
  int segments = 0;             ///< voxel segments of the non-ground points
  bool ground_found = false;    ///< GroundResult::found
};

/// The geometric labeller. Immutable after construction; safe to share between threads; deterministic.
class GeometricLabeller {
 public:
  /// @p config is used as given; Config::validate() checks its ranges (labeller.*).
  explicit GeometricLabeller(const LabellerConfig& config = {});

  /// Classes of @p points (sensor frame, metres, z up: the ground plane is roughly z = const below the sensor).
  /// Intensity is not used. Any input is accepted: NaN/Inf points are dropped, a scan without ground or with all
  /// points in one place gives dropped points, never an error.
  Labelling classify(const std::vector<Eigen::Vector3f>& points) const;

 private:
  LabellerConfig config_;
};

/// SemanticKITTI raw id of stable class @p c of the paper's seven (building 50 … traffic-sign 81); 0 (unlabeled)
/// for any other value.
uint32_t semanticKittiId(int c);

/// SemanticKITTI raw id of a labelled point (the .label convention, LabelPreset::kSemanticKittiRaw): building 50,
/// fence 51, vegetation 70, trunk 71, terrain 72, pole 80, traffic-sign 81; other ground 40 (road), anything else
/// dropped 0 (unlabeled).
std::vector<uint32_t> semanticKittiIds(const Labelling& labelling);

/// @p points with the labeller's classes as SemanticKITTI raw ids: the input of NodeExtractor under the default
/// LabelConfig (what the pipeline uses with labeller.source geometric).
LabeledCloud labelCloud(std::vector<Eigen::Vector3f> points, const GeometricLabeller& labeller);

}  // namespace sgtllc::label
