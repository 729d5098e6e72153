/// @file g2o.h
/// @brief Pose graphs as g2o text files (VERTEX_SE3:QUAT, EDGE_SE3:QUAT, FIX), as read by g2o_viewer, g2o,
///        GTSAM's readG2o and most pose-graph tools.
///
/// Lines written:
/// ```
/// VERTEX_SE3:QUAT id x y z qx qy qz qw          one per pose, id = frame index, T_world_frame
/// FIX 0                                          the first pose is held fixed (gauge)
/// EDGE_SE3:QUAT i j x y z qx qy qz qw I11 I12 … I16 I22 … I66   T_i_j and the upper triangle of the information
/// ```
/// Information convention: our backend::Edge information is over (δt, δθ) with δθ the rotation vector; g2o's
/// EDGE_SE3:QUAT error is (δt, q_v), the vector part of the error quaternion, which is δθ/2 to first order. With
/// e_ours = J · e_g2o, J = diag(I₃, 2·I₃), the same χ² needs Ω_g2o = Jᵀ · Ω_ours · J: the rotation block ×4 and the
/// translation–rotation blocks ×2. The writer applies this and the reader undoes it, so a graph read back has our
/// convention again and g2o / GTSAM weigh the constraints as our optimiser does.
#pragma once

#include <string>
#include <vector>

#include "sgtllc/backend/pose_graph_types.h"
#include "sgtllc/io/output_file.h"

namespace sgtllc::io {

/// Information over (δt, δθ) (ours) → over (δt, q_v) (g2o EDGE_SE3:QUAT), and back.
backend::Matrix6d informationToG2o(const backend::Matrix6d& ours);
backend::Matrix6d informationFromG2o(const backend::Matrix6d& g2o);

/// The g2o text of @p graph: every pose as a vertex, `FIX 0` if there is a pose, every edge. Numbers are written in
/// their shortest exact form. Quaternions have qw ≥ 0.
std::string g2oText(const backend::PoseGraph& graph);

/// Only the edges of @p edges as EDGE_SE3:QUAT lines, no vertices: the loop list for users who add our loops to
/// their own graph (GTSAM's readG2o and g2o read edge-only files; evo has no relative-pose format).
std::string g2oEdgesText(const std::vector<backend::Edge>& edges);

/// Writes g2oText / g2oEdgesText atomically (temporary file + rename). Replaces an existing file: deciding whether
/// that is allowed (--force) is the caller's job. Throws sgtllc::Error `cannot write PATH: REASON`.
void writeG2o(const std::string& path, const backend::PoseGraph& graph,
              Overwrite overwrite = Overwrite::kReplace);
void writeG2oEdges(const std::string& path, const std::vector<backend::Edge>& edges,
                   Overwrite overwrite = Overwrite::kReplace);

/// Reads a g2o file of VERTEX_SE3:QUAT, EDGE_SE3:QUAT and FIX lines (empty and `#` lines are skipped). Vertex ids
/// must be 0..N−1, each once (in any order); edges must join two of them, unless the file has no vertices at all
/// (an edge list, as g2oEdgesText writes: ids ≥ 0). The information is converted back to (δt, δθ) and must be
/// symmetric positive semi-definite with a finite, non-negative diagonal. An edge between consecutive ids
/// (j = i + 1) is kOdometry, any other kLoop (g2o files do not say). Throws sgtllc::Error
/// naming the file, the line and the problem (unknown tag, wrong number of values, non-finite value, zero
/// quaternion, duplicate or missing vertex id, edge to a missing vertex).
backend::PoseGraph readG2o(const std::string& path);

}  // namespace sgtllc::io
