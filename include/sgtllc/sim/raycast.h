/// @file raycast.h
/// @brief One raw scan: every ray of the sensor cast against the ground, the static scene and the agents, with
///        range noise, dropout and intensity.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/sim/sensor.h"
#include "sgtllc/sim/world.h"

namespace sgtllc::sim {

/// Part keys of ground points have this bit set; other keys are (object << 16) | semantic id.
inline constexpr uint64_t kGroundPart = 1ull << 63;

/// The returns of one raw scan, in ray order (rays without a return are left out).
struct RawScan {
  std::vector<Eigen::Vector3f> points;  ///< sensor frame (m)
  std::vector<float> intensity;         ///< 0..0.99, in steps of 0.01 as KITTI's
  std::vector<uint16_t> semantic;       ///< true SemanticKITTI raw id
  std::vector<uint16_t> instance;       ///< true instance id (0 for stuff)
  std::vector<uint64_t> part;           ///< what the point lies on: one object's points of one class, or a ground patch
  std::vector<float> height;            ///< height above the ground below the point (m)
  std::vector<int32_t> ray;             ///< index of the ray that produced the point
  int rows = 0, columns = 0;            ///< ray grid (see SensorModel)
  bool wraps = false;
};

/// Casts raw scan @p scan of @p sensor from pose @p T_world_lidar at time @p time (s). Pure: the result depends only
/// on the arguments (the random stream is derived from seed and scan index).
RawScan castScan(const World& world, const SensorModel& sensor, const Eigen::Matrix4d& T_world_lidar, double time,
                 int64_t scan, uint64_t seed);

}  // namespace sgtllc::sim
