/// @file sensor.h
/// @brief LiDAR models: where the rays of one scan point and how a surface answers them.
///
/// - Velodyne HDL-64E: 64 beams from +2.0° to −24.8° (upper block 1/3° apart, lower block ~1/2°), about 0.17°
///   azimuth steps (2083 per turn), 120 m, 2 cm range noise; each turn starts at a random azimuth phase.
/// - Livox Mid-70: 70.4° circular field of view scanned by two counter-rotating prisms (a rosette that never
///   repeats), 100 000 points per second, i.e. 10 000 per 0.1 s scan, 90 m.
/// - Velodyne HDL-32E (nuScenes' LIDAR_TOP): 32 beams evenly from +10.67° to −30.67° (1.33° apart), 1,085 azimuth
///   steps per turn (0.33°; 32 × 1,085 = 34,720 rays, the size of a nuScenes scan), 70 m. It spins at 20 Hz; the
///   simulator still writes one turn per 0.1 s frame, as for the HDL-64, so that a sequence's route, length and
///   revisits do not depend on the sensor (the simulator models no motion within a turn).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::sim {

enum class SensorKind { kHdl64, kMid70, kHdl32 };

/// Parses "hdl64", "hdl32" or "mid70"; throws sgtllc::Error naming the value otherwise.
SensorKind parseSensorKind(const std::string& name);
const char* sensorName(SensorKind kind);

struct SensorConfig {
  SensorKind kind = SensorKind::kHdl64;
  int rows = 64;                ///< spinning sensor's beams used (fewer: evenly chosen among its 64 or 32; fast tests)
  int columns = 2083;           ///< spinning sensor's azimuth steps per turn (HDL-64: 360° / 0.1728°; HDL-32: 1,085)
  int points_per_scan = 10000;  ///< Mid-70 samples per scan (0.1 s at 100 kHz)
  double max_range = 120.0;     ///< m, for a bright target; dark or grazing surfaces return from less far
  double min_range = 0.9;       ///< m
  double range_noise = 0.02;    ///< m, 1σ
  double dropout = 0.04;        ///< chance that a return is lost at random (glass, spray, missed pulses)

  /// Defaults of a sensor kind (Mid-70: 90 m range; HDL-32: 32 rows, 1,085 columns, 70 m).
  static SensorConfig preset(SensorKind kind);
};

/// The ray pattern of a sensor. Rays are indexed column-major (all rows of column 0, then column 1, …); the
/// Mid-70 has one row and its columns are successive samples in time, so neighbouring indices are neighbouring
/// directions in both cases.
class SensorModel {
 public:
  explicit SensorModel(const SensorConfig& config);

  const SensorConfig& config() const { return config_; }
  int rows() const { return rows_; }
  int columns() const { return columns_; }
  int raysPerScan() const { return rows_ * columns_; }
  /// True if column 0 and the last column are neighbours (a full turn: the spinning sensors).
  bool wraps() const { return config_.kind != SensorKind::kMid70; }
  /// Unit directions (sensor frame: x forward, y left, z up) of the rays of raw scan @p scan.
  void directions(int64_t scan, uint64_t seed, std::vector<Eigen::Vector3f>& out) const;
  /// Beam elevations (deg, top first) of the spinning sensor's rows in use (empty for the Mid-70).
  const std::vector<double>& elevations() const { return elevations_; }

 private:
  SensorConfig config_;
  int rows_ = 0, columns_ = 0;
  std::vector<double> elevations_;
};

}  // namespace sgtllc::sim
