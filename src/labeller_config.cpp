// Ranges of the labeller settings (config/labeller_config.h), in the style of Config::validate().
#include <cmath>
#include <string>

#include "config_ranges.h"
#include "sgtllc/config.h"
#include "sgtllc/labels.h"

namespace sgtllc {

using namespace detail;

void validateLabellerConfig(const LabellerConfig& l, const LabelConfig& labels) {
  if (l.source != LabelSource::kFile && l.source != LabelSource::kGeometric && l.source != LabelSource::kHybrid) {
    throw ConfigError("labeller.source", "labeller.source: unknown value");
  }
  const GroundConfig& g = l.ground;
  checkInt("labeller.ground.sectors", g.sectors, 8, 1440);
  checkReal("labeller.ground.bin", g.bin, {0.05}, {10.0});
  checkReal("labeller.ground.max_range", g.max_range, {0.0, false}, {1000.0});
  checkReal("labeller.ground.min_range", g.min_range, {0.0}, {20.0, false});
  checkReal("labeller.ground.step", g.step, {0.0}, {10.0});
  checkReal("labeller.ground.max_slope", g.max_slope, {0.0}, {10.0});
  checkReal("labeller.ground.max_climb", g.max_climb, {0.0}, {10.0});
  checkReal("labeller.ground.tolerance", g.tolerance, {0.0, false}, {10.0});
  // The grid holds 12 bytes per cell: at most 4 million cells (48 MB).
  const double cells = g.sectors * std::ceil(g.max_range / g.bin);
  if (cells > 4.0e6) {
    throw ConfigError("labeller.ground.bin", "labeller.ground.sectors * max_range / bin = " + text(cells) +
                                                 " ground cells is more than 4000000");
  }
  const SegmentRuleConfig& s = l.segments;
  checkReal("labeller.segments.voxel", s.voxel, {0.05}, {10.0});
  checkInt("labeller.segments.min_points", s.min_points, 1, 1000000);
  checkInt("labeller.segments.min_voxel_points", s.min_voxel_points, 3, 1000);
  checkReal("labeller.segments.pole_max_width", s.pole_max_width, {0.0, false}, {100.0});
  checkReal("labeller.segments.pole_min_height", s.pole_min_height, {0.0, false}, {100.0});
  checkReal("labeller.segments.pole_slice_low", s.pole_slice_low, {0.0}, {100.0});
  checkReal("labeller.segments.pole_slice_high", s.pole_slice_high, {0.0, false}, {100.0});
  if (!(s.pole_slice_high > s.pole_slice_low)) {
    throw ConfigError("labeller.segments.pole_slice_high", "labeller.segments.pole_slice_high = " +
                                                               text(s.pole_slice_high) +
                                                               " must be above labeller.segments.pole_slice_low");
  }
  checkReal("labeller.segments.pole_min_span", s.pole_min_span, {0.0, false}, {100.0});
  checkReal("labeller.segments.pole_voxel", s.pole_voxel, {0.05}, {10.0});
  checkReal("labeller.segments.pole_radius", s.pole_radius, {0.0, false}, {10.0});
  checkReal("labeller.segments.pole_max_occluded", s.pole_max_occluded, {0.0}, {1.0});
  checkReal("labeller.segments.building_min_top", s.building_min_top, {0.0, false}, {100.0});
  checkReal("labeller.segments.building_min_length", s.building_min_length, {0.0, false}, {1000.0});
  checkReal("labeller.segments.fence_max_top", s.fence_max_top, {0.0, false}, {100.0});
  checkReal("labeller.segments.fence_min_length", s.fence_min_length, {0.0, false}, {1000.0});
  checkReal("labeller.segments.fence_max_width", s.fence_max_width, {0.0, false}, {100.0});
  checkReal("labeller.segments.min_wall_share", s.min_wall_share, {0.0}, {1.0});
  checkReal("labeller.segments.min_fence_wall_share", s.min_fence_wall_share, {0.0}, {1.0});
  checkReal("labeller.segments.min_scatter_share", s.min_scatter_share, {0.0}, {1.0});
  if (l.source != LabelSource::kFile && !labels.extra_classes.empty()) {
    throw ConfigError("labeller.source", std::string("labeller.source ") +
                                             (l.source == LabelSource::kGeometric ? "geometric" : "hybrid") +
                                             " gives only the paper's seven classes; "
                                         "labels.extra_classes must be empty (it has " +
                                             std::to_string(labels.extra_classes.size()) + ")");
  }
}

LabelConfig effectiveLabelConfig(const LabelConfig& labels, const LabellerConfig& labeller) {
  switch (labeller.source) {
    case LabelSource::kGeometric:
      return LabelConfig{};
    case LabelSource::kHybrid:
      return hybridSplits(labels).any() ? LabelConfig{} : labels;
    default:
      return labels;
  }
}

LabelConfig effectiveLabelConfig(const Config& config) { return effectiveLabelConfig(config.labels, config.labeller); }

}  // namespace sgtllc
