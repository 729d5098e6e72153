// Street furniture: street lights, utility poles, traffic signs and lights, bins and bollards.
#include <algorithm>
#include <cmath>

#include "world_builder.h"

namespace sgtllc::sim::detail {
namespace {

constexpr ZoneMask kKerbside = zoneBit(Zone::kSidewalk) | zoneBit(Zone::kVerge) | kPrivateLand;

void pole(WorldBuilder& b, const Eigen::Vector2d& xy, double radius, double height, uint32_t object,
          float reflectivity = 0.4f) {
  Primitive p = makeCylinder(xy.cast<float>(), static_cast<float>(b.groundZ(xy) - 0.3), static_cast<float>(radius),
                             static_cast<float>(height + 0.3), semantic::kPole, object);
  p.reflectivity = reflectivity;
  b.add(p);
}

/// A plate (thin box) of label @p label facing along @p yaw, centred at height @p z above the ground at xy.
void plate(WorldBuilder& b, const Eigen::Vector2d& xy, double z, double width, double height, double yaw,
           uint16_t label, uint32_t object, float reflectivity) {
  Primitive p = makeBox(xy.cast<float>(), static_cast<float>(b.groundZ(xy) + z - 0.5 * height), 0.05f,
                        static_cast<float>(width), static_cast<float>(height), static_cast<float>(yaw), label, object);
  p.reflectivity = reflectivity;
  b.add(p);
}

/// Street light: pole, arm over the road and lamp head (all "pole" in SemanticKITTI).
void streetLight(WorldBuilder& b, Rng& rng, const RoadEdge& e, double s, int side) {
  const double off = e.profile.kerb() + (e.profile.verge_width > 1.0 ? 0.5 * e.profile.verge_width : 0.5);
  const Eigen::Vector2d xy = e.sidePoint(s, side * off);
  if (!b.fitsCircle(xy, 0.3, kKerbside)) return;
  b.occupyCircle(xy, 0.6);
  const uint32_t object = b.addObject(ObjectKind::kPole);
  const double h = rng.uniform(6.0, 8.5), arm = rng.uniform(1.0, 2.2);
  pole(b, xy, rng.uniform(0.07, 0.11), h, object);
  const Eigen::Vector2d toward_road = (e.sidePoint(s, 0.0) - xy).normalized();
  const double yaw = std::atan2(toward_road.y(), toward_road.x());
  const Eigen::Vector2d mid = xy + 0.5 * arm * toward_road;
  b.add(makeBox(mid.cast<float>(), static_cast<float>(b.groundZ(xy) + h - 0.1), static_cast<float>(arm), 0.1f, 0.1f,
                static_cast<float>(yaw), semantic::kPole, object));
  b.add(makeBox((xy + arm * toward_road).cast<float>(), static_cast<float>(b.groundZ(xy) + h - 0.3), 0.6f, 0.3f,
                0.25f, static_cast<float>(yaw), semantic::kPole, object));
}

/// Traffic sign (pole + one or two plates) at arc length s, facing traffic that travels @p forward.
void trafficSign(WorldBuilder& b, Rng& rng, const RoadEdge& e, double s, bool forward) {
  const int side = forward ? 1 : -1;
  const Eigen::Vector2d xy = e.sidePoint(s, side * (e.profile.kerb() + rng.uniform(0.4, 0.9)));
  if (!b.fitsCircle(xy, 0.3, kKerbside)) return;
  b.occupyCircle(xy, 0.5);
  const uint32_t object = b.addObject(ObjectKind::kSign);
  const double bottom = rng.uniform(1.8, 2.5), size = rng.uniform(0.55, 0.9);
  const bool second = rng.chance(0.3);
  pole(b, xy, rng.uniform(0.03, 0.05), bottom + size + 0.05, object);
  // Plates face oncoming traffic, 5 cm in front of the pole.
  const double yaw = e.headingAt(s, forward) + rng.uniform(-0.15, 0.15);
  const Eigen::Vector2d front = xy - 0.06 * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
  const float refl = static_cast<float>(rng.uniform(0.75, 1.0));  // retro-reflective
  plate(b, front, bottom + 0.5 * size, size, size, yaw, semantic::kTrafficSign, object, refl);
  if (second) plate(b, front, bottom - 0.3, size, 0.45, yaw, semantic::kTrafficSign, object, refl);
}

/// Traffic light: a taller pole with a signal head (labelled traffic-sign).
void trafficLight(WorldBuilder& b, Rng& rng, const RoadEdge& e, double s, bool forward) {
  const int side = forward ? 1 : -1;
  const Eigen::Vector2d xy = e.sidePoint(s, side * (e.profile.kerb() + 0.6));
  if (!b.fitsCircle(xy, 0.3, kKerbside)) return;
  b.occupyCircle(xy, 0.5);
  const uint32_t object = b.addObject(ObjectKind::kSign);
  const double h = rng.uniform(3.2, 4.5);
  pole(b, xy, 0.1, h, object);
  const double yaw = e.headingAt(s, forward);
  plate(b, xy, h - 0.7, 0.35, 1.0, yaw, semantic::kTrafficSign, object, 0.35f);
}

void smallObject(WorldBuilder& b, Rng& rng, const RoadEdge& e, double s, int side) {
  const RoadProfile& p = e.profile;
  const Eigen::Vector2d xy = e.sidePoint(s, side * (p.edge() - rng.uniform(0.3, std::max(0.4, p.sidewalk_width - 0.3))));
  if (!b.fitsCircle(xy, 0.5, kKerbside)) return;
  b.occupyCircle(xy, 0.5);
  const uint32_t object = b.addObject(ObjectKind::kOther);
  const double yaw = e.headingAt(s);
  // Height, width, length: the order GCC drew them in, kept so outputs stay the same (rng.h).
  const double height = rng.uniform(0.8, 1.2);
  const double width = rng.uniform(0.4, 0.7);
  const double length = rng.uniform(0.5, 1.6);
  Primitive box = makeBox(xy.cast<float>(), static_cast<float>(b.groundZ(xy)), static_cast<float>(length),
                          static_cast<float>(width), static_cast<float>(height), static_cast<float>(yaw),
                          semantic::kOtherObject, object);
  box.reflectivity = 0.3f;
  b.add(box);
}

}  // namespace

void placeStreetFurniture(WorldBuilder& b) {
  Rng rng(b.world.config.seed, Stream::kStreetFurniture);
  const ScenePreset& p = b.preset;
  const RoadNetwork& net = b.world.roads;
  for (const RoadEdge& e : net.edges()) {
    const double s0 = net.clearance(e.a), s1 = e.length() - net.clearance(e.b);
    if (s1 <= s0) continue;
    if (p.light_spacing > 0) {
      int side = rng.chance(0.5) ? 1 : -1;
      for (double s = s0 + rng.uniform(0.0, p.light_spacing); s < s1; s += p.light_spacing * rng.uniform(0.85, 1.15)) {
        streetLight(b, rng, e, s, side);
        if (e.avenue) {
          streetLight(b, rng, e, s, -side);  // avenues are lit from both sides at once
        } else {
          side = -side;
        }
      }
    } else {
      // Rural: a line of wooden utility poles on one side.
      const int side = rng.chance(0.5) ? 1 : -1;
      const double off = side * (e.profile.edge() + rng.uniform(0.5, 2.0));
      for (double s = s0 + rng.uniform(0.0, 40.0); s < s1; s += rng.uniform(40.0, 55.0)) {
        const Eigen::Vector2d xy = e.sidePoint(s, off);
        if (!b.fitsCircle(xy, 0.3, kKerbside)) continue;
        b.occupyCircle(xy, 0.5);
        pole(b, xy, 0.13, rng.uniform(8.0, 10.0), b.addObject(ObjectKind::kPole), 0.3f);
      }
    }
    // Approaches to both intersections: a sign (or a traffic light where an avenue is involved).
    for (const bool forward : {true, false}) {
      const int node = forward ? e.b : e.a;
      bool avenue = false;
      for (int other : net.nodes()[node].edges) avenue = avenue || net.edges()[other].avenue;
      const double s = forward ? s1 - rng.uniform(0.0, 3.0) : s0 + rng.uniform(0.0, 3.0);
      if (avenue && p.kind != SceneKind::kRural && rng.chance(0.8)) {
        trafficLight(b, rng, e, s, forward);
      } else if (rng.chance(p.sign_probability)) {
        trafficSign(b, rng, e, s, forward);
      }
    }
    for (int side : {1, -1}) {
      for (double s = s0 + rng.uniform(0.0, p.midblock_sign_spacing); s < s1;
           s += rng.uniform(0.3, 1.7) * p.midblock_sign_spacing) {
        trafficSign(b, rng, e, s, side > 0);
      }
      if (e.profile.sidewalk_width <= 0) continue;
      for (double s = s0 + rng.uniform(0.0, 40.0); s < s1; s += rng.uniform(20.0, 70.0)) {
        if (rng.chance(0.6)) smallObject(b, rng, e, s, side);
      }
    }
  }
}

}  // namespace sgtllc::sim::detail
