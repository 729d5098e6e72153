// Internal to the world generator: the state shared by its placement passes (world.cpp, world_*.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "sgtllc/sim/rng.h"
#include "sgtllc/sim/world.h"

namespace sgtllc::sim::detail {

/// A set of zones, one bit per Zone.
using ZoneMask = uint32_t;
inline constexpr ZoneMask zoneBit(Zone z) { return 1u << static_cast<unsigned>(z); }
inline constexpr ZoneMask kPrivateLand =
    zoneBit(Zone::kLot) | zoneBit(Zone::kLawn) | zoneBit(Zone::kPaved) | zoneBit(Zone::kField);

/// An oriented rectangle on the ground: centre, full length along yaw, full width across it.
struct Footprint {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double length = 1.0, width = 1.0, yaw = 0.0;
};

/// Vehicle body shapes.
enum class VehicleType { kCar, kVan };

class WorldBuilder {
 public:
  explicit WorldBuilder(World& world);

  World& world;
  const ScenePreset& preset;
  std::vector<Primitive> prims;  ///< static primitives; the BVH is built from them at the end

  uint32_t addObject(ObjectKind kind);
  /// Appends a finished primitive. It returns nothing on purpose: a reference into `prims` would dangle after the
  /// next add reallocates the list, so helpers set every field before adding.
  void add(const Primitive& p) { prims.push_back(p); }
  double groundZ(const Eigen::Vector2d& xy) const { return world.ground.height(xy.x(), xy.y()); }
  /// Lowest ground under the corners and centre of a footprint: boxes start below it so slopes leave no gap.
  double lowestGround(const Footprint& f) const;
  /// True if every occupancy cell whose centre lies in the footprint is free and in an allowed zone.
  bool fits(const Footprint& f, ZoneMask allowed) const;
  void occupy(const Footprint& f);
  bool fitsCircle(const Eigen::Vector2d& c, double radius, ZoneMask allowed) const {
    return fits(Footprint{c, 2 * radius, 2 * radius, 0.0}, allowed);
  }
  void occupyCircle(const Eigen::Vector2d& c, double radius) { occupy(Footprint{c, 2 * radius, 2 * radius, 0.0}); }
  /// fits() and, if so, occupy(): true if the footprint was free and is now taken.
  bool claim(const Footprint& f, ZoneMask allowed) {
    if (!fits(f, allowed)) return false;
    occupy(f);
    return true;
  }
  bool claimCircle(const Eigen::Vector2d& c, double radius, ZoneMask allowed) {
    return claim(Footprint{c, 2 * radius, 2 * radius, 0.0}, allowed);
  }
  /// With probability @p p, a random time inside the sequence (15–85 % of it) at which something changes;
  /// otherwise kInf (it never changes).
  float changeTime(Rng& rng, double p) const;

 private:
  template <typename F>
  bool visitCells(const Footprint& f, F&& visit) const;

  uint32_t things_ = 0;  ///< vehicles and people so far
  Eigen::Vector2d lo_;
  long nx_ = 0, ny_ = 0;
  std::vector<uint8_t> occupied_;
};

// Shapes shared by several passes.
/// A tree: trunk cylinder and one to three porous crown ellipsoids; @p scale ~1 sets the size. With a change time,
/// the crown is cut back (or the whole tree felled) at that time.
void addTree(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& xy, double scale, float change_time);
/// A bush: one or two porous ellipsoids of radius about @p radius; removed at @p change_time if finite.
void addBush(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& xy, double radius, float change_time);
/// A hedge or a fence along the segment a–b (porous vegetation box, or a fence box of label 51).
void addHedge(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& a, const Eigen::Vector2d& c, float change_time);
void addFence(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& a, const Eigen::Vector2d& c);
/// Primitives of a vehicle standing on z = @p ground_z.
void vehiclePrimitives(std::vector<Primitive>& out, const Eigen::Vector2d& xy, double ground_z, double yaw,
                       VehicleType type, float length, float width, float height, uint16_t semantic, uint32_t object,
                       float reflectivity);

// The placement passes, in the order generateWorld() runs them.
void paintZones(WorldBuilder& b);
void placeBuildings(WorldBuilder& b);
void placeStreetVegetation(WorldBuilder& b);
void placeStreetFurniture(WorldBuilder& b);
void placeParkedVehicles(WorldBuilder& b);
void placeAgents(WorldBuilder& b);

}  // namespace sgtllc::sim::detail
