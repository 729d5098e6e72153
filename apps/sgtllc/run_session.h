// `sgtllc run`'s options, and a run as a new session against a saved map (`run SEQ --odometry O --map A.sgtmap`,
// docs/sessions.md).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "loop_closing.h"
#include "sgtllc/io/trajectory_frame.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/pipeline/session_pipeline.h"

namespace sgtllc::cli {

struct RunOptions {
  std::string sequence;
  std::string nodes;
  std::string out;
  std::string config;
  std::string labeller;    ///< --labeller file|geometric
  std::string labels_dir;  ///< --labels-dir: NAME.label files instead of SEQ_DIR/labels
  std::string odometry, calib;  ///< --odometry, --calib: close the loop with the back end
  io::PoseFrame pose_frame = io::PoseFrame::kAuto;  ///< --pose-frame of a KITTI --odometry (or poses.txt)
  std::string save_map;         ///< --save-map: the database, names and poses as a map file
  std::string map;              ///< --map: run the sequence as a new session against this map (docs/sessions.md)
  std::string session_name;     ///< --session-name: its name in the merged map
  double false_fraction = 0.0;  ///< --add-false-loops: with --map, false inter-session loops (robustness test)
  uint64_t seed = 7;            ///< --seed of --add-false-loops
  ClosingOutputs outputs;
  int threads = 0;
  int accumulate = 1;  ///< --accumulate: scans merged into each frame
  bool json = false;
  bool quiet = false;  ///< --quiet: the summary only, no line per loop
  bool force = false;
  bool online = false;  ///< re-optimise at every loop instead of once at the end
};

/// A session fed frame by frame into its map (the part `run --map` and `eval --map --odometry` share): the map,
/// the frames, their odometry; each loop printed unless --quiet or --json. The source is kept for its frame numbers.
struct StreamedSession {
  std::unique_ptr<pipeline::SessionPipeline> pipeline;
  std::unique_ptr<pipeline::FrameSource> source;
  Odometry odometry;
  std::vector<double> frame_ms;  ///< per frame, both searches
  std::string name;              ///< the session's name in the merged map
};
StreamedSession streamSession(const RunOptions& o, const Config& config);

/// The run with --map: every frame searched in the map and among the session's own frames, then merged into the
/// map's frame; writes --out-trajectory (the session in the map's frame), --save-map (the merged map) and --out.
void runSession(const RunOptions& o);

}  // namespace sgtllc::cli
