// The `labeller.ground.*` and `labeller.segments.*` keys of the configuration YAML (config_fields.cpp); the fields
// are documented in include/sgtllc/config/labeller_config.h.
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
  rule_number("pole_max_width", "a pole segment is at most this wide (m)", [](S& s) -> double& { return s.pole_max_width; });
  rule_number("pole_min_height", "... and at least this tall (m)", [](S& s) -> double& { return s.pole_min_height; });
  rule_number("pole_slice_low", "the pole slice starts this high above the ground (m)",
              [](S& s) -> double& { return s.pole_slice_low; });
  rule_number("pole_slice_high", "... and ends this high (m)", [](S& s) -> double& { return s.pole_slice_high; });
  rule_number("pole_min_span", "a thin slice component spanning this height is a pole section (m)",
              [](S& s) -> double& { return s.pole_min_span; });
  rule_number("pole_voxel", "voxel leaf of the pole slice (m)", [](S& s) -> double& { return s.pole_voxel; });
  rule_number("pole_radius", "points this close to a pole axis in the slice are pole (m)",
              [](S& s) -> double& { return s.pole_radius; });
  rule_number("pole_max_occluded", "a pole is kept if at most this share of the points beside a side lie nearer",
              [](S& s) -> double& { return s.pole_max_occluded; });
  rule_number("building_min_top", "a tall segment reaches this high above the ground (m)",
              [](S& s) -> double& { return s.building_min_top; });
  rule_number("building_min_length", "a building is at least this long (m)",
              [](S& s) -> double& { return s.building_min_length; });
  rule_number("fence_max_top", "a fence ends below this height above the ground (m)",
              [](S& s) -> double& { return s.fence_max_top; });
  rule_number("fence_min_length", "... is at least this long (m)", [](S& s) -> double& { return s.fence_min_length; });
  rule_number("fence_max_width", "... and at most this thick (m)", [](S& s) -> double& { return s.fence_max_width; });
  rule_number("min_wall_share", "share of vertical-plane voxels a building needs (a tall segment with fewer is vegetation)",
              [](S& s) -> double& { return s.min_wall_share; });
  rule_number("min_fence_wall_share", "share of vertical-plane voxels a fence needs",
              [](S& s) -> double& { return s.min_fence_wall_share; });
  rule_number("min_scatter_share", "share of scattered voxels that makes a segment vegetation",
              [](S& s) -> double& { return s.min_scatter_share; });
}

}  // namespace sgtllc::io::detail
