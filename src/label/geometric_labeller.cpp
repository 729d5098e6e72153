// The geometric labeller's rules (docs/labeller.md §4). Each segment is summarised once (its moments, height above
// the ground, and the shapes of its voxels); the rules then give the whole segment one class, so an object is
// labelled alike from any viewpoint that sees enough of it.
#include "sgtllc/label/geometric_labeller.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "sgtllc/label/ground.h"
#include "sgtllc/label/segmentation.h"
#include "sgtllc/label/shape_features.h"
#include "sgtllc/label/side_view.h"

namespace sgtllc::label {
namespace {

/// A voxel is a wall piece if its points lie on a plane whose normal is nearly horizontal, scattered if they
/// fill it in all three directions (vegetation). Thresholds: docs/labeller.md §3.
constexpr double kWallPlanarity = 0.5;
constexpr double kWallNormalVerticality = 0.35;
constexpr double kScattered = 0.15;
/// How far above the pole slice (m) the points around a pole axis still count as pole: the trunk's top below
/// the crown, not the crown.
constexpr double kPoleAboveSlice = 0.5;
/// A pole is seen whole if, within kBeside m beside each side of it, at most pole_max_occluded of the points lie
/// more than kNearer m nearer the sensor (docs/labeller.md §4, "Seen whole").
constexpr double kBeside = 0.6;
constexpr double kNearer = 0.5;

struct SegmentSummary {
  Moments moments;
  float bottom = std::numeric_limits<float>::infinity();  // lowest height above the ground (m)
  float top = -std::numeric_limits<float>::infinity();    // highest
  int shaped_voxels = 0;
  int wall_voxels = 0;
  int scattered_voxels = 0;
};

/// 4 standard deviations of the horizontal spread along the major and the minor axis (m): the length and width
/// of a uniform bar, whatever its heading.
std::pair<double, double> horizontalExtent(const Eigen::Matrix3d& cov) {
  const Eigen::Matrix2d c = cov.topLeftCorner<2, 2>();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
  solver.computeDirect(c);
  const Eigen::Vector2d ev = solver.eigenvalues().cwiseMax(0.0);
  return {4.0 * std::sqrt(ev(1)), 4.0 * std::sqrt(ev(0))};
}

int8_t classOf(const SegmentSummary& s, const SegmentRuleConfig& r) {
  if (s.moments.count() < r.min_points) return kDropped;
  const Eigen::Matrix3d cov = s.moments.covariance();
  const auto [length, width] = horizontalExtent(cov);
  const double height = s.top - s.bottom;
  const double shaped = std::max(1, s.shaped_voxels);
  const double wall_share = s.wall_voxels / shaped;
  const double scatter_share = s.scattered_voxels / shaped;
  if (length <= r.pole_max_width && height >= r.pole_min_height) return kPole;  // trunk and pole: one class
  // Tall segments reach above a car's roof: walls (building) or, without walls, crowns and hedges (vegetation).
  // A 64-beam sensor 1.73 m up with +2° of upward view sees only ~2.4 m of a wall 20 m away, so "tall" is low.
  if (s.top >= r.building_min_top) {
    if (length >= r.building_min_length && wall_share >= r.min_wall_share) return kBuilding;
    if (wall_share < r.min_wall_share) return kVegetation;
  }
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

/// Poles and trunks inside larger segments (a trunk under its crown, a pole touching a hedge): the points of a
/// horizontal slice of the scene, pole_slice_low..pole_slice_high above the ground, are segmented on their own;
/// a slice component that is thin (4 std devs ≤ pole_max_width), spans pole_min_span of height and is seen whole
/// against the points flagged in @p seen (none: every thin component is) is a pole section, and every point of
/// its segment within pole_radius of its axis, up to kPoleAboveSlice above the slice, becomes kPole.
/// After the slicing pole extraction of Schaefer et al., "Long-term urban vehicle localization using pole
/// landmarks extracted from 3-D lidar scans", ECMR 2019 (docs/labeller.md §4).
void markPoles(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& height,
               const std::vector<uint8_t>* seen, const SegmentRuleConfig& r, Labelling* out) {
  const size_t n = points.size();
  std::vector<uint8_t> in_slice(n, 0);
  for (size_t i = 0; i < n; ++i) {
    in_slice[i] = out->segment[i] >= 0 && height[i] >= r.pole_slice_low && height[i] <= r.pole_slice_high;
  }
  const Segmentation slice = segmentVoxels(points, in_slice, r.pole_voxel);
  std::vector<Moments> parts(static_cast<size_t>(slice.num_segments));
  std::vector<float> low(parts.size(), std::numeric_limits<float>::infinity());
  std::vector<float> high(parts.size(), -std::numeric_limits<float>::infinity());
  for (size_t i = 0; i < n; ++i) {
    const int v = slice.point_voxel[i];
    if (v < 0) continue;
    const int k = slice.voxel_segment[v];
    parts[k].add(points[i]);
    low[k] = std::min(low[k], height[i]);
    high[k] = std::max(high[k], height[i]);
  }
  // Axis (x, y) and owning segment of each pole section.
  struct Axis {
    Eigen::Vector2d xy;
    int segment;
  };
  std::vector<Axis> axes;
  std::vector<int> part_axis(parts.size(), -1);
  std::vector<uint8_t> thin(parts.size(), 0);
  for (size_t k = 0; k < parts.size(); ++k) {
    thin[k] = parts[k].count() >= r.min_points && high[k] - low[k] >= r.pole_min_span &&
              horizontalExtent(parts[k].covariance()).first <= r.pole_max_width;
  }
  const std::vector<double> occluded =
      seen ? occludedSides(points, *seen, membersOf(slice.point_voxel, slice.voxel_segment, thin), kBeside, kNearer)
           : std::vector<double>(parts.size(), 0.0);
  for (size_t k = 0; k < parts.size(); ++k) {
    if (!thin[k] || occluded[k] > r.pole_max_occluded) continue;
    part_axis[k] = static_cast<int>(axes.size());
    axes.push_back({parts[k].mean().head<2>(), -1});
  }
  if (axes.empty()) return;
  for (size_t i = 0; i < n; ++i) {
    const int v = slice.point_voxel[i];
    if (v >= 0 && part_axis[slice.voxel_segment[v]] >= 0) axes[part_axis[slice.voxel_segment[v]]].segment = out->segment[i];
  }
  // Each segment's pole axes; a point is tested only against those of its own segment.
  std::vector<std::vector<int>> segment_axes(static_cast<size_t>(out->segments));
  for (size_t a = 0; a < axes.size(); ++a) segment_axes[axes[a].segment].push_back(static_cast<int>(a));
  const double r2 = r.pole_radius * r.pole_radius;
  const float top = static_cast<float>(r.pole_slice_high + kPoleAboveSlice);
  for (size_t i = 0; i < n; ++i) {
    const int s = out->segment[i];
    if (s < 0 || segment_axes[s].empty() || height[i] > top) continue;
    for (int a : segment_axes[s]) {
      if ((points[i].head<2>().cast<double>() - axes[a].xy).squaredNorm() <= r2) {
        out->classes[i] = kPole;
        break;
      }
    }
  }
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
  for (size_t i = 0; i < n; ++i) {
    const int v = seg.point_voxel[i];
    if (v < 0) continue;
    voxels[v].add(points[i]);
    SegmentSummary& s = segments[seg.voxel_segment[v]];
    s.bottom = std::min(s.bottom, ground.height[i]);
    s.top = std::max(s.top, ground.height[i]);
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
  markPoles(points, ground.height, seen_whole ? &use : nullptr, rules, &out);
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
