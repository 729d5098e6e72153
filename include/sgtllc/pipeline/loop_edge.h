/// @file loop_edge.h
/// @brief A detected or read loop as an edge of the pose graph (docs/backend.md, "Loop edges").
#pragma once

#include <string>
#include <vector>

#include "sgtllc/backend/information.h"
#include "sgtllc/backend/pose_graph_types.h"
#include "sgtllc/database.h"
#include "sgtllc/detector.h"
#include "sgtllc/io/loops_csv.h"

namespace sgtllc::pipeline {

/// One loop for the back end, with its frame names and where it came from.
struct ClosingLoop {
  backend::Edge edge;           ///< from = match frame, to = query frame
  std::string query, match;     ///< frame names
  bool has_information = true;  ///< false: nominalLoopInformation
  bool injected = false;        ///< a false loop added by falseLoops()
  double score = 0.0;           ///< the detector's loop score (0 for loops from elsewhere without one)
  double score_c = 0.0;         ///< its consistency score
};

/// Information of a loop whose own cannot be computed (a 16-column loops CSV, or inlier centres on one line): the
/// loopInformation of a nominal fit of 8 inliers spread 10 m around the sensor at σ = @p noise.sigma_min.
backend::Matrix6d nominalLoopInformation(const backend::LoopNoise& noise);

/// The loop edge of @p candidate, the loop of frame @p query: loopEdge() on the two frames' stored nodes (or the ICP
/// pose and its information when the candidate was refined), or the nominal information if the inlier centres are
/// collinear. @p query_name and @p match_name name the two frames.
ClosingLoop detectedLoop(int query, const Candidate& candidate, const FrameDatabase& database,
                         std::string query_name, std::string match_name, const backend::LoopNoise& noise);

/// The loops CSV record of a loop (with its information, if any).
io::LoopRecord loopRecord(const ClosingLoop& loop);

/// The loops of a loops CSV (their information, or the nominal one).
std::vector<ClosingLoop> csvLoops(const std::vector<io::LoopRecord>& records, const backend::LoopNoise& noise);

}  // namespace sgtllc::pipeline
