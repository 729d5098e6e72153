/// @file thinning.h
/// @brief Which frames of a new session add to a map (docs/sessions.md, "A map that does not grow with revisits").
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/map/map.h"

namespace sgtllc::map {

/// The thinning rule's parameters (backend.sessions.keep_*; docs/sessions.md).
struct ThinningRule {
  double distance_m = 3.0;   ///< a map frame this near ...
  double heading_deg = 45.0; ///< ... facing within this of a session frame covers it; distance ≤ 0 keeps all
  /// A frame the map covers but did not recognise joins only while its covering map frames come from fewer than
  /// this many drives (sessions): a place the detector keeps missing gains a view, not one per drive.
  int max_covering_sessions = 2;
};

/// The session (drive) of each frame of @p map: the index in map.sessions, or 0 for every frame of a map that lists
/// no sessions (one drive).
std::vector<int> frameSessions(const Map& map);

/// For each session frame (its pose T_world_frame in the map's world, @p frames), whether it adds to a map whose
/// frames are at @p map_poses, each from drive @p map_session[i] (empty: all one drive). A frame that no map frame
/// covers (a street the map lacks, or one it has only facing another way) joins. A covered frame joins only if the
/// map did not recognise it (@p recognised: its inter-session loop was accepted; a miss, or a changed place) and its
/// covering frames (among the 32 nearest map frames) come from fewer than rule.max_covering_sessions drives.
/// Deterministic: a function of the poses, the drives and the decisions alone.
std::vector<bool> framesThatAdd(const std::vector<Eigen::Matrix4d>& map_poses, const std::vector<int>& map_session,
                                const std::vector<Eigen::Isometry3d>& frames, const std::vector<bool>& recognised,
                                const ThinningRule& rule);

}  // namespace sgtllc::map
