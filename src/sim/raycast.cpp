#include "sgtllc/sim/raycast.h"

#include <algorithm>
#include <cmath>

#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {
namespace {

constexpr double kGroundPatch = 5.0;   // m: ground label errors come in patches about this size
constexpr double kDynamicMargin = 10.0;  // m beyond the range within which agents are considered
constexpr double kEgoClearance = 3.5;    // m: agents closer than this would overlap the sensor's vehicle

/// Return probability falls for dark and grazing surfaces: a surface of effective reflectivity ρ·cos θ returns
/// up to max_range · (ρ·cos θ / 0.5)^¼ (a soft version of the LiDAR range equation).
double reachFor(double max_range, double effective_reflectivity) {
  return max_range * std::sqrt(std::sqrt(std::min(1.0, std::max(effective_reflectivity, 1e-4) / 0.5)));
}

}  // namespace

RawScan castScan(const World& world, const SensorModel& sensor, const Eigen::Matrix4d& T_world_lidar, double time,
                 int64_t scan, uint64_t seed) {
  const SensorConfig& cfg = sensor.config();
  RawScan out;
  out.rows = sensor.rows();
  out.columns = sensor.columns();
  out.wraps = sensor.wraps();
  std::vector<Eigen::Vector3f> dirs;
  sensor.directions(scan, seed, dirs);

  const Eigen::Matrix3f R = T_world_lidar.topLeftCorner<3, 3>().cast<float>();
  const Eigen::Vector3d origin_d = T_world_lidar.topRightCorner<3, 1>();
  const Eigen::Vector3f origin = origin_d.cast<float>();
  const Bvh dynamics(world.agentPrimitives(time, origin_d.head<2>(), cfg.max_range + kDynamicMargin, kEgoClearance));
  const auto& statics = world.statics.primitives();
  Rng rng(seed, Stream::kScan, static_cast<uint64_t>(scan));
  const uint64_t ray_seed = hashWords(seed, static_cast<uint64_t>(Stream::kScan), static_cast<uint64_t>(scan), 2);
  const float max_range = static_cast<float>(cfg.max_range);
  const float slope_bound = static_cast<float>(world.ground.maxSlope());
  const size_t n = dirs.size();
  out.points.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    const Ray ray(origin, R * dirs[i]);
    const RayContext ctx{static_cast<float>(time), hashWords(ray_seed, i)};
    // Closest object (static or moving) within a limit. Agents' rays use their own key space so a porous draw
    // never repeats a static one.
    Hit hit;
    const Primitive* prim = nullptr;
    auto castObjects = [&](float limit) {
      hit = world.statics.closestHit(ray, limit, ctx);
      if (hit.valid()) prim = &statics[hit.prim];
      const Hit moving = dynamics.closestHit(ray, hit.valid() ? hit.t : limit, RayContext{ctx.time, ~ctx.key});
      if (moving.valid()) {
        hit = moving;
        prim = &dynamics.primitives()[moving.prim];
      }
    };
    float t_ground = kInf;
    Eigen::Vector2d ground_gradient;
    bool ground;
    if (ray.d.z() + slope_bound * ray.d.head<2>().norm() < 0.0f) {
      // Steep down: the ground is found in a few Newton steps and bounds the object search.
      ground = world.ground.intersect(ray, max_range, t_ground, &ground_gradient);
      castObjects(ground ? t_ground : max_range);
      if (prim) ground = false;
    } else {
      // Near the horizon: objects first, so the slow search for a distant ground crossing stops at them.
      castObjects(max_range);
      ground = world.ground.intersect(ray, prim ? hit.t : max_range, t_ground, &ground_gradient);
      if (ground && prim && !(t_ground < hit.t)) ground = false;
    }
    if (ground) prim = nullptr;  // the ground is nearer; objects win exact ties either way
    // Draw the noise for every ray, hit or not, so one ray's outcome never shifts another's random numbers.
    const double noise = rng.normal(0.0, cfg.range_noise), drop = rng.uniform(), glint = rng.normal(0.0, 0.02);
    if (!prim && !ground) continue;
    const float t = prim ? hit.t : t_ground;
    const Eigen::Vector3f x = ray.at(t);
    Eigen::Vector3f normal;
    double reflectivity;
    uint16_t label, instance = 0;
    uint64_t part;
    if (prim) {
      normal = normalAt(*prim, x);
      reflectivity = prim->reflectivity;
      label = prim->semantic;
      instance = world.objects[prim->object].instance;
      part = (static_cast<uint64_t>(prim->object) << 16) | label;
      if (prim->porous()) normal = -ray.d;  // foliage: no single surface; leaves face every way
    } else {
      normal = Eigen::Vector3d(-ground_gradient.x(), -ground_gradient.y(), 1.0).normalized().cast<float>();
      const Zone zone = world.zones.at(x.x(), x.y());
      reflectivity = groundReflectivity(zone);
      label = groundSemantic(zone);
      const auto cx = static_cast<int64_t>(std::floor(x.x() / kGroundPatch));
      const auto cy = static_cast<int64_t>(std::floor(x.y() / kGroundPatch));
      part = kGroundPart | (hashWords(static_cast<uint64_t>(cx), static_cast<uint64_t>(cy), label) >> 1);
    }
    const double cos_incidence = std::clamp(static_cast<double>(std::abs(normal.dot(ray.d))), 0.05, 1.0);
    const double range = t + noise;
    if (range < cfg.min_range || range > reachFor(cfg.max_range, reflectivity * cos_incidence) ||
        drop < cfg.dropout) {
      continue;
    }
    const double intensity =
        reflectivity * (0.5 + 0.5 * cos_incidence) * (1.0 - 0.3 * std::min(1.0, range / 80.0)) + glint;
    out.points.push_back(dirs[i] * static_cast<float>(range));
    out.intensity.push_back(static_cast<float>(std::round(std::clamp(intensity, 0.0, 0.99) * 100.0) / 100.0));
    out.semantic.push_back(label);
    out.instance.push_back(instance);
    out.part.push_back(part);
    out.height.push_back(prim ? static_cast<float>(x.z() - world.ground.height(x.x(), x.y())) : 0.0f);
    out.ray.push_back(static_cast<int32_t>(i));
  }
  return out;
}

}  // namespace sgtllc::sim
