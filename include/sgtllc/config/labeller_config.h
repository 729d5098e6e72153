/// @file labeller_config.h
/// @brief Where per-point classes come from: the label files beside the scans, or the geometric labeller
///        (docs/labeller.md). Plain data; the settings table (settings.h) holds the ranges.
#pragma once

namespace sgtllc {

/// Source of the per-point semantic classes.
enum class LabelSource {
  kFile,       ///< labels read with the scan (KITTI .label, PCD label field), mapped by LabelConfig [default]
  kGeometric,  ///< the scan's geometry alone: label::GeometricLabeller (docs/labeller.md); no label file is read
  /// the label files, with the classes their label set lacks (pole, trunk) split off by the geometric labeller
  /// (label::CloudLabeller, docs/labeller.md §6)
  kHybrid,
};

/// Ground segmentation (docs/labeller.md §1): a polar grid of sectors × range bins; each sector's lowest points are
/// followed outwards as a line of bounded slope (Himmelsbach et al. 2010).
struct GroundConfig {
  int sectors = 120;            ///< angular sectors around the sensor
  double bin = 0.5;             ///< range bin length (m)
  double max_range = 100.0;     ///< points farther (horizontally, m) are not ground-tested
  /// The ground height below the sensor is a plane fitted to the lowest points of the bins min_range..20 m away;
  /// with fewer than 8 such bins the scan has no ground.
  double min_range = 3.0;       ///< nearer points (horizontally, m) do not estimate the ground height
  /// A bin's lowest point continues its sector's ground line iff it is within step + max_slope · Δr (m) of the last
  /// ground bin Δr metres nearer.
  double step = 0.15;
  double max_slope = 0.1;       ///< rise per metre of range a ground line may have
  /// ... and it stays within step + max_climb · r of the sensor's ground height at range r (m/m)
  double max_climb = 0.05;
  double tolerance = 0.2;       ///< points this far (m) above their bin's ground height or lower are ground
};

/// Segments and their classes (docs/labeller.md §2–§4).
struct SegmentRuleConfig {
  double voxel = 0.4;            ///< leaf (m) of the voxels whose 26-neighbourhood connects a segment
  int min_points = 10;           ///< smaller segments are dropped
  int min_voxel_points = 5;      ///< a voxel's own shape (planar/scattered) counts from this many points
  double pole_max_width = 1.0;   ///< a pole segment's horizontal extent (m, 4 standard deviations) at most
  double pole_min_height = 1.5;  ///< ... and its vertical extent at least (m)
  /// A pole or trunk stands taller than a person: it reaches this high above the ground (m; a slice section's
  /// column does), or the top of the sensor's view. A person is a thin upright too, and is gone at the next visit
  /// (docs/labeller.md §4, "Standing taller than a person"); 2.2 m comes from a person's height, not from tuning.
  double pole_min_top = 2.2;
  /// Poles inside larger segments: the slice pole_slice_low..pole_slice_high (m above the ground) is segmented
  /// alone in voxels of pole_voxel (m); a thin component that spans pole_min_span (m) of height marks the points
  /// of its segment within pole_radius (m) of its axis as pole.
  double pole_slice_low = 0.5;
  double pole_slice_high = 1.8;
  double pole_min_span = 0.9;
  double pole_voxel = 0.25;
  double pole_radius = 0.4;
  /// A pole (segment or slice section) is kept only if on neither side more than this share of the points just
  /// beside it lie nearer the sensor: seen whole, not a strip of a wall or crown between occluders
  /// (docs/labeller.md §4, "Seen whole"); 1 keeps every pole.
  double pole_max_occluded = 0.75;
  /// A tall segment reaches at least this high above the ground (m): a building if long with walls, else
  /// vegetation. A long segment with walls cut by the top of the sensor's view is a building below it too
  /// (docs/labeller.md §4, "Cut by the view's top").
  double building_min_top = 2.3;
  double building_min_length = 4.0;  ///< ... and is at least this long horizontally (m, 4 std devs)
  double fence_max_top = 2.3;        ///< a fence ends below this height above the ground (m)
  double fence_min_length = 2.0;     ///< ... is at least this long (m, 4 std devs)
  double fence_max_width = 0.6;      ///< ... and at most this thick (m, 4 std devs)
  /// Share of a segment's shaped voxels that must be vertical planes for a building; a tall segment with fewer
  /// is vegetation.
  double min_wall_share = 0.25;
  double min_fence_wall_share = 0.35;  ///< the same share for a fence
  /// Share of a segment's shaped voxels that are scattered (scattering λ3/λ1 ≥ 0.15, docs/labeller.md §3)
  /// above which it is vegetation.
  double min_scatter_share = 0.3;
};

/// Everything the labelling stage reads (Config::labeller).
struct LabellerConfig {
  LabelSource source = LabelSource::kFile;  ///< label files or the scan's geometry (`--labeller`)
  GroundConfig ground;                      ///< ground segmentation
  SegmentRuleConfig segments;               ///< segmentation and class rules
};

}  // namespace sgtllc
