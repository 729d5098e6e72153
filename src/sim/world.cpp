// World generation: the zone raster, the occupancy bookkeeping and the order of the placement passes.
#include "sgtllc/sim/world.h"

#include <algorithm>
#include <cmath>

#include "world_builder.h"

namespace sgtllc::sim {
namespace detail {
namespace {

constexpr double kZoneCell = 0.25;      // m: ground-class boundaries are this sharp
constexpr double kOccupancyCell = 0.5;  // m
constexpr double kMargin = 70.0;        // m of land around the road network

/// Smooth value noise in [0, 1) with features about @p scale metres across.
double valueNoise(uint64_t seed, double x, double y, double scale) {
  const double gx = x / scale, gy = y / scale;
  const double fx = std::floor(gx), fy = std::floor(gy);
  const double u = gx - fx, v = gy - fy;
  auto corner = [&](double cx, double cy) {
    return hashUniform(hashWords(seed, static_cast<uint64_t>(static_cast<int64_t>(cx)),
                                 static_cast<uint64_t>(static_cast<int64_t>(cy))));
  };
  const double su = u * u * (3 - 2 * u), sv = v * v * (3 - 2 * v);
  return (1 - sv) * ((1 - su) * corner(fx, fy) + su * corner(fx + 1, fy)) +
         sv * ((1 - su) * corner(fx, fy + 1) + su * corner(fx + 1, fy + 1));
}

}  // namespace

WorldBuilder::WorldBuilder(World& w) : world(w), preset(w.config.preset) {
  lo_ = w.zones.lo();
  const Eigen::Vector2d hi = w.zones.hi();
  nx_ = static_cast<long>(std::ceil((hi.x() - lo_.x()) / kOccupancyCell));
  ny_ = static_cast<long>(std::ceil((hi.y() - lo_.y()) / kOccupancyCell));
  occupied_.assign(static_cast<size_t>(nx_ * ny_), 0);
}

uint32_t WorldBuilder::addObject(ObjectKind kind) {
  Object o;
  o.kind = kind;
  if (kind == ObjectKind::kVehicle || kind == ObjectKind::kPerson) {
    // Instance ids count things only, as SemanticKITTI's; they wrap after 65535 (never 0).
    o.instance = static_cast<uint16_t>(things_++ % 65535 + 1);
  }
  world.objects.push_back(o);
  return static_cast<uint32_t>(world.objects.size() - 1);
}

double WorldBuilder::lowestGround(const Footprint& f) const {
  const Eigen::Vector2d ax(std::cos(f.yaw), std::sin(f.yaw)), ay(-ax.y(), ax.x());
  double z = groundZ(f.centre);
  for (int sx : {-1, 1}) {
    for (int sy : {-1, 1}) z = std::min(z, groundZ(f.centre + 0.5 * (sx * f.length * ax + sy * f.width * ay)));
  }
  return z;
}

template <typename F>
bool WorldBuilder::visitCells(const Footprint& f, F&& visit) const {
  const Eigen::Vector2d ax(std::cos(f.yaw), std::sin(f.yaw)), ay(-ax.y(), ax.x());
  const double ex = 0.5 * (std::abs(ax.x()) * f.length + std::abs(ay.x()) * f.width);
  const double ey = 0.5 * (std::abs(ax.y()) * f.length + std::abs(ay.y()) * f.width);
  const long x0 = static_cast<long>(std::floor((f.centre.x() - ex - lo_.x()) / kOccupancyCell));
  const long x1 = static_cast<long>(std::floor((f.centre.x() + ex - lo_.x()) / kOccupancyCell));
  const long y0 = static_cast<long>(std::floor((f.centre.y() - ey - lo_.y()) / kOccupancyCell));
  const long y1 = static_cast<long>(std::floor((f.centre.y() + ey - lo_.y()) / kOccupancyCell));
  for (long iy = y0; iy <= y1; ++iy) {
    for (long ix = x0; ix <= x1; ++ix) {
      const Eigen::Vector2d c = lo_ + kOccupancyCell * Eigen::Vector2d(ix + 0.5, iy + 0.5);
      const Eigen::Vector2d r = c - f.centre;
      if (std::abs(r.dot(ax)) > 0.5 * f.length || std::abs(r.dot(ay)) > 0.5 * f.width) continue;
      if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return false;
      if (!visit(static_cast<size_t>(iy * nx_ + ix), c)) return false;
    }
  }
  return true;
}

bool WorldBuilder::fits(const Footprint& f, ZoneMask allowed) const {
  return visitCells(f, [&](size_t i, const Eigen::Vector2d& c) {
    return !occupied_[i] && (allowed & zoneBit(world.zones.at(c.x(), c.y())));
  });
}

void WorldBuilder::occupy(const Footprint& f) {
  visitCells(f, [&](size_t i, const Eigen::Vector2d&) {
    occupied_[i] = 1;
    return true;
  });
}

float WorldBuilder::changeTime(Rng& rng, double p) const {
  if (!rng.chance(p)) return kInf;
  return static_cast<float>(rng.uniform(0.15, 0.85) * world.config.duration);
}

void paintZones(WorldBuilder& b) {
  World& w = b.world;
  const RoadNetwork& net = w.roads;
  for (size_t e = 0; e < net.edges().size(); ++e) {
    const RoadEdge& edge = net.edges()[e];
    const RoadProfile& p = edge.profile;
    // Parking lanes and verges stop short of intersections; the sidewalk runs round the corner instead.
    auto trim = [&](int node) {
      double widest = 0.0;
      for (int other : net.nodes()[node].edges) widest = std::max(widest, net.edges()[other].profile.kerb());
      return widest + 3.0;
    };
    const double s0 = trim(edge.a), s1 = edge.length() - trim(edge.b);
    for (size_t k = 0; k + 1 < edge.line.size(); ++k) {
      const Eigen::Vector2d &a = edge.line[k], &c = edge.line[k + 1];
      w.zones.paintSegment(a, c, p.lanes_per_direction * p.lane_width, Zone::kRoad);
      const bool inner = edge.s[k] >= s0 && edge.s[k + 1] <= s1;
      if (inner && p.parking_width > 0) w.zones.paintSegment(a, c, p.kerb(), Zone::kParking);
      if (inner && p.verge_width > 0) w.zones.paintSegment(a, c, p.kerb() + p.verge_width, Zone::kVerge);
      if (p.sidewalk_width > 0) w.zones.paintSegment(a, c, p.edge(), Zone::kSidewalk);
      if (p.sidewalk_width <= 0 && p.verge_width > 0) w.zones.paintSegment(a, c, p.edge(), Zone::kVerge);
    }
  }
  const uint64_t seed = hashWords(w.config.seed, static_cast<uint64_t>(Stream::kGround), 7);
  const bool rural = b.preset.kind == SceneKind::kRural;
  const double lawn = b.preset.lawn_fraction;
  w.zones.forEach([&](double x, double y, Zone& z) {
    if (z != Zone::kLot) return;
    if (rural) {
      z = Zone::kField;
    } else {
      z = valueNoise(seed, x, y, 9.0) < lawn ? Zone::kLawn : Zone::kPaved;
    }
  });
}

}  // namespace detail

int blocksForRoute(const ScenePreset& preset, double route_length) {
  const double block = 0.5 * (preset.block_min + preset.block_max);
  return std::clamp(static_cast<int>(std::lround(1.2 * std::sqrt(std::max(route_length, 0.0) / block))), 2, 16);
}

World generateWorld(const WorldConfig& config) {
  World w;
  w.config = config;
  w.ground = GroundHeight(config.seed, config.preset.ground_amplitude);
  w.roads = RoadNetwork::generate(config.preset, config.blocks_x, config.blocks_y, config.seed);
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(detail::kMargin);
  w.zones = ZoneMap(w.roads.lo() - margin, w.roads.hi() + margin, detail::kZoneCell, Zone::kLot, Zone::kField);
  detail::WorldBuilder b(w);
  detail::paintZones(b);
  // Big things first, so smaller ones fill the space left between them.
  detail::placeBuildings(b);
  detail::placeStreetFurniture(b);
  detail::placeStreetVegetation(b);
  detail::placeParkedVehicles(b);
  detail::placeAgents(b);
  w.statics = Bvh(std::move(b.prims));
  return w;
}

std::vector<Primitive> World::agentPrimitives(double time, const Eigen::Vector2d& centre, double radius,
                                              double clearance) const {
  std::vector<Primitive> out;
  for (const Agent& a : agents) {
    const RoadEdge& e = roads.edges()[a.edge];
    const double len = e.length();
    double s = std::fmod(a.phase + a.speed * time, len);
    if (s < 0) s += len;
    const double at = a.forward ? s : len - s;
    const Eigen::Vector2d xy = e.sidePoint(at, a.forward ? a.offset : -a.offset);
    const double dist = (xy - centre).norm();
    if (dist > radius || dist < clearance) continue;
    const double yaw = e.headingAt(at, a.forward);
    const double z = ground.height(xy.x(), xy.y());
    const bool moving = a.speed > 0;
    const uint16_t label = a.car ? (moving ? semantic::kMovingCar : semantic::kCar)
                                 : (moving ? semantic::kMovingPerson : semantic::kPerson);
    if (a.car) {
      detail::vehiclePrimitives(out, xy, z, yaw, detail::VehicleType::kCar, a.length, a.width, a.height, label,
                                a.object, 0.2f);
    } else {
      Primitive p = makeCylinder(xy.cast<float>(), static_cast<float>(z), 0.5f * a.width, a.height, label, a.object);
      p.reflectivity = 0.22f;
      out.push_back(p);
    }
  }
  return out;
}

}  // namespace sgtllc::sim
