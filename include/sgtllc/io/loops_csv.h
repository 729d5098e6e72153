/// @file loops_csv.h
/// @brief The loops CSV that `sgtllc run --out` writes, and its reader for the back end and the evaluation.
///
/// One header line, then one loop per line:
/// `query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz`
/// where query and match are frame names (file stems such as `004501`), score is the verification score s_t,
/// score_c the consistency score, and the twelve numbers the row-major 3×4 T_match_query (maps points of the query
/// scan into the match scan's LiDAR frame), written `%.6f`.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/backend/pose_graph_types.h"

namespace sgtllc::io {

/// One detected loop: the query frame revisits the match frame.
struct LoopRecord {
  std::string query;  ///< frame name of the query (the later frame)
  std::string match;  ///< frame name of the matched earlier frame
  int query_index = -1;  ///< position of the query in the sequence (set by readLoopsCsv; unused by the writer)
  int match_index = -1;  ///< position of the match in the sequence (set by readLoopsCsv; unused by the writer)
  double score = 0.0;    ///< verification score s_t
  double score_c = 0.0;  ///< consistency score
  Eigen::Matrix4d T_match_query = Eigen::Matrix4d::Identity();
};

/// The CSV column names, in order (the header line joins them with commas).
const std::vector<std::string>& loopsCsvColumns();

/// The CSV text of @p loops (header included).
std::string loopsCsvText(const std::vector<LoopRecord>& loops);

/// Reads a loops CSV and maps its frame names to positions in @p frame_names (the sequence's frames in order).
/// Empty lines are skipped. Throws sgtllc::Error naming the file, the line and the problem: a header other than
/// loopsCsvColumns(), a row without 16 columns, a number that is not finite, a rotation that is not orthonormal
/// within 1e-3, a frame name not in @p frame_names (`loops.csv:3: unknown query frame '009999' (not one of the
/// sequence's 4541 frames)`), or a loop of a frame with itself.
std::vector<LoopRecord> readLoopsCsv(const std::string& path, const std::vector<std::string>& frame_names);

/// Pose-graph edges of @p loops (indices from readLoopsCsv): from = match, to = query, T_from_to = T_match_query
/// with its rotation projected onto SO(3) (the CSV's six decimals leave it orthonormal to ~1e-6 only), the given
/// @p information and kind kLoop.
std::vector<backend::Edge> loopEdges(const std::vector<LoopRecord>& loops, const backend::Matrix6d& information);

}  // namespace sgtllc::io
