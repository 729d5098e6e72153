/// @file session_merge.h
/// @brief A new session's trajectory placed in a prior map's frame (docs/sessions.md): one pose graph of the map's
///        poses, held fixed, and the session's odometry, joined by the inter-session loops, with the outlier step
///        of pose_graph_optimizer.h over every loop.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/backend/pose_graph_optimizer.h"
#include "sgtllc/config/backend_config.h"

namespace sgtllc::backend {

/// The graph's frames: map frames 0..M−1, then session frames M..M+N−1 (session frame i is M + i). A loop whose
/// `from` is a map frame and `to` a session frame is an inter-session loop; one between two session frames an
/// intra-session loop (from < to or not); a loop between two map frames is refused.
struct SessionGraph {
  std::vector<Eigen::Isometry3d> map_poses;  ///< T_world_frame of the map's frames, the map's world; held fixed
  std::vector<Eigen::Isometry3d> odometry;   ///< the session's odometry poses, in its own frame (any start)
  std::vector<Edge> loops;                   ///< inter- and intra-session loops, in the order found
};

/// What came of the merge.
struct SessionMerge {
  /// The session's poses: in the map's world when `placed`, else its odometry optimised with its own loops alone,
  /// in the odometry's frame. `loops` has a decision per loop of SessionGraph::loops, in order; poses are the
  /// session's (N), not the map's.
  BackendResult result;
  /// At least backend.sessions.min_inter_loops mutually consistent inter-session loops were accepted, so the
  /// session is tied to the map.
  bool placed = false;
  int inter_loops = 0;     ///< inter-session loops given
  int inter_accepted = 0;  ///< of them accepted
  /// The session's odometry frame in the map's world that the solve started from: the first accepted
  /// inter-session loop of the largest consistent set (identity unless placed).
  Eigen::Isometry3d T_world_odometry = Eigen::Isometry3d::Identity();
};

/// Merges @p graph: (1) the largest consistent set of the inter-session loops, each pair checked around the cycle
/// through the map's poses and the session's odometry, and that of the intra-session loops (checked as in one
/// drive; an inter- and an intra-session loop share no cycle and do not constrain each other); (2) with at least
/// config.sessions.min_inter_loops inter-session loops kept, the session is started at the first of them and solved with the
/// map's poses fixed; (3) the residual check, as PoseGraphOptimizer. Fewer: the session is solved alone (not
/// placed) and every inter-session loop is rejected as inconsistent. Throws sgtllc::Error for an empty session, a
/// loop naming a frame outside the graph, joining two map frames or a frame to itself, or an invalid @p config.
SessionMerge mergeSession(const SessionGraph& graph, const BackendConfig& config);

}  // namespace sgtllc::backend
