#include "sgtllc/sim/geometry.h"

#include <algorithm>
#include <cmath>

namespace sgtllc::sim {
namespace {

/// Slab interval of one axis: o + t·d ∈ [lo, hi]. A ray parallel to the slab is inside for all t or never.
bool slab(float o, float d, float lo, float hi, float& t0, float& t1) {
  if (d == 0.0f) {
    if (o < lo || o > hi) return false;
    return true;
  }
  float a = (lo - o) / d, b = (hi - o) / d;
  if (a > b) std::swap(a, b);
  t0 = std::max(t0, a);
  t1 = std::min(t1, b);
  return t0 <= t1;
}

/// The ray in a box's local frame (rotated by −yaw about the centre).
void toLocal(const Primitive& p, const Ray& ray, Eigen::Vector3f& o, Eigen::Vector3f& d) {
  const Eigen::Vector3f r = ray.o - p.centre;
  o = Eigen::Vector3f(p.cos_yaw * r.x() + p.sin_yaw * r.y(), -p.sin_yaw * r.x() + p.cos_yaw * r.y(), r.z());
  d = Eigen::Vector3f(p.cos_yaw * ray.d.x() + p.sin_yaw * ray.d.y(), -p.sin_yaw * ray.d.x() + p.cos_yaw * ray.d.y(),
                      ray.d.z());
}

/// Roots of a·t² + 2b·t + c = 0 (a > 0); false if none.
bool quadratic(float a, float b, float c, float& t0, float& t1) {
  const float disc = b * b - a * c;
  if (disc < 0.0f || a <= 0.0f) return false;
  const float s = std::sqrt(disc);
  // Stable form: avoid cancellation between −b and s.
  const float q = b > 0.0f ? -(b + s) : -(b - s);
  if (q == 0.0f) {
    t0 = t1 = 0.0f;
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace

Ray::Ray(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction) : o(origin), d(direction) {
  for (int k = 0; k < 3; ++k) inv_d[k] = 1.0f / d[k];  // ±inf for 0, as the slab test expects
}

float Aabb::area() const {
  if (!(lo.x() <= hi.x())) return 0.0f;
  const Eigen::Vector3f e = hi - lo;
  return 2.0f * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
}

bool Aabb::hit(const Ray& ray, float t_min, float t_max, float& t_enter) const {
  float t0 = t_min, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    float a = (lo[k] - ray.o[k]) * ray.inv_d[k];
    float b = (hi[k] - ray.o[k]) * ray.inv_d[k];
    if (a > b) std::swap(a, b);
    // NaN (0·inf on a slab boundary) compares false and leaves the bound unchanged: the ray counts as inside.
    if (a > t0) t0 = a;
    if (b < t1) t1 = b;
    if (t0 > t1) return false;
  }
  t_enter = t0;
  return true;
}

Primitive makeBox(const Eigen::Vector2f& centre_xy, float ground_z, float length, float width, float height, float yaw,
                  uint16_t semantic, uint32_t object) {
  Primitive p;
  p.shape = Shape::kBox;
  p.semantic = semantic;
  p.object = object;
  p.centre = Eigen::Vector3f(centre_xy.x(), centre_xy.y(), ground_z + 0.5f * height);
  p.half = Eigen::Vector3f(0.5f * length, 0.5f * width, 0.5f * height);
  p.cos_yaw = std::cos(yaw);
  p.sin_yaw = std::sin(yaw);
  return p;
}

Primitive makeCylinder(const Eigen::Vector2f& xy, float z0, float radius, float height, uint16_t semantic,
                       uint32_t object) {
  Primitive p;
  p.shape = Shape::kCylinder;
  p.semantic = semantic;
  p.object = object;
  p.centre = Eigen::Vector3f(xy.x(), xy.y(), z0);
  p.half = Eigen::Vector3f(radius, radius, height);
  return p;
}

Primitive makeEllipsoid(const Eigen::Vector3f& centre, const Eigen::Vector3f& radii, uint16_t semantic,
                        uint32_t object) {
  Primitive p;
  p.shape = Shape::kEllipsoid;
  p.semantic = semantic;
  p.object = object;
  p.centre = centre;
  p.half = radii;
  return p;
}

Aabb bounds(const Primitive& p) {
  Aabb b;
  switch (p.shape) {
    case Shape::kBox: {
      const float ex = std::abs(p.cos_yaw) * p.half.x() + std::abs(p.sin_yaw) * p.half.y();
      const float ey = std::abs(p.sin_yaw) * p.half.x() + std::abs(p.cos_yaw) * p.half.y();
      const Eigen::Vector3f e(ex, ey, p.half.z());
      b.lo = p.centre - e;
      b.hi = p.centre + e;
      break;
    }
    case Shape::kCylinder:
      b.lo = p.centre - Eigen::Vector3f(p.half.x(), p.half.x(), 0.0f);
      b.hi = p.centre + Eigen::Vector3f(p.half.x(), p.half.x(), p.half.z());
      break;
    case Shape::kEllipsoid:
      b.lo = p.centre - p.half;
      b.hi = p.centre + p.half;
      break;
  }
  return b;
}

bool span(const Primitive& p, const Ray& ray, float& t_in, float& t_out) {
  float t0 = -kInf, t1 = kInf;
  switch (p.shape) {
    case Shape::kBox: {
      Eigen::Vector3f o, d;
      toLocal(p, ray, o, d);
      for (int k = 0; k < 3; ++k) {
        if (!slab(o[k], d[k], -p.half[k], p.half[k], t0, t1)) return false;
      }
      break;
    }
    case Shape::kCylinder: {
      const float ox = ray.o.x() - p.centre.x(), oy = ray.o.y() - p.centre.y();
      const float a = ray.d.x() * ray.d.x() + ray.d.y() * ray.d.y();
      const float r2 = p.half.x() * p.half.x();
      if (a == 0.0f) {  // vertical ray: inside the disc or never
        if (ox * ox + oy * oy > r2) return false;
      } else if (!quadratic(a, ox * ray.d.x() + oy * ray.d.y(), ox * ox + oy * oy - r2, t0, t1)) {
        return false;
      }
      if (!slab(ray.o.z(), ray.d.z(), p.centre.z(), p.centre.z() + p.half.z(), t0, t1)) return false;
      break;
    }
    case Shape::kEllipsoid: {
      const Eigen::Vector3f o = (ray.o - p.centre).cwiseQuotient(p.half);
      const Eigen::Vector3f d = ray.d.cwiseQuotient(p.half);
      if (!quadratic(d.squaredNorm(), o.dot(d), o.squaredNorm() - 1.0f, t0, t1)) return false;
      break;
    }
  }
  if (t1 < 0.0f) return false;
  t_in = t0;
  t_out = t1;
  return true;
}

bool intersect(const Primitive& p, const Ray& ray, float t_min, float t_max, double u, float& t) {
  float t_in, t_out;
  if (!span(p, ray, t_in, t_out)) return false;
  float hit;
  if (p.porous()) {
    const float depth = static_cast<float>(-std::log1p(-u)) * p.mean_free_path / ray.d.norm();
    hit = std::max(t_in, t_min) + depth;
    if (hit > t_out) return false;
  } else {
    hit = t_in > t_min ? t_in : t_out;
  }
  if (hit <= t_min || hit > t_max) return false;
  t = hit;
  return true;
}

Eigen::Vector3f normalAt(const Primitive& p, const Eigen::Vector3f& x) {
  switch (p.shape) {
    case Shape::kBox: {
      const Eigen::Vector3f r = x - p.centre;
      const Eigen::Vector3f l(p.cos_yaw * r.x() + p.sin_yaw * r.y(), -p.sin_yaw * r.x() + p.cos_yaw * r.y(), r.z());
      int axis = 0;
      float best = -1.0f;
      for (int k = 0; k < 3; ++k) {
        const float v = std::abs(l[k]) / p.half[k];
        if (v > best) {
          best = v;
          axis = k;
        }
      }
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      n[axis] = l[axis] >= 0.0f ? 1.0f : -1.0f;
      return Eigen::Vector3f(p.cos_yaw * n.x() - p.sin_yaw * n.y(), p.sin_yaw * n.x() + p.cos_yaw * n.y(), n.z());
    }
    case Shape::kCylinder: {
      const Eigen::Vector3f r = x - p.centre;
      const float radial = std::hypot(r.x(), r.y()) / p.half.x();
      const float cap = std::max(-r.z(), r.z() - p.half.z());  // > 0 beyond a cap plane
      if (radial < 1.0f - 1e-3f || cap > -1e-4f) return Eigen::Vector3f(0, 0, r.z() < 0.5f * p.half.z() ? -1 : 1);
      return Eigen::Vector3f(r.x(), r.y(), 0.0f).normalized();
    }
    case Shape::kEllipsoid:
      return (x - p.centre).cwiseQuotient(p.half.cwiseProduct(p.half)).normalized();
  }
  return Eigen::Vector3f::UnitZ();
}

}  // namespace sgtllc::sim
