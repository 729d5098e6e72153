// Buildings in lots along every road side, with what stands in front of them: fences, hedges, yard trees, bushes.
#include <algorithm>
#include <cmath>

#include "world_builder.h"

namespace sgtllc::sim::detail {
namespace {

/// A lot along one side of an edge: frontage from s0 to s1, starting at the property line.
struct Lot {
  const RoadEdge* edge = nullptr;
  int side = 1;  ///< +1 right of the edge, −1 left
  double s0 = 0.0, s1 = 0.0;
  double base = 0.0;  ///< centre line to property line (m)

  double mid() const { return 0.5 * (s0 + s1); }
  double width() const { return s1 - s0; }
  double yaw() const { return edge->headingAt(mid()); }
  /// A point @p along metres from the lot's start and @p depth metres behind the property line.
  Eigen::Vector2d at(double along, double depth) const { return edge->sidePoint(s0 + along, side * (base + depth)); }
};

/// Main block plus optional upper storey set back, rear wing and front bays; all share one object.
bool addBuilding(WorldBuilder& b, Rng& rng, const Lot& lot, double setback) {
  const ScenePreset& p = b.preset;
  const double depth = rng.uniform(p.depth_min, p.depth_max);
  const double yaw = lot.yaw();
  const Eigen::Vector2d inward = (lot.at(0.5 * lot.width(), 1.0) - lot.at(0.5 * lot.width(), 0.0)).normalized();
  const Footprint main{lot.at(0.5 * lot.width(), setback + 0.5 * depth), lot.width(), depth, yaw};
  if (!b.claim(main, kPrivateLand)) return false;
  const uint32_t object = b.addObject(ObjectKind::kBuilding);
  const float refl = static_cast<float>(rng.uniform(0.25, 0.55));
  auto box = [&](const Footprint& f, double z0, double top) {
    Primitive prim = makeBox(f.centre.cast<float>(), static_cast<float>(z0), static_cast<float>(f.length),
                             static_cast<float>(f.width), static_cast<float>(top - z0), static_cast<float>(f.yaw),
                             semantic::kBuilding, object);
    prim.reflectivity = refl;
    b.add(prim);
  };
  const double z0 = b.lowestGround(main) - 1.0;  // sunk into the slope: no gap under the walls
  const double ground = b.groundZ(main.centre);
  const double height = rng.uniform(p.height_min, p.height_max);
  if (height > 8.0 && rng.chance(0.35)) {
    const double lower = height * rng.uniform(0.55, 0.75), back = rng.uniform(1.5, 3.0);
    box(main, z0, ground + lower);
    box(Footprint{main.centre + 0.5 * back * inward, main.length, depth - back, yaw}, ground + lower - 0.1,
        ground + height);
  } else {
    box(main, z0, ground + height);
  }
  if (rng.chance(0.35)) {  // rear wing at one end
    const double wing_w = lot.width() * rng.uniform(0.3, 0.6), wing_d = rng.uniform(4.0, 10.0);
    const double along = rng.chance(0.5) ? 0.5 * wing_w : lot.width() - 0.5 * wing_w;
    const Footprint wing{lot.at(along, setback + depth + 0.5 * wing_d), wing_w, wing_d, yaw};
    if (b.claim(wing, kPrivateLand)) {
      box(wing, z0, ground + height * rng.uniform(0.5, 0.9));
    }
  }
  if (setback > 1.5 && rng.chance(0.3)) {  // bays or porches in front of the facade
    const int bays = rng.uniformInt(1, 2);
    for (int k = 0; k < bays; ++k) {
      const double w = rng.uniform(2.0, 4.0), d = rng.uniform(0.6, 1.2);
      const Footprint bay{lot.at(rng.uniform(0.5 * w, lot.width() - 0.5 * w), setback - 0.5 * d), w, d, yaw};
      if (!b.claim(bay, kPrivateLand)) continue;
      box(bay, z0, ground + rng.uniform(2.6, std::max(2.8, 0.8 * height)));
    }
  }
  return true;
}

/// Fence, wall or hedge along the lot's front, with a gap for the gate or drive.
void addLotFront(WorldBuilder& b, Rng& rng, const Lot& lot) {
  const ScenePreset& p = b.preset;
  const double r = rng.uniform();
  if (r >= p.fence_probability + p.hedge_probability || lot.width() < 4.0) return;
  const bool hedge = r >= p.fence_probability;
  const double gap = rng.uniform(1.0, 3.5), gate = rng.uniform(0.0, lot.width() - gap);
  const double depth = hedge ? 0.7 : 0.25;
  const float change = hedge ? b.changeTime(rng, p.vegetation_change) : kInf;
  for (const auto& [from, to] : {std::pair{0.3, gate}, std::pair{gate + gap, lot.width() - 0.3}}) {
    if (to - from < 1.5) continue;
    const Eigen::Vector2d a = lot.at(from, depth), c = lot.at(to, depth);
    const Footprint f{0.5 * (a + c), (c - a).norm(), hedge ? 1.0 : 0.3, lot.yaw()};
    if (!b.claim(f, kPrivateLand)) continue;
    if (hedge) {
      addHedge(b, rng, a, c, change);
    } else {
      addFence(b, rng, a, c);
    }
  }
}

/// Trees and bushes in front of (or instead of) a building.
void addYard(WorldBuilder& b, Rng& rng, const Lot& lot, double depth_free) {
  const ScenePreset& p = b.preset;
  if (depth_free > 3.0 && rng.chance(p.yard_tree_probability)) {
    // Depth before position along the lot: the order GCC drew them in, kept so outputs stay the same (rng.h).
    const double depth = rng.uniform(2.0, std::max(2.2, depth_free - 1.5));
    const Eigen::Vector2d xy = lot.at(rng.uniform(2.0, std::max(2.5, lot.width() - 2.0)), depth);
    if (b.claimCircle(xy, 1.0, kPrivateLand)) {
      const float change = b.changeTime(rng, p.vegetation_change);
      addTree(b, rng, xy, rng.uniform(0.6, 1.1), change);
    }
  }
  if (depth_free > 1.5 && rng.chance(p.bush_probability)) {
    const int n = rng.uniformInt(1, 4);
    for (int k = 0; k < n; ++k) {
      const double radius = rng.uniform(0.6, 1.5);
      const double depth = rng.uniform(1.2, std::max(1.3, depth_free - radius));  // first, as above
      const Eigen::Vector2d xy = lot.at(rng.uniform(1.0, std::max(1.2, lot.width() - 1.0)), depth);
      if (!b.claimCircle(xy, radius, kPrivateLand)) continue;
      addBush(b, rng, xy, radius, b.changeTime(rng, p.vegetation_change));
    }
  }
}

}  // namespace

void placeBuildings(WorldBuilder& b) {
  Rng rng(b.world.config.seed, Stream::kBuildings);
  const ScenePreset& p = b.preset;
  const RoadNetwork& net = b.world.roads;
  for (const RoadEdge& e : net.edges()) {
    const double end = e.length() - net.clearance(e.b);
    for (int side : {1, -1}) {
      double s = net.clearance(e.a) + rng.uniform(0.0, 3.0);
      while (true) {
        Lot lot{&e, side, s, s + rng.uniform(p.lot_width_min, p.lot_width_max), e.profile.edge()};
        if (lot.s1 > end) break;
        const double u = rng.uniform();
        const double setback = p.setback_min + u * u * (p.setback_max - p.setback_min);
        const bool built = rng.chance(p.building_probability) && addBuilding(b, rng, lot, setback);
        if (setback > 1.0 || !built) addLotFront(b, rng, lot);
        addYard(b, rng, lot, built ? setback : 12.0);
        const double gap = rng.chance(p.row_house_probability) ? 0.0 : rng.uniform(p.lot_gap_min, p.lot_gap_max);
        if (gap > 2.0 && rng.chance(p.bush_probability)) {
          // Greenery between houses: a bush or a small tree near the front of the gap.
          const Lot between{&e, side, lot.s1, lot.s1 + gap, lot.base};
          const Eigen::Vector2d xy = between.at(0.5 * gap, rng.uniform(1.0, 4.0));
          if (b.claimCircle(xy, 0.5 * gap, kPrivateLand)) {
            const float change = b.changeTime(rng, p.vegetation_change);
            if (rng.chance(0.4)) {
              addTree(b, rng, xy, rng.uniform(0.6, 1.0), change);
            } else {
              addBush(b, rng, xy, std::min(1.5, 0.45 * gap), change);
            }
          }
        }
        s = lot.s1 + gap;
      }
    }
  }
}

}  // namespace sgtllc::sim::detail
