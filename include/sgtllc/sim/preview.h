/// @file preview.h
/// @brief Bird's-eye-view PNGs of a simulated sequence: one scan coloured by class, and the trajectory with its
///        revisits and loop queries over the road network.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/io/output_file.h"
#include "sgtllc/sim/loop_pairs.h"
#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {

/// SemanticKITTI class name of a raw id the simulator emits ("road", "traffic-sign", …; "other" if unknown).
const char* semanticName(uint16_t id);

/// Points within 50 m of the sensor, seen from above, in SemanticKITTI's colours with a legend of the classes.
void writeScanPreview(const std::string& path, const SimFrame& frame, const std::string& title,
                      io::Overwrite overwrite = io::Overwrite::kReplace);

/// The route in the frame of frame 0 (@p lidar_poses: T_lidar0_lidari) over the roads, revisit legs coloured by
/// kind, frames that have a loop candidate within 3 m marked.
void writeTrajectoryPreview(const std::string& path, const Simulator& sim,
                            const std::vector<Eigen::Matrix4d>& lidar_poses, const std::vector<LoopPair>& pairs,
                            io::Overwrite overwrite = io::Overwrite::kReplace);

}  // namespace sgtllc::sim
