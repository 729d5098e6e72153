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

/// The same test for a session merged into a map (docs/sessions.md; `sgtllc run --map --add-false-loops F`):
/// round(@p fraction × the inter-session loops of @p loops) false inter-session loops (at least one if
/// @p fraction > 0 and there is one). Each takes the session frame of a random inter-session loop, which lies at that
/// loop's map frame, and ties it to a map frame more than @p min_distance metres from it by @p map_poses, with a
/// random relative pose (as falseLoops) and the information of that loop. Inter-session loops are those of
/// @p loops whose `from` is below the map's frame count (map_poses.size()); match names come from @p map_names.
/// Deterministic in @p seed. Throws sgtllc::Error if no map frame lies that far from a chosen one.
std::vector<pipeline::ClosingLoop> falseInterSessionLoops(const std::vector<Eigen::Isometry3d>& map_poses,
                                                          const std::vector<pipeline::ClosingLoop>& loops,
                                                          double fraction, uint64_t seed,
                                                          const std::vector<std::string>& map_names,
                                                          double min_distance = 50.0);

}  // namespace sgtllc::eval
