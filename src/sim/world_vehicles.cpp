// Parked vehicles (which come and go between visits) and moving agents: cars in lanes, people on sidewalks.
#include <algorithm>
#include <cmath>

#include "world_builder.h"

namespace sgtllc::sim::detail {
namespace {

struct VehicleDraw {
  VehicleType type = VehicleType::kCar;
  uint16_t label = semantic::kCar;
  float length = 4.4f, width = 1.8f, height = 1.5f;
};

VehicleDraw drawVehicle(Rng& rng) {
  VehicleDraw v;
  const double r = rng.uniform();
  if (r < 0.88) {
    v.length = static_cast<float>(rng.uniform(3.8, 4.9));
    v.width = static_cast<float>(rng.uniform(1.68, 1.9));
    v.height = static_cast<float>(rng.uniform(1.4, 1.65));
  } else if (r < 0.97) {
    v.type = VehicleType::kVan;
    v.length = static_cast<float>(rng.uniform(4.8, 5.5));
    v.width = static_cast<float>(rng.uniform(1.9, 2.05));
    v.height = static_cast<float>(rng.uniform(1.9, 2.4));
  } else {
    v.type = VehicleType::kVan;  // trailer or small lorry
    v.label = semantic::kOtherVehicle;
    v.length = static_cast<float>(rng.uniform(3.0, 5.0));
    v.width = 2.0f;
    v.height = static_cast<float>(rng.uniform(1.6, 2.6));
  }
  return v;
}

int countFor(Rng& rng, double expected) {
  const double whole = std::floor(expected);
  return static_cast<int>(whole) + (rng.chance(expected - whole) ? 1 : 0);
}

}  // namespace

void vehiclePrimitives(std::vector<Primitive>& out, const Eigen::Vector2d& xy, double ground_z, double yaw,
                       VehicleType type, float length, float width, float height, uint16_t semantic, uint32_t object,
                       float reflectivity) {
  const Eigen::Vector2d fwd(std::cos(yaw), std::sin(yaw));
  const float z = static_cast<float>(ground_z);
  auto push = [&](const Eigen::Vector2d& c, float z0, float l, float w, float h) {
    Primitive p = makeBox(c.cast<float>(), z0, l, w, h, static_cast<float>(yaw), semantic, object);
    p.reflectivity = reflectivity;
    out.push_back(p);
  };
  if (type == VehicleType::kCar) {
    // Body between the wheels' clearance and the waist line, cabin above it set back a little.
    const float waist = 0.58f * height;
    push(xy, z + 0.25f, length, width, waist - 0.25f);
    push(xy - 0.06 * length * fwd, z + waist, 0.55f * length, 0.9f * width, height - waist);
  } else {  // van
    push(xy - 0.08 * length * fwd, z + 0.3f, 0.84f * length, width, height - 0.3f);
    push(xy + 0.42 * length * fwd, z + 0.3f, 0.16f * length, width, 0.45f * height);
  }
}

void placeParkedVehicles(WorldBuilder& b) {
  Rng rng(b.world.config.trafficSeed(), Stream::kVehicles);
  const ScenePreset& p = b.preset;
  const RoadNetwork& net = b.world.roads;
  constexpr ZoneMask kParkingZones = zoneBit(Zone::kParking);
  if (p.parking_occupancy <= 0) return;
  for (const RoadEdge& e : net.edges()) {
    if (e.profile.parking_width <= 0) continue;
    const double s0 = net.clearance(e.a) + 1.0, s1 = e.length() - net.clearance(e.b) - 1.0;
    const double off = e.profile.kerb() - 0.5 * e.profile.parking_width;
    for (int side : {1, -1}) {
      for (double s = s0; s + 6.0 < s1; s += rng.uniform(5.8, 6.6)) {
        // Who stands in this slot before and after its change (if it changes at all).
        const float change = b.changeTime(rng, p.parked_change);
        const bool changes = std::isfinite(change);
        for (int period = 0; period < (changes ? 2 : 1); ++period) {
          if (!rng.chance(p.parking_occupancy)) continue;
          const VehicleDraw v = drawVehicle(rng);
          const double at = s + 3.0 + rng.uniform(-0.3, 0.3);
          const Eigen::Vector2d xy = e.sidePoint(at, side * (off + rng.uniform(-0.15, 0.15)));
          const double yaw = e.headingAt(at, side > 0) + rng.uniform(-0.04, 0.04);
          if (!b.fits(Footprint{xy, v.length - 0.5, v.width - 0.4, yaw}, kParkingZones)) continue;
          const uint32_t object = b.addObject(ObjectKind::kVehicle);
          const size_t first = b.prims.size();
          vehiclePrimitives(b.prims, xy, b.lowestGround(Footprint{xy, v.length, v.width, yaw}), yaw, v.type, v.length,
                            v.width, v.height, v.label, object, static_cast<float>(rng.uniform(0.05, 0.3)));
          for (size_t k = first; k < b.prims.size(); ++k) {
            b.prims[k].t_begin = period == 0 ? -kInf : change;
            b.prims[k].t_end = period == 0 ? change : kInf;
          }
        }
      }
    }
  }
}

void placeAgents(WorldBuilder& b) {
  Rng rng(b.world.config.trafficSeed(), Stream::kAgents);
  const ScenePreset& p = b.preset;
  const auto& edges = b.world.roads.edges();
  for (size_t ei = 0; ei < edges.size(); ++ei) {
    const RoadEdge& e = edges[ei];
    const RoadProfile& prof = e.profile;
    const int cars = countFor(rng, e.length() / 1000.0 * p.moving_cars_per_km * prof.lanes_per_direction);
    for (int k = 0; k < cars; ++k) {
      Agent a;
      a.object = b.addObject(ObjectKind::kVehicle);
      a.edge = static_cast<int>(ei);
      a.forward = rng.chance(0.5);
      a.offset = (rng.uniformInt(0, prof.lanes_per_direction - 1) + 0.5) * prof.lane_width;
      a.speed = rng.uniform(6.0, 14.0);
      a.phase = rng.uniform(0.0, e.length());
      const VehicleDraw v = drawVehicle(rng);
      a.length = v.length;
      a.width = v.width;
      a.height = v.height;
      b.world.agents.push_back(a);
    }
    if (prof.sidewalk_width <= 0) continue;
    const int people = countFor(rng, 2.0 * e.length() / 1000.0 * p.pedestrians_per_km);
    for (int k = 0; k < people; ++k) {
      Agent a;
      a.object = b.addObject(ObjectKind::kPerson);
      a.edge = static_cast<int>(ei);
      a.car = false;
      a.forward = rng.chance(0.5);
      const int side = rng.chance(0.5) ? 1 : -1;
      const double off = prof.kerb() + prof.verge_width + prof.sidewalk_width * rng.uniform(0.25, 0.75);
      a.offset = (a.forward ? side : -side) * off;
      a.speed = rng.chance(0.7) ? rng.uniform(0.8, 1.6) : 0.0;
      a.phase = rng.uniform(0.0, e.length());
      a.length = a.width = static_cast<float>(rng.uniform(0.45, 0.6));
      a.height = static_cast<float>(rng.uniform(1.55, 1.9));
      b.world.agents.push_back(a);
    }
  }
}

}  // namespace sgtllc::sim::detail
