// Trees, bushes, hedges and fences, and the vegetation that lines roads (street trees, woods, hedgerows).
#include <algorithm>
#include <cmath>

#include "world_builder.h"

namespace sgtllc::sim::detail {
namespace {

constexpr ZoneMask kTreeZones = kPrivateLand | zoneBit(Zone::kVerge) | zoneBit(Zone::kSidewalk);

/// A box between two ground points: a wall-like primitive of given thickness and height.
Primitive segmentBox(WorldBuilder& b, const Eigen::Vector2d& a, const Eigen::Vector2d& c, double thickness,
                     double height, uint16_t label, uint32_t object) {
  const Eigen::Vector2d d = c - a;
  const double z0 = std::min(b.groundZ(a), b.groundZ(c)) - 0.3;
  const double top = std::max(b.groundZ(a), b.groundZ(c)) + height;
  return makeBox((0.5 * (a + c)).cast<float>(), static_cast<float>(z0), static_cast<float>(d.norm()),
                 static_cast<float>(thickness), static_cast<float>(top - z0), static_cast<float>(std::atan2(d.y(), d.x())),
                 label, object);
}

/// Crown ellipsoids of a tree (centre of the main lobe at @p centre).
void addCrown(WorldBuilder& b, Rng& rng, const Eigen::Vector3f& centre, const Eigen::Vector3f& radii, uint32_t object,
              float t_begin, float t_end) {
  const int lobes = rng.uniformInt(1, 3);
  for (int k = 0; k < lobes; ++k) {
    Eigen::Vector3f c = centre, r = radii;
    if (k > 0) {
      const double a = rng.uniform(0.0, 2.0 * M_PI);
      c += Eigen::Vector3f(std::cos(a), std::sin(a), rng.uniform(-0.3, 0.3)).cwiseProduct(0.45f * radii);
      r *= static_cast<float>(rng.uniform(0.55, 0.8));
    }
    Primitive p = makeEllipsoid(c, r, semantic::kVegetation, object);
    p.mean_free_path = static_cast<float>(rng.uniform(0.45, 0.9));
    p.reflectivity = static_cast<float>(rng.uniform(0.3, 0.45));
    p.t_begin = t_begin;
    p.t_end = t_end;
    b.add(p);
  }
}

/// Trees every few metres along one side of an edge between arc lengths s0 and s1, @p offset right of the centre.
void treeRow(WorldBuilder& b, Rng& rng, const RoadEdge& e, int side, double offset, double s0, double s1,
             double spacing_min, double spacing_max) {
  for (double s = s0 + rng.uniform(0.0, spacing_max); s < s1; s += rng.uniform(spacing_min, spacing_max)) {
    const Eigen::Vector2d xy = e.sidePoint(s, side * offset);
    if (!b.fitsCircle(xy, 0.6, kTreeZones)) continue;
    b.occupyCircle(xy, 0.9);
    const float change = b.changeTime(rng, b.preset.vegetation_change);
    addTree(b, rng, xy, rng.uniform(0.8, 1.2), change);
  }
}

/// Rural woodland: rows of trees behind the verge along a stretch of road.
void woodland(WorldBuilder& b, Rng& rng, const RoadEdge& e, int side, double s0, double s1) {
  const double start = e.profile.edge() + rng.uniform(1.0, 4.0);
  const int rows = rng.uniformInt(2, 5);
  for (int r = 0; r < rows; ++r) {
    for (double s = s0 + rng.uniform(0.0, 5.0); s < s1; s += rng.uniform(3.5, 7.0)) {
      const Eigen::Vector2d xy = e.sidePoint(s, side * (start + r * rng.uniform(4.0, 6.0)));
      if (!b.fitsCircle(xy, 0.5, kPrivateLand)) continue;
      b.occupyCircle(xy, 1.0);
      addTree(b, rng, xy, rng.uniform(0.8, 1.4), kInf);
      if (rng.chance(0.3)) {
        // y before x: the order GCC drew them in, kept so outputs stay the same (rng.h).
        const double dy = rng.uniform(-2, 2);
        const double dx = rng.uniform(-2, 2);
        addBush(b, rng, xy + Eigen::Vector2d(dx, dy), 0.9, kInf);
      }
    }
  }
}

}  // namespace

void addTree(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& xy, double scale, float change_time) {
  const uint32_t object = b.addObject(ObjectKind::kTree);
  const double ground = b.groundZ(xy);
  const double trunk_r = std::min(0.45, rng.uniform(0.13, 0.28) * scale);
  const double crown_base = rng.uniform(1.7, 3.2) * std::sqrt(scale);
  // Vertical radius before horizontal: the order GCC drew them in, kept so outputs stay the same (rng.h).
  const double radius_z = rng.uniform(1.8, 3.2) * scale;
  const double radius_x = rng.uniform(1.8, 3.4) * scale;
  const Eigen::Vector3f radii(static_cast<float>(radius_x), 0.0f, static_cast<float>(radius_z));
  const Eigen::Vector3f r(radii.x(), radii.x() * static_cast<float>(rng.uniform(0.85, 1.15)), radii.z());
  const Eigen::Vector3f centre(static_cast<float>(xy.x()), static_cast<float>(xy.y()),
                               static_cast<float>(ground + crown_base + r.z()));
  const bool felled = std::isfinite(change_time) && rng.chance(0.3);
  Primitive trunk = makeCylinder(xy.cast<float>(), static_cast<float>(ground - 0.3), static_cast<float>(trunk_r),
                                 static_cast<float>(crown_base + r.z() + 0.3), semantic::kTrunk, object);
  trunk.reflectivity = static_cast<float>(rng.uniform(0.25, 0.4));
  if (felled) trunk.t_end = change_time;
  b.add(trunk);
  addCrown(b, rng, centre, r, object, -kInf, change_time);
  if (std::isfinite(change_time) && !felled) {
    // Cut back: a smaller, higher crown from the change on.
    const Eigen::Vector3f pruned = r * static_cast<float>(rng.uniform(0.6, 0.8));
    addCrown(b, rng, centre + Eigen::Vector3f(0, 0, r.z() - pruned.z()), pruned, object, change_time, kInf);
  }
}

void addBush(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& xy, double radius, float change_time) {
  const uint32_t object = b.addObject(ObjectKind::kBush);
  const double ground = b.groundZ(xy);
  const int lobes = rng.uniformInt(1, 2);
  for (int k = 0; k < lobes; ++k) {
    const double r = radius * rng.uniform(0.6, 1.3);
    Eigen::Vector2d c = xy;
    if (k > 0) {
      const double dy = rng.uniform(-1, 1);  // y before x, as in woodland()
      const double dx = rng.uniform(-1, 1);
      c += r * Eigen::Vector2d(dx, dy);
    }
    const double h = r * rng.uniform(0.6, 1.0);
    Primitive p = makeEllipsoid(Eigen::Vector3f(c.x(), c.y(), ground + 0.6 * h),
                                Eigen::Vector3f(r, r * rng.uniform(0.8, 1.2), h).cast<float>(), semantic::kVegetation,
                                object);
    p.mean_free_path = 0.3f;
    p.reflectivity = static_cast<float>(rng.uniform(0.3, 0.45));
    p.t_end = change_time;  // removed at the change (kInf: never)
    b.add(p);
  }
}

void addHedge(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& a, const Eigen::Vector2d& c, float change_time) {
  const uint32_t object = b.addObject(ObjectKind::kHedge);
  const double thick = rng.uniform(0.6, 1.1), height = rng.uniform(0.9, 2.2);
  Primitive p = segmentBox(b, a, c, thick, height, semantic::kVegetation, object);
  p.mean_free_path = 0.3f;
  p.reflectivity = static_cast<float>(rng.uniform(0.3, 0.45));
  if (std::isfinite(change_time)) p.t_end = change_time;
  b.add(p);
  if (std::isfinite(change_time)) {
    // Trimmed lower and thinner from the change on.
    Primitive q = segmentBox(b, a, c, 0.8 * thick, std::max(0.6, height - 0.6), semantic::kVegetation, object);
    q.mean_free_path = 0.3f;
    q.reflectivity = p.reflectivity;
    q.t_begin = change_time;
    b.add(q);
  }
}

void addFence(WorldBuilder& b, Rng& rng, const Eigen::Vector2d& a, const Eigen::Vector2d& c) {
  const uint32_t object = b.addObject(ObjectKind::kFence);
  const double kind = rng.uniform();
  Primitive p;
  if (kind < 0.45) {  // see-through metal or lattice fence
    p = segmentBox(b, a, c, 0.06, rng.uniform(1.0, 1.8), semantic::kFence, object);
    p.mean_free_path = 0.1f;
    p.reflectivity = 0.45f;
  } else if (kind < 0.75) {  // board fence
    p = segmentBox(b, a, c, 0.05, rng.uniform(1.2, 1.9), semantic::kFence, object);
    p.reflectivity = 0.3f;
  } else {  // low wall
    p = segmentBox(b, a, c, 0.25, rng.uniform(0.5, 1.2), semantic::kFence, object);
    p.reflectivity = 0.4f;
  }
  b.add(p);
}

void placeStreetVegetation(WorldBuilder& b) {
  Rng rng(b.world.config.seed, Stream::kVegetation);
  const ScenePreset& p = b.preset;
  const RoadNetwork& net = b.world.roads;
  for (const RoadEdge& e : net.edges()) {
    const double s0 = net.clearance(e.a) + 1.0, s1 = e.length() - net.clearance(e.b) - 1.0;
    const RoadProfile& prof = e.profile;
    for (int side : {1, -1}) {
      if (rng.chance(p.street_tree_probability)) {
        double offset;
        if (prof.verge_width >= 1.2) {
          offset = prof.kerb() + 0.5 * prof.verge_width;
        } else if (prof.sidewalk_width >= 2.0) {
          offset = prof.kerb() + 0.7;  // tree pits at the kerb side of the sidewalk
        } else {
          offset = prof.edge() + rng.uniform(0.5, 2.5);
        }
        treeRow(b, rng, e, side, offset, s0, s1, p.tree_spacing_min, p.tree_spacing_max);
      }
      if (rng.chance(p.forest_probability)) {
        const double len = rng.uniform(60.0, 220.0), start = rng.uniform(s0, std::max(s0, s1 - len));
        woodland(b, rng, e, side, start, std::min(s1, start + len));
      }
      if (p.kind == SceneKind::kRural && rng.chance(0.3)) {
        // Hedgerow or pasture fence along the field edge, in pieces.
        const double off = side * (prof.edge() + rng.uniform(0.5, 1.5));
        const bool hedge = rng.chance(0.6);
        for (double s = s0; s + 10.0 < s1; s += rng.uniform(25.0, 60.0)) {
          const double len = rng.uniform(15.0, 50.0);
          const Eigen::Vector2d a = e.sidePoint(s, off), c = e.sidePoint(std::min(s1, s + len), off);
          const Footprint strip{0.5 * (a + c), (c - a).norm(), 1.0, std::atan2((c - a).y(), (c - a).x())};
          if (!b.claim(strip, kPrivateLand | zoneBit(Zone::kVerge))) continue;
          if (hedge) {
            addHedge(b, rng, a, c, kInf);
          } else {
            addFence(b, rng, a, c);
          }
        }
      }
    }
  }
}

}  // namespace sgtllc::sim::detail
