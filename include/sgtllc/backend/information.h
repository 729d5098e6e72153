/// @file information.h
/// @brief Information matrices of odometry and loop edges (model in docs/backend.md).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sgtllc/config/backend_config.h"
#include "sgtllc/backend/pose_graph_types.h"
#include "sgtllc/types.h"
#include "sgtllc/verification.h"

namespace sgtllc::backend {

/// Information of an odometry step T_prev_curr: diagonal, from the distance and angle moved (OdometryNoise).
Matrix6d odometryInformation(const Eigen::Isometry3d& T_prev_curr, const OdometryNoise& noise);

/// Odometry edges i → i+1 of a trajectory of odometry poses (T_world_frame), with odometryInformation.
std::vector<Edge> odometryEdges(const std::vector<Eigen::Isometry3d>& odometry, const OdometryNoise& noise);

/// A pose graph of an odometry trajectory: initial poses = odometry, edges = odometryEdges. Loops are added after.
PoseGraph odometryGraph(const std::vector<Eigen::Isometry3d>& odometry, const OdometryNoise& noise);

/// Information of a loop fitted to n ≥ 3 inlier pairs (query centre s_i, match centre d_i) with pose
/// T_match_query = (R, t), over the edge error of pose_graph_types.h (match → query, perturbation in the query
/// frame). The fit residuals r_i = R s_i + t − d_i give the per-axis noise estimate
///   σ² = max(sigma_min², Σ‖r_i‖² / max(1, 3n − 6))
/// and the Gauss-Newton information of the point-to-point fit is
///   Ω = information_scale / σ² · Σ_i [ I  −[s_i]× ; [s_i]×  −[s_i]×² ]
/// (translation block n/σ², rotation block ≈ n·spread²/σ² about each axis). Throws sgtllc::Error if n < 3, the
/// sizes differ or the centres are collinear (Ω singular).
Matrix6d loopInformation(const std::vector<Eigen::Vector3d>& query_centres,
                         const std::vector<Eigen::Vector3d>& match_centres, const Eigen::Isometry3d& T_match_query,
                         const LoopNoise& noise);

/// The same from a detector match: the RANSAC inliers of @p match, with the node centres it indexes.
Matrix6d loopInformation(const MatchResult& match, const std::vector<Node>& query_nodes,
                         const std::vector<Node>& match_nodes, const LoopNoise& noise);

/// A loop edge (from = match frame, to = query frame) of a verified detector match, with loopInformation.
Edge loopEdge(int match_frame, int query_frame, const MatchResult& match, const std::vector<Node>& query_nodes,
              const std::vector<Node>& match_nodes, const LoopNoise& noise);

}  // namespace sgtllc::backend
