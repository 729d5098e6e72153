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
/// The pole slice is searched twice, the second time this much higher (m): the foot of a trunk standing in a bush
/// or a hedge joins the bush in the first slice, and a trunk seen near the sensor ends where the view does
/// (~2 m above the ground at 5 m for a 64-beam sensor), so the first slice cannot simply reach higher
/// (docs/labeller.md §4, "Trunks in bushes"; BENCHMARKS.md, "Geometric labeller").
constexpr double kUpperSliceLift = 0.5;
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
/// landmarks extracted from 3-D lidar scans", ECMR 2019 (docs/labeller.md §4). The slice is searched twice, the
/// second time kUpperSliceLift higher; both searches work on the points of the slices only, and their candidates
/// are tested for being seen whole together (BENCHMARKS.md, "Geometric labeller").
void markPoles(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& height,
               const std::vector<uint8_t>* seen, const SegmentRuleConfig& r, Labelling* out) {
  const size_t n = points.size();
  constexpr int kSlices = 2;
  const float low[kSlices] = {static_cast<float>(r.pole_slice_low),
                              static_cast<float>(r.pole_slice_low + kUpperSliceLift)};
  const float high[kSlices] = {static_cast<float>(r.pole_slice_high),
                               static_cast<float>(r.pole_slice_high + kUpperSliceLift)};
  // The points of either slice, in scan order.
  std::vector<int> index;
  for (size_t i = 0; i < n; ++i) {
    if (out->segment[i] >= 0 && height[i] >= low[0] && height[i] <= high[kSlices - 1]) {
      index.push_back(static_cast<int>(i));
    }
  }
  std::vector<Eigen::Vector3f> slice_points(index.size());
  for (size_t j = 0; j < index.size(); ++j) slice_points[j] = points[index[j]];

  // Each slice's components; a component is a part, numbered across the slices.
  struct Part {
    Moments moments;
    float low = std::numeric_limits<float>::infinity();
    float high = -std::numeric_limits<float>::infinity();
    int slice = 0;
  };
  std::vector<Part> parts;
  std::vector<int> slice_part(static_cast<size_t>(kSlices) * index.size(), -1);  // [slice][j]
  std::vector<uint8_t> in_slice(index.size());
  for (int k = 0; k < kSlices; ++k) {
    for (size_t j = 0; j < index.size(); ++j) {
      const float h = height[index[j]];
      in_slice[j] = h >= low[k] && h <= high[k];
    }
    const Segmentation slice = segmentVoxels(slice_points, in_slice, r.pole_voxel);
    const size_t first = parts.size();
    parts.resize(first + static_cast<size_t>(slice.num_segments));
    for (size_t j = 0; j < index.size(); ++j) {
      const int v = slice.point_voxel[j];
      if (v < 0) continue;
      const int id = static_cast<int>(first) + slice.voxel_segment[v];
      slice_part[k * index.size() + j] = id;
      Part& part = parts[static_cast<size_t>(id)];
      part.slice = k;
      part.moments.add(slice_points[j]);
      part.low = std::min(part.low, height[index[j]]);
      part.high = std::max(part.high, height[index[j]]);
    }
  }
  // Thin parts are candidates; those seen whole are pole sections, each with its axis and owning segment.
  std::vector<uint8_t> thin(parts.size(), 0);
  for (size_t k = 0; k < parts.size(); ++k) {
    const Part& part = parts[k];
    thin[k] = part.moments.count() >= r.min_points && part.high - part.low >= r.pole_min_span &&
              horizontalExtent(part.moments.covariance()).first <= r.pole_max_width;
  }
  std::vector<std::vector<int>> candidates(parts.size());  // the thin parts' points, in scan order
  for (size_t at = 0; at < slice_part.size(); ++at) {
    const int id = slice_part[at];
    if (id >= 0 && thin[id]) candidates[id].push_back(index[at % index.size()]);
  }
  const std::vector<double> occluded =
      seen ? occludedSides(points, *seen, candidates, kBeside, kNearer) : std::vector<double>(parts.size(), 0.0);
  struct Axis {
    Eigen::Vector2d xy;
    float top;  // the highest height (above the ground) that still counts as pole
  };
  std::vector<std::vector<Axis>> segment_axes(static_cast<size_t>(out->segments));
  bool any = false;
  for (size_t k = 0; k < parts.size(); ++k) {
    if (candidates[k].empty() || occluded[k] > r.pole_max_occluded) continue;
    // The segment of its last point: a slice component nearly always lies within one.
    const int segment = out->segment[candidates[k].back()];
    segment_axes[segment].push_back(
        {parts[k].moments.mean().head<2>(), high[parts[k].slice] + static_cast<float>(kPoleAboveSlice)});
    any = true;
  }
  if (!any) return;
  // A point is tested only against the axes of its own segment.
  const double r2 = r.pole_radius * r.pole_radius;
  for (size_t i = 0; i < n; ++i) {
    const int s = out->segment[i];
    if (s < 0 || segment_axes[s].empty()) continue;
    for (const Axis& axis : segment_axes[s]) {
      if (height[i] <= axis.top && (points[i].head<2>().cast<double>() - axis.xy).squaredNorm() <= r2) {
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
