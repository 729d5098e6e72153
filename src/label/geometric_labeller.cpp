// The geometric labeller's rules (docs/labeller.md §4). Each segment is summarised once (its moments, height above
// the ground, and the shapes of its voxels); the rules then give the whole segment one class, so an object is
// labelled alike from any viewpoint that sees enough of it.
#include "sgtllc/label/geometric_labeller.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sgtllc/label/ground.h"
#include "sgtllc/label/segmentation.h"
#include "sgtllc/label/shape_features.h"
#include "sgtllc/label/side_view.h"
#include "sgtllc/label/view_ceiling.h"

#include "pole_slices.h"

namespace sgtllc::label {
namespace {

/// A voxel is a wall piece if its points lie on a plane whose normal is nearly horizontal, scattered if they
/// fill it in all three directions (vegetation). Thresholds: docs/labeller.md §3.
constexpr double kWallPlanarity = 0.5;
constexpr double kWallNormalVerticality = 0.35;
constexpr double kScattered = 0.15;

struct SegmentSummary {
  Moments moments;
  float bottom = std::numeric_limits<float>::infinity();  // lowest height above the ground (m)
  float top = -std::numeric_limits<float>::infinity();    // highest
  int shaped_voxels = 0;
  int wall_voxels = 0;
  int scattered_voxels = 0;
  bool at_view_top = false;  // a point within kViewTopMargin of the view's top
  /// Taller than a person, or cut by the view's top (SegmentRuleConfig::pole_min_top).
  bool standing(const SegmentRuleConfig& r) const { return top >= r.pole_min_top || at_view_top; }
};

int8_t classOf(const SegmentSummary& s, const SegmentRuleConfig& r) {
  if (s.moments.count() < r.min_points) return kDropped;
  const Eigen::Matrix3d cov = s.moments.covariance();
  const auto [length, width] = horizontalExtent(cov);
  const double height = s.top - s.bottom;
  const double shaped = std::max(1, s.shaped_voxels);
  const double wall_share = s.wall_voxels / shaped;
  const double scatter_share = s.scattered_voxels / shaped;
  if (length <= r.pole_max_width && height >= r.pole_min_height && s.standing(r)) return kPole;  // trunk and pole
  // Tall segments reach above a car's roof: walls (building) or, without walls, crowns and hedges (vegetation).
  // A 64-beam sensor 1.73 m up with +2° of upward view sees only ~2.4 m of a wall 20 m away, so "tall" is low.
  const bool walled = length >= r.building_min_length && wall_share >= r.min_wall_share;
  if (s.top >= r.building_min_top) {
    if (walled) return kBuilding;
    if (wall_share < r.min_wall_share) return kVegetation;
  }
  // A long wall cut by the view's top is as tall as the view lets it be: what it reaches there moves with the
  // heading and the voxels a scan is cut into, and was either side of building_min_top (docs/labeller.md §4,
  // "Cut by the view's top"). Crowns and hedges are not: cars merged with a bush reach the view's top near the
  // sensor too.
  if (s.at_view_top && walled) return kBuilding;
  if (s.top <= r.fence_max_top && length >= r.fence_min_length && width <= r.fence_max_width &&
      wall_share >= r.min_fence_wall_share) {
    return kFence;
  }
  if (scatter_share >= r.min_scatter_share) return kVegetation;
  // No traffic-sign rule: small planes held up in the air were mostly parts of crowns and façades that change
  // with the viewpoint, and their nodes did not come back at a revisit (docs/labeller.md §4).
  return kDropped;
}

/// The points of each segment k with @p wanted[k], in point order (empty lists for the others).
std::vector<std::vector<int>> membersOf(const std::vector<int>& point_voxel, const std::vector<int>& voxel_segment,
                                        const std::vector<uint8_t>& wanted) {
  std::vector<std::vector<int>> members(wanted.size());
  for (size_t i = 0; i < point_voxel.size(); ++i) {
    const int v = point_voxel[i];
    if (v >= 0 && wanted[voxel_segment[v]]) members[voxel_segment[v]].push_back(static_cast<int>(i));
  }
  return members;
}

}  // namespace

GeometricLabeller::GeometricLabeller(const LabellerConfig& config) : config_(config) {}

Labelling GeometricLabeller::classify(const std::vector<Eigen::Vector3f>& points) const {
  const size_t n = points.size();
  const SegmentRuleConfig& rules = config_.segments;
  Labelling out;
  out.classes.assign(n, kDropped);
  out.segment.assign(n, -1);
  GroundResult ground = segmentGround(points, config_.ground);
  out.ground_found = ground.found;
  std::vector<uint8_t> use(n);
  for (size_t i = 0; i < n; ++i) use[i] = !ground.ground[i] && std::isfinite(ground.height[i]);
  const Segmentation seg = segmentVoxels(points, use, rules.voxel);
  out.segments = seg.num_segments;

  std::vector<Moments> voxels(static_cast<size_t>(seg.num_voxels));
  std::vector<SegmentSummary> segments(static_cast<size_t>(seg.num_segments));
  const float view_top = viewCeiling(points, use, kViewTopShare) - kViewTopMargin;
  for (size_t i = 0; i < n; ++i) {
    const int v = seg.point_voxel[i];
    if (v < 0) continue;
    const Eigen::Vector3f& p = points[i];
    voxels[v].add(p);
    SegmentSummary& s = segments[seg.voxel_segment[v]];
    s.bottom = std::min(s.bottom, ground.height[i]);
    s.top = std::max(s.top, ground.height[i]);
    if (atViewTop(p, view_top)) s.at_view_top = true;
  }
  for (int v = 0; v < seg.num_voxels; ++v) {
    SegmentSummary& s = segments[seg.voxel_segment[v]];
    s.moments.merge(voxels[v]);  // in voxel order: the same sums on every run
    if (voxels[v].count() < rules.min_voxel_points) continue;
    const ShapeFeatures f = shapeFeatures(voxels[v].covariance());
    ++s.shaped_voxels;
    if (f.planarity >= kWallPlanarity && f.normal_verticality <= kWallNormalVerticality) ++s.wall_voxels;
    if (f.scattering >= kScattered) ++s.scattered_voxels;
  }
  std::vector<int8_t> segment_class(segments.size());
  std::vector<uint8_t> pole(segments.size(), 0);
  for (size_t k = 0; k < segments.size(); ++k) {
    segment_class[k] = classOf(segments[k], rules);
    pole[k] = segment_class[k] == kPole;
  }
  // A thin upright segment hidden at a side behind nearer points is a strip of something seen through a gap
  // (pole_max_occluded 1 keeps every pole: then nothing is looked at).
  const bool seen_whole = rules.pole_max_occluded < 1.0;
  if (seen_whole) {
    const std::vector<double> occluded =
        occludedSides(points, use, membersOf(seg.point_voxel, seg.voxel_segment, pole), kBeside, kNearer);
    for (size_t k = 0; k < segments.size(); ++k) {
      if (pole[k] && occluded[k] > rules.pole_max_occluded) segment_class[k] = kDropped;
    }
  }
  for (size_t i = 0; i < n; ++i) {
    const int v = seg.point_voxel[i];
    if (v < 0) continue;
    out.segment[i] = seg.voxel_segment[v];
    out.classes[i] = segment_class[seg.voxel_segment[v]];
  }
  std::vector<uint8_t> standing(segments.size());
  for (size_t k = 0; k < segments.size(); ++k) standing[k] = segments[k].standing(rules);
  markPoles(points, ground.height, seen_whole ? &use : nullptr, view_top, standing, rules, &out);
  out.ground = std::move(ground.ground);
  return out;
}

uint32_t semanticKittiId(int c) {
  static constexpr uint32_t kIds[kNumPaperClasses] = {50, 51, 70, 71, 72, 80, 81};
  return c >= 0 && c < kNumPaperClasses ? kIds[c] : 0;
}

std::vector<uint32_t> semanticKittiIds(const Labelling& labelling) {
  std::vector<uint32_t> ids(labelling.classes.size(), 0);
  for (size_t i = 0; i < ids.size(); ++i) {
    const int8_t c = labelling.classes[i];
    if (c >= 0 && c < kNumPaperClasses) {
      ids[i] = semanticKittiId(c);
    } else if (labelling.ground[i]) {
      ids[i] = 40;
    }
  }
  return ids;
}

LabeledCloud labelCloud(std::vector<Eigen::Vector3f> points, const GeometricLabeller& labeller) {
  LabeledCloud cloud;
  cloud.labels = semanticKittiIds(labeller.classify(points));
  cloud.points = std::move(points);
  return cloud;
}

}  // namespace sgtllc::label
