// The settings of the labelling stage (config/labeller_config.h documents each field; docs/labeller.md the method).
#include "setting_table.h"

namespace sgtllc::detail {

void addLabellerSettings(std::vector<Setting>* out) {
  SectionTable<LabellerConfig> l("labeller", [](Config& c) -> LabellerConfig& { return c.labeller; }, out);
  l.choice("source", &LabellerConfig::source,
           {{"file", LabelSource::kFile}, {"geometric", LabelSource::kGeometric}, {"hybrid", LabelSource::kHybrid}},
           "per-point classes from the label files, the scan's geometry, or both (hybrid) (docs/labeller.md)");

  using G = GroundConfig;
  SectionTable<G> g("labeller.ground", [](Config& c) -> G& { return c.labeller.ground; }, out);
  g.number("sectors", &G::sectors, "[8, 1440]", "", "angular sectors of the ground grid");
  g.number("bin", &G::bin, "[0.05, 10]", "m", "range bin of the ground grid");
  g.number("max_range", &G::max_range, "(0, 1000]", "m", "farther points are not ground-tested");
  g.number("min_range", &G::min_range, "[0, 20)", "m", "nearer points do not estimate the ground height");
  g.number("step", &G::step, "[0, 10]", "m", "a ground line continues within step + max_slope * range change");
  g.number("max_slope", &G::max_slope, "[0, 10]", "", "rise per metre a ground line may have");
  g.number("max_climb", &G::max_climb, "[0, 10]", "",
           "... and within step + max_climb * range of the sensor's ground height");
  g.number("tolerance", &G::tolerance, "(0, 10]", "m", "points this far above the ground height or lower are ground");

  using S = SegmentRuleConfig;
  SectionTable<S> s("labeller.segments", [](Config& c) -> S& { return c.labeller.segments; }, out);
  s.number("voxel", &S::voxel, "[0.05, 10]", "m", "voxel leaf of the segments");
  s.number("min_points", &S::min_points, "[1, 1000000]", "", "smaller segments are dropped");
  s.number("min_voxel_points", &S::min_voxel_points, "[3, 1000]", "", "a voxel's own shape counts from this many points");
  s.number("pole_max_width", &S::pole_max_width, "(0, 100]", "m", "a pole segment is at most this wide");
  s.number("pole_min_height", &S::pole_min_height, "(0, 100]", "m", "... and at least this tall");
  s.number("pole_min_top", &S::pole_min_top, "(0, 100]", "m",
           "a pole reaches this high above the ground, or the top of the sensor's view");
  s.number("pole_slice_low", &S::pole_slice_low, "[0, 100]", "m", "the pole slice starts this high above the ground");
  // Config::validate also asks for pole_slice_high > pole_slice_low.
  s.number("pole_slice_high", &S::pole_slice_high, "(0, 100]", "m", "... and ends this high");
  s.number("pole_min_span", &S::pole_min_span, "(0, 100]", "m", "a thin slice component spanning this height is a pole section");
  s.number("pole_voxel", &S::pole_voxel, "[0.05, 10]", "m", "voxel leaf of the pole slice");
  s.number("pole_radius", &S::pole_radius, "(0, 10]", "m", "points this close to a pole axis in the slice are pole");
  s.number("pole_max_occluded", &S::pole_max_occluded, "[0, 1]", "",
           "a pole is kept if at most this share of the points beside a side lie nearer");
  s.number("building_min_top", &S::building_min_top, "(0, 100]", "m",
           "a tall segment reaches this high above the ground (a long wall cut by the view's top is a building below "
           "it too)");
  s.number("building_min_length", &S::building_min_length, "(0, 1000]", "m", "a building is at least this long");
  s.number("fence_max_top", &S::fence_max_top, "(0, 100]", "m", "a fence ends below this height above the ground");
  s.number("fence_min_length", &S::fence_min_length, "(0, 1000]", "m", "... is at least this long");
  s.number("fence_max_width", &S::fence_max_width, "(0, 100]", "m", "... and at most this thick");
  s.number("min_wall_share", &S::min_wall_share, "[0, 1]", "",
           "share of vertical-plane voxels a building needs (a tall segment with fewer is vegetation)");
  s.number("min_fence_wall_share", &S::min_fence_wall_share, "[0, 1]", "", "share of vertical-plane voxels a fence needs");
  s.number("min_scatter_share", &S::min_scatter_share, "[0, 1]", "", "share of scattered voxels that makes a segment vegetation");
}

}  // namespace sgtllc::detail
