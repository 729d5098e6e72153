/// @file scene.h
/// @brief Scene presets: the numbers that make a generated world urban (KITTI 00), suburban (KITTI 08) or rural.
#pragma once

#include <string>

namespace sgtllc::sim {

enum class SceneKind { kUrban, kSuburban, kRural };

/// Parses "urban", "suburban" or "rural"; throws sgtllc::Error naming the value otherwise.
SceneKind parseSceneKind(const std::string& name);
const char* sceneName(SceneKind kind);

/// Cross-section of a road from its centre line outwards, per side (m).
struct RoadProfile {
  int lanes_per_direction = 1;
  double lane_width = 3.0;
  double parking_width = 0.0;   ///< parking lane along the kerb (0 = none)
  double verge_width = 0.0;     ///< grass strip between kerb and sidewalk
  double sidewalk_width = 0.0;  ///< 0 = no sidewalk (rural)

  /// Centre line to kerb: driving lanes plus parking lane.
  double kerb() const { return lanes_per_direction * lane_width + parking_width; }
  /// Centre line to the property line behind the sidewalk.
  double edge() const { return kerb() + verge_width + sidewalk_width; }
};

/// Ranges are [min, max]; probabilities per item; densities per metre of road side unless noted.
struct ScenePreset {
  SceneKind kind = SceneKind::kUrban;

  // Road network and ground.
  double block_min = 75.0, block_max = 120.0;  ///< distance between neighbouring intersections (m)
  double node_jitter = 8.0;                    ///< random shift of an intersection (m)
  double curve_probability = 0.25;             ///< an edge is a curve (quadratic Bézier) ...
  double curve_bulge = 0.12;                   ///< ... whose control point is this share of its length aside
  double remove_probability = 0.10;            ///< an edge is dropped (every intersection keeps ≥ 2 roads)
  double diagonal_probability = 0.08;          ///< a block gets a diagonal street
  double avenue_probability = 0.2;             ///< a grid line becomes an avenue
  RoadProfile street{1, 2.9, 2.1, 0.0, 2.0};
  double street_parking_probability = 0.6;  ///< a street has parking lanes (else its parking_width is 0)
  RoadProfile avenue{2, 3.3, 2.2, 2.0, 3.0};
  double verge_probability = 0.1;              ///< a street gets a grass verge of street_verge_width
  double street_verge_width = 1.6;
  double ground_amplitude = 2.0;               ///< height field amplitude (m), see GroundHeight
  double lawn_fraction = 0.05;                 ///< share of private land that is grass (the rest is paved)

  // Buildings, set along each road side in lots.
  double building_probability = 0.95;
  double lot_width_min = 9.0, lot_width_max = 24.0;
  double lot_gap_min = 0.5, lot_gap_max = 4.0;
  double row_house_probability = 0.6;   ///< a lot follows the previous one without a gap
  double setback_min = 0.3, setback_max = 4.0;  ///< drawn skewed towards the minimum
  double depth_min = 10.0, depth_max = 16.0;
  double height_min = 8.0, height_max = 20.0;

  // Lot boundaries and vegetation.
  double fence_probability = 0.15;   ///< a lot front gets a fence or low wall
  double hedge_probability = 0.4;    ///< ... or a hedge
  double street_tree_probability = 0.65;  ///< a road side gets a row of street trees
  double tree_spacing_min = 6.0, tree_spacing_max = 11.0;
  double yard_tree_probability = 0.4;     ///< a lot gets a tree in its yard
  double bush_probability = 0.7;          ///< a lot gets bushes
  double forest_probability = 0.0;        ///< a road side stretch is lined by woodland (rural)

  // Street furniture.
  double light_spacing = 40.0;            ///< street lights (m apart, alternating sides)
  double sign_probability = 0.75;         ///< an intersection approach gets a sign
  double midblock_sign_spacing = 90.0;    ///< other signs along the road (mean m apart per side)

  // Vehicles and people.
  double parking_occupancy = 0.55;        ///< a parking slot holds a car
  double moving_cars_per_km = 5.0;        ///< per km of road
  double pedestrians_per_km = 5.0;        ///< per km of sidewalk

  // Change between visits (share of items that change once during the sequence).
  double parked_change = 0.35;
  double vegetation_change = 0.12;

  // Driving.
  double speed_min = 7.0, speed_max = 12.0;  ///< cruise speed of a leg (m/s), 5–15 overall
};

/// The preset of a scene kind.
ScenePreset scenePreset(SceneKind kind);

}  // namespace sgtllc::sim
