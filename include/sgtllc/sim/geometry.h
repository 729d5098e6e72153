/// @file geometry.h
/// @brief Scene primitives of the simulator and exact ray intersection with them.
///
/// Three convex solids build every object: a box turned about the vertical axis (buildings, cars, fences, plates),
/// a vertical capped cylinder (trunks, poles, pedestrians) and an axis-aligned ellipsoid (tree crowns, bushes).
/// A primitive may be *porous* (foliage): a ray entering it returns from a random depth inside, or passes through.
#pragma once

#include <cstdint>
#include <limits>

#include <Eigen/Core>

namespace sgtllc::sim {

inline constexpr float kInf = std::numeric_limits<float>::infinity();

/// A ray o + t·d (t ≥ 0); d need not be unit length, t is then in units of |d|.
struct Ray {
  Eigen::Vector3f o = Eigen::Vector3f::Zero();
  Eigen::Vector3f d = Eigen::Vector3f::UnitX();
  Eigen::Vector3f inv_d = Eigen::Vector3f::Constant(kInf);  ///< 1/d per component (±inf for 0)

  Ray() = default;
  Ray(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction);
  Eigen::Vector3f at(float t) const { return o + t * d; }
};

/// Axis-aligned bounding box.
struct Aabb {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(kInf);
  Eigen::Vector3f hi = Eigen::Vector3f::Constant(-kInf);

  void grow(const Eigen::Vector3f& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void grow(const Aabb& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  Eigen::Vector3f centre() const { return 0.5f * (lo + hi); }
  float area() const;  ///< surface area (0 for an empty box)
  /// Entry and exit parameters of the ray within (t_min, t_max]; false if it misses.
  bool hit(const Ray& ray, float t_min, float t_max, float& t_enter) const;
};

enum class Shape : uint8_t { kBox, kCylinder, kEllipsoid };

/// One solid. Sizes are in metres, times in seconds of the sequence.
struct Primitive {
  Shape shape = Shape::kBox;
  uint16_t semantic = 0;  ///< SemanticKITTI raw id of the points it returns
  uint32_t object = 0;    ///< index of the object it belongs to (World::objects)
  /// Box and ellipsoid: centre. Cylinder: centre of the bottom cap.
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  /// Box: half extents along its local x, y, z. Cylinder: (radius, radius, height). Ellipsoid: semi-axes.
  Eigen::Vector3f half = Eigen::Vector3f::Ones();
  float cos_yaw = 1.0f, sin_yaw = 0.0f;  ///< box: local x axis is (cos, sin, 0) in the world
  float mean_free_path = 0.0f;  ///< porous: mean depth (m) a ray travels inside before it returns; 0 = solid
  float reflectivity = 0.3f;    ///< 0..1, drives intensity and long-range dropout
  float t_begin = -kInf;        ///< present from this time (s) ...
  float t_end = kInf;           ///< ... until just before this time: change between visits

  bool aliveAt(float time) const { return time >= t_begin && time < t_end; }
  bool porous() const { return mean_free_path > 0.0f; }
};

/// Box helper: a box of full size (length along yaw, width, height) standing on z = @p ground_z.
Primitive makeBox(const Eigen::Vector2f& centre_xy, float ground_z, float length, float width, float height, float yaw,
                  uint16_t semantic, uint32_t object);
/// Vertical cylinder from z = @p z0 up by @p height.
Primitive makeCylinder(const Eigen::Vector2f& xy, float z0, float radius, float height, uint16_t semantic,
                       uint32_t object);
/// Axis-aligned ellipsoid.
Primitive makeEllipsoid(const Eigen::Vector3f& centre, const Eigen::Vector3f& radii, uint16_t semantic,
                        uint32_t object);

/// Bounding box of a primitive.
Aabb bounds(const Primitive& p);

/// The part of the ray inside the solid: t_in ≤ t_out (t_in < 0 when the origin is inside). Tangent rays touch
/// (t_in == t_out) and count as hits. False if the ray's line misses the solid or the solid lies behind the origin.
bool span(const Primitive& p, const Ray& ray, float& t_in, float& t_out);

/// First surface crossing in (t_min, t_max] of a solid primitive: the entry point, or the exit point when the
/// origin is inside. Porous primitives: the return depth is entry + (−ln(1 − u)) · mean_free_path for the given
/// uniform u ∈ [0, 1); a ray whose depth exceeds the exit passes through (no hit).
bool intersect(const Primitive& p, const Ray& ray, float t_min, float t_max, double u, float& t);

/// Outward unit normal of the primitive's surface nearest to @p x (a point on or near the surface).
Eigen::Vector3f normalAt(const Primitive& p, const Eigen::Vector3f& x);

}  // namespace sgtllc::sim
