#include "sgtllc/sim/ground.h"

#include <algorithm>
#include <cmath>

#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {

GroundHeight::GroundHeight(uint64_t seed, double amplitude) {
  Rng rng(seed, Stream::kGround);
  // Wavelengths (m) and relative amplitudes: slope of one wave = 2π a / λ.
  const std::array<double, 4> lambda = {420.0, 260.0, 150.0, 90.0};
  const std::array<double, 4> rel = {1.0, 0.55, 0.22, 0.08};
  max_slope_ = 0.0;
  for (size_t k = 0; k < waves_.size(); ++k) {
    const double dir = rng.uniform(0.0, 2.0 * M_PI);
    const double w = 2.0 * M_PI / lambda[k];
    waves_[k] = Wave{amplitude * rel[k] * rng.uniform(0.7, 1.0), w * std::cos(dir), w * std::sin(dir),
                     rng.uniform(0.0, 2.0 * M_PI)};
    max_slope_ += std::abs(waves_[k].a) * w;
  }
}

double GroundHeight::evaluate(double x, double y, Eigen::Vector2d* gradient) const {
  double z = 0.0;
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  for (const Wave& w : waves_) {
    const double phase = w.wx * x + w.wy * y + w.phase;
    z += w.a * std::sin(phase);
    if (gradient) g += w.a * std::cos(phase) * Eigen::Vector2d(w.wx, w.wy);  // sin and cos fuse into sincos
  }
  if (gradient) *gradient = g;
  return z;
}

Eigen::Vector2d GroundHeight::gradient(double x, double y) const {
  Eigen::Vector2d g;
  evaluate(x, y, &g);
  return g;
}

bool GroundHeight::intersect(const Ray& ray, float t_max, float& t_out, Eigen::Vector2d* gradient_out) const {
  const Eigen::Vector3d o = ray.o.cast<double>(), d = ray.d.cast<double>();
  Eigen::Vector2d grad;
  // f(t): height of the ray above the ground; f'(t) from the same evaluation.
  auto f = [&](double t, double* slope) {
    const double v = o.z() + t * d.z() - evaluate(o.x() + t * d.x(), o.y() + t * d.y(), &grad);
    if (slope) *slope = d.z() - grad.dot(d.head<2>());
    return v;
  };
  constexpr double kTolerance = 1e-4;  // m
  auto finish = [&](double t) {
    t_out = static_cast<float>(t);
    if (gradient_out) *gradient_out = grad;
    return t_out > 0.0f;
  };
  // Safeguarded Newton from t inside a bracket with f(lo) > 0 ≥ f(hi) (hi unchecked while hi_known is false).
  auto refine = [&](double lo, double hi, bool hi_known, double t) {
    for (int it = 0; it < 60; ++it) {
      if (t >= hi && !hi_known) {
        if (f(hi, nullptr) > 0.0) return false;  // no crossing within reach
        hi_known = true;
      }
      if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
      double slope;
      const double v = f(t, &slope);
      if (std::abs(v) < kTolerance) break;
      (v > 0.0 ? lo : hi) = t;
      t = slope < 0.0 ? t - v / slope : 0.5 * (lo + hi);
    }
    return finish(t);
  };
  const double h = d.head<2>().norm();
  const double fastest_descent = max_slope_ * h - d.z();  // f falls by at most this much per unit t
  double slope;
  double f0 = f(0.0, &slope);
  if (f0 <= 0.0 || fastest_descent <= 0.0) return false;
  if (d.z() + max_slope_ * h < 0.0) {
    // f is strictly decreasing: one root, in [0, t_max] iff f(t_max) ≤ 0 (checked only if Newton gets that far).
    return refine(0.0, t_max, false, f0 / -slope);
  }
  // Shallow ray: steps of f / fastest_descent never pass a crossing. A Newton step that lands below the ground
  // brackets a crossing early (the ray may graze the ground long before it crosses it).
  double t = 0.0;
  for (int it = 0; it < 200; ++it) {
    if (slope < 0.0) {
      const double newton = std::min(t - f0 / slope, static_cast<double>(t_max));
      if (newton > t && f(newton, nullptr) <= 0.0) return refine(t, newton, true, newton);
    }
    t += f0 / fastest_descent;
    if (t > t_max) return false;
    f0 = f(t, &slope);
    if (f0 < kTolerance) return finish(t);
  }
  return false;  // still above ground after many steps: a grazing ray, treated as a miss
}

uint16_t groundSemantic(Zone zone) {
  switch (zone) {
    case Zone::kRoad: return 40;
    case Zone::kParking: return 44;
    case Zone::kSidewalk:
    case Zone::kPaved: return 48;
    case Zone::kVerge:
    case Zone::kLot:
    case Zone::kLawn:
    case Zone::kField:
    case Zone::kCount: break;
  }
  return 72;
}

float groundReflectivity(Zone zone) {
  switch (zone) {
    case Zone::kRoad: return 0.30f;
    case Zone::kParking: return 0.38f;
    case Zone::kSidewalk:
    case Zone::kPaved: return 0.45f;
    default: return 0.42f;
  }
}

ZoneMap::ZoneMap(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double cell, Zone fill, Zone outside)
    : lo_(lo), cell_(cell), inv_cell_(1.0 / cell), outside_(outside) {
  nx_ = std::max(1L, static_cast<long>(std::ceil((hi.x() - lo.x()) / cell)));
  ny_ = std::max(1L, static_cast<long>(std::ceil((hi.y() - lo.y()) / cell)));
  cells_.assign(static_cast<size_t>(nx_ * ny_), static_cast<uint8_t>(fill));
}

void ZoneMap::paintSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double radius, Zone zone) {
  const Eigen::Vector2d lo = a.cwiseMin(b).array() - radius, hi = a.cwiseMax(b).array() + radius;
  const long x0 = std::max(0L, static_cast<long>((lo.x() - lo_.x()) * inv_cell_));
  const long y0 = std::max(0L, static_cast<long>((lo.y() - lo_.y()) * inv_cell_));
  const long x1 = std::min(nx_ - 1, static_cast<long>((hi.x() - lo_.x()) * inv_cell_));
  const long y1 = std::min(ny_ - 1, static_cast<long>((hi.y() - lo_.y()) * inv_cell_));
  const Eigen::Vector2d ab = b - a;
  const double len2 = std::max(ab.squaredNorm(), 1e-12);
  const uint8_t value = static_cast<uint8_t>(zone);
  for (long iy = y0; iy <= y1; ++iy) {
    for (long ix = x0; ix <= x1; ++ix) {
      uint8_t& c = cells_[static_cast<size_t>(iy * nx_ + ix)];
      if (c <= value) continue;
      const Eigen::Vector2d p(lo_.x() + (ix + 0.5) * cell_, lo_.y() + (iy + 0.5) * cell_);
      const double s = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
      const double dist = (p - a - s * ab).norm();
      if (dist <= radius) c = value;
    }
  }
}

}  // namespace sgtllc::sim
