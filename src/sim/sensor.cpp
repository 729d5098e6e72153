#include "sgtllc/sim/sensor.h"

#include <cmath>

#include "sgtllc/sim/rng.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;
// Mid-70 prism rotation rates (Hz): an irrational ratio, so the rosette never repeats; ~21 petals per 0.1 s.
constexpr double kPrismHz1 = 123.4567, kPrismHz2 = -87.3209;
constexpr double kMid70HalfFov = 35.2;      // deg
constexpr double kMid70Rate = 100000.0;     // points per second

/// The 64 HDL-64E elevations (deg): upper block +2.0 … −8.33 in 1/3° steps, lower block −8.83 … −24.8.
std::vector<double> hdl64Elevations() {
  std::vector<double> e;
  for (int k = 0; k < 32; ++k) e.push_back(2.0 - k * (10.33 / 31.0));
  for (int k = 0; k < 32; ++k) e.push_back(-8.83 - k * (15.97 / 31.0));
  return e;
}

/// The 32 HDL-32E elevations (deg): +10.67 … −30.67 in equal steps of 41.34° / 31 ≈ 1.33°.
std::vector<double> hdl32Elevations() {
  std::vector<double> e;
  for (int k = 0; k < 32; ++k) e.push_back(10.67 - k * (41.34 / 31.0));
  return e;
}

}  // namespace

SensorKind parseSensorKind(const std::string& name) {
  if (name == "hdl64") return SensorKind::kHdl64;
  if (name == "hdl32") return SensorKind::kHdl32;
  if (name == "mid70") return SensorKind::kMid70;
  throw Error("unknown sensor '" + name + "' (expected hdl64, hdl32 or mid70)");
}

const char* sensorName(SensorKind kind) {
  switch (kind) {
    case SensorKind::kHdl64: return "hdl64";
    case SensorKind::kHdl32: return "hdl32";
    case SensorKind::kMid70: break;
  }
  return "mid70";
}

SensorConfig SensorConfig::preset(SensorKind kind) {
  SensorConfig c;
  c.kind = kind;
  if (kind == SensorKind::kMid70) c.max_range = 90.0;
  if (kind == SensorKind::kHdl32) {
    c.rows = 32;
    c.columns = 1085;
    c.max_range = 70.0;
  }
  return c;
}

SensorModel::SensorModel(const SensorConfig& config) : config_(config) {
  if (config.kind != SensorKind::kMid70) {
    const std::vector<double> all = config.kind == SensorKind::kHdl64 ? hdl64Elevations() : hdl32Elevations();
    const int beams = static_cast<int>(all.size());
    if (config.rows < 1 || config.rows > beams) {
      throw Error("sensor rows must be 1.." + std::to_string(beams) + ", not " + std::to_string(config.rows));
    }
    if (config.columns < 8) throw Error("sensor columns must be at least 8, not " + std::to_string(config.columns));
    for (int r = 0; r < config.rows; ++r) {
      const long at = config.rows == 1 ? 0 : std::lround(r * (beams - 1.0) / (config.rows - 1));
      elevations_.push_back(all[static_cast<size_t>(at)]);
    }
    rows_ = config.rows;
    columns_ = config.columns;
  } else {
    if (config.points_per_scan < 1) {
      throw Error("sensor points per scan must be positive, not " + std::to_string(config.points_per_scan));
    }
    rows_ = 1;
    columns_ = config.points_per_scan;
  }
}

void SensorModel::directions(int64_t scan, uint64_t seed, std::vector<Eigen::Vector3f>& out) const {
  out.resize(static_cast<size_t>(raysPerScan()));
  if (wraps()) {
    const double step = 2.0 * M_PI / columns_;
    // Each turn starts at its own azimuth, as a free-running spinning sensor does.
    const double phase = step * hashUniform(hashWords(seed, static_cast<uint64_t>(Stream::kScan), scan, 1));
    std::vector<double> ce(rows_), se(rows_);
    for (int r = 0; r < rows_; ++r) {
      ce[r] = std::cos(elevations_[r] * kDeg);
      se[r] = std::sin(elevations_[r] * kDeg);
    }
    for (int c = 0; c < columns_; ++c) {
      // Start behind the vehicle and turn counter-clockwise, as KITTI's scans do.
      const double az = -M_PI + phase + c * step;
      const double ca = std::cos(az), sa = std::sin(az);
      for (int r = 0; r < rows_; ++r) {
        out[static_cast<size_t>(c * rows_ + r)] =
            Eigen::Vector3d(ce[r] * ca, ce[r] * sa, se[r]).cast<float>();
      }
    }
    return;
  }
  // Mid-70: the sum of two rotating deflections of equal size gives the rosette; time runs on across scans.
  const double a = 0.5 * kMid70HalfFov * kDeg;
  for (int k = 0; k < columns_; ++k) {
    const double t = (static_cast<double>(scan) * columns_ + k) / kMid70Rate;
    const double u = a * (std::cos(2 * M_PI * kPrismHz1 * t) + std::cos(2 * M_PI * kPrismHz2 * t + 1.0));
    const double v = a * (std::sin(2 * M_PI * kPrismHz1 * t) + std::sin(2 * M_PI * kPrismHz2 * t + 1.0));
    const double polar = std::hypot(u, v), around = std::atan2(v, u);
    out[static_cast<size_t>(k)] =
        Eigen::Vector3d(std::cos(polar), std::sin(polar) * std::cos(around), std::sin(polar) * std::sin(around))
            .cast<float>();
  }
}

}  // namespace sgtllc::sim
