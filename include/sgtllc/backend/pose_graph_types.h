/// @file pose_graph_types.h
/// @brief Plain data of a pose graph, shared by the back end (Ceres), the file formats and the evaluation.
///
/// Header-only and free of Ceres, so the file formats (`sgtllc::io`) can read and write graphs without the
/// optimiser. Frames are indexed 0..N−1 in sequence order.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sgtllc::backend {

/// 6×6 information matrix of a relative-pose constraint, over the tangent error (δt, δθ): translation in metres
/// first, then the rotation vector in radians, of Δ = T_from_to⁻¹ · T_world_from⁻¹ · T_world_to (a right
/// perturbation, in the `to` frame; g2o's EDGE_SE3 error has the same Δ). (g2o's EDGE_SE3:QUAT uses the
/// quaternion's vector part ≈ δθ / 2 instead; the g2o writer converts.)
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// What produced a constraint.
enum class EdgeKind {
  kOdometry,  ///< between consecutive frames, from the odometry
  kLoop,      ///< from the loop detector's verification
};

/// A relative-pose constraint between two frames: p_from = T_from_to · p_to.
/// A detected loop (query q revisits match m, `T_match_query`) is the edge from = m, to = q.
struct Edge {
  int from = 0;
  int to = 0;
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();
  Matrix6d information = Matrix6d::Identity();
  EdgeKind kind = EdgeKind::kOdometry;
};

/// A pose graph: one pose per frame (T_world_frame: p_world = T · p_frame) and its constraints.
struct PoseGraph {
  std::vector<Eigen::Isometry3d> poses;
  std::vector<Edge> edges;
};

}  // namespace sgtllc::backend
