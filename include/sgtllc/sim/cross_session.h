/// @file cross_session.h
/// @brief Cross-session ground truth of a second session: for each of its frames, the nearest frame of the first
///        session and how far it is (docs/relocalization.md).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/io/output_file.h"

namespace sgtllc::sim {

/// File name of the cross-session ground truth inside a second session's folder.
inline constexpr const char* kCrossSessionName = "cross_session.txt";

/// The first-session frame nearest to one second-session frame.
struct NearestFrame {
  int frame = -1;         ///< index into the first session (−1 if it has no frames)
  double distance = 0.0;  ///< m, 3-D between LiDAR positions
};

/// For every query position, the nearest map position (ties to the lower index), exactly, through a grid of
/// @p cell metre squares searched ring by ring.
std::vector<NearestFrame> nearestFrames(const std::vector<Eigen::Vector3d>& map,
                                        const std::vector<Eigen::Vector3d>& queries, double cell = 10.0);

/// Writes `%06d %06d %.3f` lines (second-session frame, nearest first-session frame, distance in m).
void writeCrossSession(const std::string& path, const std::vector<NearestFrame>& nearest, io::Overwrite overwrite);

}  // namespace sgtllc::sim
