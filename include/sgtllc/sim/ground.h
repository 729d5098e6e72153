/// @file ground.h
/// @brief The ground: a smooth height field with gentle slopes, and a raster of ground zones (road, sidewalk, …).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/sim/geometry.h"

namespace sgtllc::sim {

/// Height field z = Σ a_k sin(w_k · (x, y) + φ_k): a few long waves, so slopes stay gentle everywhere.
class GroundHeight {
 public:
  GroundHeight() = default;
  /// @p amplitude scales every wave (m); waves of 90–420 m wavelength, directions and phases from @p seed.
  GroundHeight(uint64_t seed, double amplitude);

  double height(double x, double y) const { return evaluate(x, y, nullptr); }
  Eigen::Vector2d gradient(double x, double y) const;
  /// Height at (x, y), and its gradient if @p gradient is not null (one pass over the waves).
  double evaluate(double x, double y, Eigen::Vector2d* gradient) const;
  /// Upper bound of |∇z| over the plane.
  double maxSlope() const { return max_slope_; }
  /// First crossing of the ray with the ground in (0, t_max]; false if none (or the origin is underground).
  /// Downward rays steeper than the steepest slope have exactly one crossing, found by safeguarded Newton steps.
  /// Flatter rays advance by steps that cannot skip a crossing (sphere tracing with the slope bound) until a
  /// Newton step lands below the ground and brackets a crossing; a ray that only grazes a crest is a miss.
  /// @p gradient, if given, receives the ground's gradient at the crossing.
  bool intersect(const Ray& ray, float t_max, float& t, Eigen::Vector2d* gradient = nullptr) const;

 private:
  struct Wave {
    double a = 0.0, wx = 0.0, wy = 0.0, phase = 0.0;
  };
  std::array<Wave, 4> waves_{};
  double max_slope_ = 0.0;
};

/// What covers the ground at a place. The order is the priority when zones of two roads overlap (lower wins).
enum class Zone : uint8_t {
  kRoad = 0,
  kParking,   ///< parking lane along the road
  kVerge,     ///< grass strip between kerb and sidewalk
  kSidewalk,
  kLot,       ///< private land not yet assigned (becomes kLawn or kPaved)
  kLawn,      ///< grass in yards and parks
  kPaved,     ///< paved yards, forecourts
  kField,     ///< open land far from streets
  kCount
};

/// SemanticKITTI raw id of the ground in a zone (road 40, parking 44, sidewalk 48, terrain 72).
uint16_t groundSemantic(Zone zone);
/// Typical reflectivity (0..1) of the ground in a zone.
float groundReflectivity(Zone zone);

/// A raster of zones over a rectangle; outside it every place is @p outside.
class ZoneMap {
 public:
  ZoneMap() = default;
  ZoneMap(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double cell, Zone fill, Zone outside);

  Zone at(double x, double y) const {
    const double fx = (x - lo_.x()) * inv_cell_, fy = (y - lo_.y()) * inv_cell_;
    // Range test before converting: a far or non-finite coordinate must not reach the (undefined) cast to long.
    if (!(x >= lo_.x() && y >= lo_.y() && fx < static_cast<double>(nx_) && fy < static_cast<double>(ny_))) {
      return outside_;
    }
    return static_cast<Zone>(cells_[static_cast<size_t>(static_cast<long>(fy) * nx_ + static_cast<long>(fx))]);
  }
  /// Sets every cell whose centre lies within @p radius of the segment a–b to @p zone if @p zone has priority
  /// (a lower value) over the cell's current zone.
  void paintSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double radius, Zone zone);
  /// Calls f(cell_x, cell_y, zone&) for every cell (row by row).
  template <typename F>
  void forEach(F&& f) {
    for (long iy = 0; iy < ny_; ++iy) {
      for (long ix = 0; ix < nx_; ++ix) {
        Zone z = static_cast<Zone>(cells_[static_cast<size_t>(iy * nx_ + ix)]);
        f(lo_.x() + (ix + 0.5) * cell_, lo_.y() + (iy + 0.5) * cell_, z);
        cells_[static_cast<size_t>(iy * nx_ + ix)] = static_cast<uint8_t>(z);
      }
    }
  }
  const Eigen::Vector2d& lo() const { return lo_; }
  Eigen::Vector2d hi() const { return lo_ + cell_ * Eigen::Vector2d(nx_, ny_); }

 private:
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  double cell_ = 1.0, inv_cell_ = 1.0;
  long nx_ = 0, ny_ = 0;
  Zone outside_ = Zone::kField;
  std::vector<uint8_t> cells_;
};

}  // namespace sgtllc::sim
