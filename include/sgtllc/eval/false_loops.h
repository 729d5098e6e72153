/// @file false_loops.h
/// @brief The back end's robustness test (docs/backend.md, "Outlier step"; `sgtllc optimize --add-false-loops F
///        --seed S`): false loops between frames far apart, to check that the back end rejects them and that the
///        corrected trajectory does not move.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sgtllc/pipeline/loop_edge.h"

namespace sgtllc::eval {

/// round(@p fraction × real loops) false loops (at least one if @p fraction > 0): random frame pairs a < b whose
/// odometry positions are more than @p min_distance metres apart, each with a random relative pose (yaw in
/// [−π, π), translation within ±10 m horizontally and ±1 m vertically) and the information of a random real loop
/// (the nominal one if there are none), so they weigh like real loops. Deterministic in @p seed. Throws
/// sgtllc::Error if no two frames are that far apart. Frame names come from @p frame_names.
std::vector<pipeline::ClosingLoop> falseLoops(const std::vector<Eigen::Isometry3d>& odometry,
                                              const std::vector<pipeline::ClosingLoop>& real, double fraction,
                                              uint64_t seed, const std::vector<std::string>& frame_names,
                                              const backend::LoopNoise& noise, double min_distance = 50.0);

}  // namespace sgtllc::eval
