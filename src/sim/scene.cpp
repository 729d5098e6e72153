#include "sgtllc/sim/scene.h"

#include "sgtllc/types.h"

namespace sgtllc::sim {

SceneKind parseSceneKind(const std::string& name) {
  if (name == "urban") return SceneKind::kUrban;
  if (name == "suburban") return SceneKind::kSuburban;
  if (name == "rural") return SceneKind::kRural;
  throw Error("unknown scene '" + name + "' (expected urban, suburban or rural)");
}

const char* sceneName(SceneKind kind) {
  switch (kind) {
    case SceneKind::kUrban: return "urban";
    case SceneKind::kSuburban: return "suburban";
    case SceneKind::kRural: return "rural";
  }
  return "urban";
}

ScenePreset scenePreset(SceneKind kind) {
  ScenePreset p;  // the defaults are the urban preset
  p.kind = kind;
  if (kind == SceneKind::kSuburban) {
    // KITTI 08-like: detached houses with lawns, many trees and hedges, fewer parked cars.
    p.block_min = 110.0;
    p.block_max = 170.0;
    p.curve_probability = 0.35;
    p.avenue_probability = 0.15;
    p.street = RoadProfile{1, 3.0, 2.0, 2.5, 1.8};
    p.street_parking_probability = 0.5;
    p.verge_probability = 0.8;
    p.street_verge_width = 2.5;
    p.lawn_fraction = 0.8;
    p.building_probability = 0.6;
    p.lot_width_min = 16.0;
    p.lot_width_max = 32.0;
    p.lot_gap_min = 3.0;
    p.lot_gap_max = 12.0;
    p.row_house_probability = 0.0;
    p.setback_min = 4.0;
    p.setback_max = 10.0;
    p.depth_min = 9.0;
    p.depth_max = 14.0;
    p.height_min = 5.0;
    p.height_max = 10.0;
    p.fence_probability = 0.3;
    p.hedge_probability = 0.4;
    p.street_tree_probability = 0.75;
    p.yard_tree_probability = 0.7;
    p.bush_probability = 0.7;
    p.parking_occupancy = 0.3;
    p.moving_cars_per_km = 5.0;
    p.pedestrians_per_km = 4.0;
    p.vegetation_change = 0.15;
    p.speed_min = 7.0;
    p.speed_max = 13.0;
  } else if (kind == SceneKind::kRural) {
    // Country roads through fields and woods: few structures, so few distinctive graph nodes.
    p.block_min = 220.0;
    p.block_max = 340.0;
    p.node_jitter = 25.0;
    p.curve_probability = 0.6;
    p.curve_bulge = 0.18;
    p.remove_probability = 0.2;
    p.diagonal_probability = 0.05;
    p.avenue_probability = 0.0;
    p.street = RoadProfile{1, 2.9, 0.0, 3.5, 0.0};
    p.street_parking_probability = 0.0;
    p.verge_probability = 1.0;
    p.street_verge_width = 3.5;
    p.ground_amplitude = 4.0;
    p.lawn_fraction = 1.0;
    p.building_probability = 0.06;
    p.lot_width_min = 14.0;
    p.lot_width_max = 30.0;
    p.lot_gap_min = 20.0;
    p.lot_gap_max = 80.0;
    p.row_house_probability = 0.0;
    p.setback_min = 6.0;
    p.setback_max = 20.0;
    p.height_min = 5.0;
    p.height_max = 9.0;
    p.fence_probability = 0.12;
    p.hedge_probability = 0.15;
    p.street_tree_probability = 0.35;
    p.tree_spacing_min = 9.0;
    p.tree_spacing_max = 20.0;
    p.yard_tree_probability = 0.5;
    p.bush_probability = 0.3;
    p.forest_probability = 0.2;
    p.light_spacing = 0.0;  // utility poles instead (see street furniture)
    p.sign_probability = 0.35;
    p.midblock_sign_spacing = 250.0;
    p.parking_occupancy = 0.0;
    p.moving_cars_per_km = 3.0;
    p.pedestrians_per_km = 0.3;
    p.speed_min = 9.0;
    p.speed_max = 15.0;
  }
  return p;
}

}  // namespace sgtllc::sim
