/// @file loops_csv.h
/// @brief The loops CSV that `sgtllc run --out` writes, and its reader for the back end and the evaluation.
///
/// One header line, then one loop per line:
/// `query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz`
/// where query and match are frame names (file stems such as `004501`), score is the loop score,
/// score_c the consistency score, and the twelve numbers the row-major 3×4 T_match_query (maps points of the query
/// scan into the match scan's LiDAR frame), written `%.6f`. A frame name holding a comma, a double quote, CR or LF
/// is quoted as RFC 4180 says (csv.h); the reader accepts that quoting, newlines inside quotes included.
///
/// Optionally (`sgtllc run` writes it) 21 more columns `i11,i12,…,i16,i22,…,i66`: the upper triangle, row by row, of
/// the loop's 6×6 information matrix over (δt, δθ) (pose_graph_types.h), in shortest exact form, so `sgtllc
/// optimize` weighs each loop as `run` did. All 21 are empty for a loop without information (its inlier centres
/// were collinear); readers then use a nominal model. The 16-column form stays valid.
#pragma once

#include <optional>
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
  double score = 0.0;    ///< the loop score
  double score_c = 0.0;  ///< consistency score
  Eigen::Matrix4d T_match_query = Eigen::Matrix4d::Identity();
  /// Information of the loop edge over (δt, δθ), if known (written and read with the information columns).
  std::optional<backend::Matrix6d> information;
};

/// The CSV column names, in order (the header line joins them with commas).
const std::vector<std::string>& loopsCsvColumns();
/// The 21 optional information columns `i11` … `i66` that follow loopsCsvColumns().
const std::vector<std::string>& loopsCsvInformationColumns();

/// The CSV text of @p loops (header included); with @p with_information, the 37-column form (loops without
/// information get 21 empty fields).
std::string loopsCsvText(const std::vector<LoopRecord>& loops, bool with_information = false);

/// Reads a loops CSV and maps its frame names to positions in @p frame_names (the sequence's frames in order).
/// Empty lines are skipped. Both forms are read (16 columns, or 37 with the information). Throws sgtllc::Error
/// naming the file, the line and the problem: a header other than the two forms', a row with another column count,
/// information fields that are neither all empty nor all finite with a non-negative diagonal, a number that is
/// not finite, a rotation that is not orthonormal within 1e-3, a frame name not in @p frame_names (`loops.csv:3: unknown query frame '009999' (not one of the
/// sequence's 4541 frames)`), or a loop of a frame with itself.
std::vector<LoopRecord> readLoopsCsv(const std::string& path, const std::vector<std::string>& frame_names);

/// Pose-graph edges of @p loops (indices from readLoopsCsv): from = match, to = query, T_from_to = T_match_query
/// with its rotation projected onto SO(3) (the CSV's six decimals leave it orthonormal to ~1e-6 only), the loop's
/// own information if it has one, else @p information, and kind kLoop.
std::vector<backend::Edge> loopEdges(const std::vector<LoopRecord>& loops, const backend::Matrix6d& information);

}  // namespace sgtllc::io
