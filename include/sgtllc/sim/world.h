/// @file world.h
/// @brief A generated world: ground, roads, every static object as primitives in a BVH, and moving agents.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sgtllc/sim/bvh.h"
#include "sgtllc/sim/ground.h"
#include "sgtllc/sim/road_network.h"
#include "sgtllc/sim/scene.h"

namespace sgtllc::sim {

/// SemanticKITTI raw ids the simulator emits (data/README.md lists them all).
namespace semantic {
inline constexpr uint16_t kUnlabeled = 0, kCar = 10, kTruck = 18, kOtherVehicle = 20, kPerson = 30, kRoad = 40,
                          kParking = 44, kSidewalk = 48, kOtherGround = 49, kBuilding = 50, kFence = 51,
                          kOtherStructure = 52, kVegetation = 70, kTrunk = 71, kTerrain = 72, kPole = 80,
                          kTrafficSign = 81, kOtherObject = 99, kMovingCar = 252, kMovingPerson = 254;
}  // namespace semantic

enum class ObjectKind : uint8_t { kBuilding, kFence, kHedge, kTree, kBush, kPole, kSign, kVehicle, kPerson, kOther };

/// One object (a building, a tree, a car, …): the unit of instance ids and of coherent label errors.
struct Object {
  ObjectKind kind = ObjectKind::kOther;
  uint16_t instance = 0;  ///< SemanticKITTI instance id: non-zero for things (vehicles, people) only
};

/// Something that moves along a road: a car in a lane or a pedestrian on a sidewalk.
struct Agent {
  uint32_t object = 0;
  int edge = 0;             ///< road it moves along (it reappears at the start when it reaches the end)
  bool forward = true;      ///< direction a → b
  double offset = 0.0;      ///< metres right of the centre line in its direction of travel
  double speed = 0.0;       ///< m/s (0 = standing)
  double phase = 0.0;       ///< arc length at time 0
  float length = 4.4f, width = 1.8f, height = 1.5f;
  bool car = true;          ///< car or pedestrian
};

/// What generateWorld() needs.
struct WorldConfig {
  ScenePreset preset;
  uint64_t seed = 1;
  int blocks_x = 4, blocks_y = 4;  ///< grid size of the road network
  double duration = 100.0;         ///< seconds the sequence lasts (sets when changes between visits happen)
  /// Seeds the parked and moving vehicles and the people; unset = seed. A second session through the same world
  /// sets its own (docs/relocalization.md): the streets, buildings and trees stay, the traffic does not.
  std::optional<uint64_t> traffic_seed;

  uint64_t trafficSeed() const { return traffic_seed.value_or(seed); }
};

struct World {
  WorldConfig config;
  GroundHeight ground;
  ZoneMap zones;
  RoadNetwork roads;
  std::vector<Object> objects;
  Bvh statics;  ///< every static primitive; time-limited ones model parked cars leaving, vegetation cut back
  std::vector<Agent> agents;

  /// Primitives of the agents at time @p time within @p radius of @p centre (xy), leaving out any closer than
  /// @p clearance to it (they would overlap the sensor's own vehicle).
  std::vector<Primitive> agentPrimitives(double time, const Eigen::Vector2d& centre, double radius,
                                         double clearance) const;
};

/// Generates the world (deterministic in config.seed).
World generateWorld(const WorldConfig& config);

/// Grid size that gives a route of @p route_length metres room to explore without driving in circles.
int blocksForRoute(const ScenePreset& preset, double route_length);

}  // namespace sgtllc::sim
