// `sgtllc eval S2 --map A.sgtmap --odometry O`: a session merged into a map, scored against its ground truth
// (docs/sessions.md, "Evaluating a merge").
#pragma once

#include "run_session.h"

namespace sgtllc::cli {

/// Runs the session of @p o (SEQ_DIR or --nodes, --odometry, --map) as `run --map` does, then scores it against
/// SEQ_DIR/poses.txt (+ calib.txt), which must be in the map's world (the simulator's `--world-of` sessions are):
/// inter-session loops found, correct (pose within 1 m / 5 deg of the truth, judged against the map's stored pose of
/// its map frame) and accepted, intra-session loops likewise, the merged trajectory's ATE (aligned and in the map's
/// frame) beside the odometry's, and the map's frames after the merge against the map's and the session's. Prints
/// text or (--json) one JSON object. Throws sgtllc::Error naming the file when the truth is missing.
void evalMerge(const RunOptions& o, const Config& config);

}  // namespace sgtllc::cli
