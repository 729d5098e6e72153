// The `labeller.ground.*` and `labeller.segments.*` keys of the configuration YAML (config_fields.cpp); the fields
// are documented in include/sgtllc/label/labeller_config.h.
#include "config_yaml_backend.h"

namespace sgtllc::io::detail {

void addLabellerFields(const BackendFieldMakers& add) {
  using G = GroundConfig;
  using S = SegmentRuleConfig;
  auto ground_number = [&add](const char* key, const char* comment, double& (*ref)(G&)) {
    add.number(std::string("labeller.ground.") + key, comment,
               [ref](Config& c) -> double& { return ref(c.labeller.ground); });
  };
  auto rule_number = [&add](const char* key, const char* comment, double& (*ref)(S&)) {
    add.number(std::string("labeller.segments.") + key, comment,
               [ref](Config& c) -> double& { return ref(c.labeller.segments); });
  };
  auto rule_integer = [&add](const char* key, const char* comment, int& (*ref)(S&)) {
    add.integer(std::string("labeller.segments.") + key, comment,
                [ref](Config& c) -> int& { return ref(c.labeller.segments); });
  };
  add.integer("labeller.ground.sectors", "angular sectors of the ground grid",
              [](Config& c) -> int& { return c.labeller.ground.sectors; });
  ground_number("bin", "range bin of the ground grid (m)", [](G& g) -> double& { return g.bin; });
  ground_number("max_range", "farther points are not ground-tested (m)", [](G& g) -> double& { return g.max_range; });
  ground_number("min_range", "nearer points do not estimate the ground height (m)",
                [](G& g) -> double& { return g.min_range; });
  ground_number("step", "a ground line continues within step + max_slope * range change (m)",
                [](G& g) -> double& { return g.step; });
  ground_number("max_slope", "rise per metre a ground line may have", [](G& g) -> double& { return g.max_slope; });
  ground_number("max_climb", "... and within step + max_climb * range of the sensor's ground height",
                [](G& g) -> double& { return g.max_climb; });
  ground_number("tolerance", "points this far above the ground height or lower are ground (m)",
                [](G& g) -> double& { return g.tolerance; });
  rule_number("voxel", "voxel leaf of the segments (m)", [](S& s) -> double& { return s.voxel; });
  rule_integer("min_points", "smaller segments are dropped", [](S& s) -> int& { return s.min_points; });
  rule_integer("min_voxel_points", "a voxel's own shape counts from this many points",
               [](S& s) -> int& { return s.min_voxel_points; });
  rule_number("pole_max_width", "pole: horizontal extent at most (m)", [](S& s) -> double& { return s.pole_max_width; });
  rule_number("pole_min_height", "pole: vertical extent at least (m)", [](S& s) -> double& { return s.pole_min_height; });
  rule_number("pole_slice_low", "pole slice: from this height above the ground (m)",
              [](S& s) -> double& { return s.pole_slice_low; });
  rule_number("pole_slice_high", "pole slice: up to this height (m)", [](S& s) -> double& { return s.pole_slice_high; });
  rule_number("pole_min_span", "pole slice: a thin component spanning this height is a pole section (m)",
              [](S& s) -> double& { return s.pole_min_span; });
  rule_number("pole_voxel", "pole slice: voxel leaf (m)", [](S& s) -> double& { return s.pole_voxel; });
  rule_number("pole_radius", "pole slice: points this close to a thin component's axis are pole (m)",
              [](S& s) -> double& { return s.pole_radius; });
  rule_number("building_min_top", "building: reaches at least this high above the ground (m)",
              [](S& s) -> double& { return s.building_min_top; });
  rule_number("building_min_length", "building: horizontal length at least (m)",
              [](S& s) -> double& { return s.building_min_length; });
  rule_number("fence_max_top", "fence: ends below this height above the ground (m)",
              [](S& s) -> double& { return s.fence_max_top; });
  rule_number("fence_min_length", "fence: length at least (m)", [](S& s) -> double& { return s.fence_min_length; });
  rule_number("fence_max_width", "fence: thickness at most (m)", [](S& s) -> double& { return s.fence_max_width; });
  rule_number("min_wall_share", "building: share of shaped voxels that are vertical planes (a tall segment with fewer is vegetation)",
              [](S& s) -> double& { return s.min_wall_share; });
  rule_number("min_fence_wall_share", "fence: share of shaped voxels that are vertical planes",
              [](S& s) -> double& { return s.min_fence_wall_share; });
  rule_number("min_scatter_share", "vegetation: share of shaped voxels that are scattered",
              [](S& s) -> double& { return s.min_scatter_share; });
}

}  // namespace sgtllc::io::detail
