/// @file thinning.h
/// @brief Which frames of a new session add to a map (docs/sessions.md, "A map that does not grow with revisits").
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace sgtllc::map {

/// For each session frame (its pose T_world_frame in the map's world, @p frames), whether it adds to a map whose
/// frames are at @p map_poses: it does unless the map recognised it (@p recognised: its inter-session loop was
/// accepted) and a map frame lies within @p distance_m of it with a forward axis within @p heading_deg of its own.
/// A place the map did not recognise from there (the place changed, or the view is new) and a place it does not
/// cover are kept. @p distance_m ≤ 0 keeps every frame. Deterministic: a function of the poses alone.
std::vector<bool> framesThatAdd(const std::vector<Eigen::Matrix4d>& map_poses,
                                const std::vector<Eigen::Isometry3d>& frames, const std::vector<bool>& recognised,
                                double distance_m, double heading_deg);

}  // namespace sgtllc::map
