// The slice search for poles inside larger segments (pole_slices.h; docs/labeller.md §4, "Poles inside larger
// segments", "Trunks in bushes"). Both slices are segmented from the points of the two slices alone, and their
// candidates are tested for being seen whole together (BENCHMARKS.md, "Trunks in bushes").
#include "pole_slices.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sgtllc/label/segmentation.h"
#include "sgtllc/label/shape_features.h"
#include "sgtllc/label/side_view.h"

namespace sgtllc::label {
namespace {

/// How far above the pole slice (m) the points around a pole axis still count as pole: the trunk's top below
/// the crown, not the crown.
constexpr double kPoleAboveSlice = 0.5;
/// The pole slice is searched twice, the second time this much higher (m): the foot of a trunk standing in a bush
/// or a hedge joins the bush in the first slice, and a trunk seen near the sensor ends where the view does
/// (~2 m above the ground at 5 m for a 64-beam sensor). One raised slice instead loses the short poles only the
/// low one sees, which a 32-beam sensor needs (docs/labeller.md §4, "Trunks in bushes").
constexpr double kUpperSliceLift = 0.5;

}  // namespace

void markPoles(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& height,
               const std::vector<uint8_t>* seen, float view_top, const std::vector<uint8_t>& standing,
               const SegmentRuleConfig& r, Labelling* out) {
  const size_t n = points.size();
  constexpr int kSlices = 2;
  const float low[kSlices] = {static_cast<float>(r.pole_slice_low),
                              static_cast<float>(r.pole_slice_low + kUpperSliceLift)};
  const float high[kSlices] = {static_cast<float>(r.pole_slice_high),
                               static_cast<float>(r.pole_slice_high + kUpperSliceLift)};
  // The points of either slice, in scan order, in segments that stand.
  std::vector<int> index;
  for (size_t i = 0; i < n; ++i) {
    const int s = out->segment[i];
    if (s >= 0 && standing[s] && height[i] >= low[0] && height[i] <= high[kSlices - 1]) {
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
    bool standing = false;  // the column around the axis stands taller than a person
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
  // A point is tested only against the axes of its own segment: first whether each axis's column stands, then
  // which points become pole.
  const double r2 = r.pole_radius * r.pole_radius;
  const auto within = [&](size_t i, const Axis& axis) {
    return (points[i].head<2>().cast<double>() - axis.xy).squaredNorm() <= r2;
  };
  for (size_t i = 0; i < n; ++i) {
    const int s = out->segment[i];
    if (s < 0 || segment_axes[s].empty()) continue;
    const Eigen::Vector3f& p = points[i];
    if (height[i] < r.pole_min_top && !atViewTop(p, view_top)) continue;
    for (Axis& axis : segment_axes[s]) axis.standing = axis.standing || within(i, axis);
  }
  for (size_t i = 0; i < n; ++i) {
    const int s = out->segment[i];
    if (s < 0 || segment_axes[s].empty()) continue;
    for (const Axis& axis : segment_axes[s]) {
      if (axis.standing && height[i] <= axis.top && within(i, axis)) {
        out->classes[i] = kPole;
        break;
      }
    }
  }
}

}  // namespace sgtllc::label
