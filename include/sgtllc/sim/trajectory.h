/// @file trajectory.h
/// @brief From a route to sensor poses at 10 Hz: a smoothed path, a speed profile of 5–15 m/s that slows for
///        turns, and the ground's slope plus a little body motion as pitch and roll.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/sim/route.h"
#include "sgtllc/sim/world.h"

namespace sgtllc::sim {

struct TrajectoryConfig {
  int frames = 100;
  double period = 0.1;          ///< s between frames (10 Hz)
  double sensor_height = 1.73;  ///< m above the ground (KITTI's Velodyne)
  double speed_min = 6.0, speed_max = 11.0;  ///< cruise speeds of legs (m/s); overall speeds stay in 5–15 m/s
  uint64_t seed = 1;
};

/// The sensor at one frame.
struct FramePose {
  double time = 0.0;                                        ///< s since frame 0
  Eigen::Matrix4d T_world_lidar = Eigen::Matrix4d::Identity();  ///< LiDAR frame (x forward, z up) in the world
  double speed = 0.0;                                       ///< m/s
  int leg = 0;                                              ///< index of the route leg being driven
  VisitKind kind = VisitKind::kExplore;
};

/// Poses along the route; fewer than config.frames if the route ends first.
std::vector<FramePose> driveRoute(const World& world, const std::vector<Leg>& legs, const TrajectoryConfig& config);

}  // namespace sgtllc::sim
