/// @file session_pipeline.h
/// @brief A new session run against a saved map (docs/sessions.md): each frame is searched in the map
///        (inter-session loops, map/relocalizer.h) and among the session's own frames (intra-session loops, the
///        loop-closing pipeline); at the end one pose graph places the session in the map's frame with the map's
///        poses fixed (backend/session_merge.h), and the map grows by the session.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/backend/session_merge.h"
#include "sgtllc/map/map.h"
#include "sgtllc/map/relocalizer.h"
#include "sgtllc/pipeline/loop_closing_pipeline.h"

namespace sgtllc::pipeline {

class FrameReducer;

/// How a session is named in the map it joins (how many inter-session loops it needs to join is
/// backend.sessions.min_inter_loops).
struct SessionOptions {
  /// The session's name in the merged map (map::MapSession); its frames are named NAME/FRAME there. Non-empty,
  /// without '/' and not a name the map's sessions already have.
  std::string name = "session";
  /// The name the map's frames get as a session of their own when the map has no sessions yet (a map saved by
  /// `run --save-map`).
  std::string map_session = "map";
};

/// What one frame brought.
struct SessionFrame {
  PipelineFrame own;                          ///< the intra-session detection (own.loop: an intra-session loop)
  map::Relocalization in_map;                 ///< the frame searched in the map
  std::optional<ClosingLoop> inter;           ///< the inter-session loop it gave, if in_map localized it
};

/// What the merge made of the session.
struct SessionClosing {
  backend::SessionMerge merge;  ///< per-loop decisions (in loops() order), poses in the map's world if placed
  /// Per session frame, whether it joins the merged map (map::framesThatAdd with backend.sessions.keep_distance_m,
  /// keep_heading_deg and max_covering_sessions).
  std::vector<bool> kept;
  double ms = 0.0;  ///< the merge's time
};

/// Not thread-safe; the answers do not depend on config.threads.
class SessionPipeline {
 public:
  /// @p map needs poses (the map's world) and a configuration compatible with @p config (map::checkCompatible;
  /// throws map::MapError naming @p source otherwise); throws sgtllc::Error if @p options are invalid (a name empty,
  /// with a '/', or one of the map's sessions').
  SessionPipeline(map::Map map, const Config& config, SessionOptions options, const std::string& source = "map");
  ~SessionPipeline();

  /// The session's next frame, reduced to nodes, at odometry pose @p T_odometry_frame (the session's own frame);
  /// @p name defaults to the index, six digits. Throws as LoopClosingPipeline::addFrame.
  SessionFrame addFrame(LoadedFrame frame, const Eigen::Isometry3d& T_odometry_frame, std::string name = {});
  /// A scan (sensor frame) with a label per point, or any labels with labeller.source geometric; as addFrame.
  SessionFrame addScan(const LabeledCloud& scan, const Eigen::Isometry3d& T_odometry_frame, std::string name = {});
  /// A frame given as nodes; as addFrame.
  SessionFrame addNodes(std::vector<Node> nodes, const Eigen::Isometry3d& T_odometry_frame, std::string name = {});

  /// A loop found elsewhere (another place recognition, a surveyor's tie, or eval::falseInterSessionLoops' robustness
  /// test), merged at finish() with the loops found here and judged like them. Its edge joins map frame `from`
  /// (0..M−1) or session frame M + i to session frame `to` = M + j, both already added; query and match name them.
  /// Throws sgtllc::Error after finish(), for a frame out of range, or for a loop between two map frames or ending in
  /// a map frame.
  void addLoop(ClosingLoop loop);

  /// Ends the session: the merge of every loop found. Called once.
  const SessionClosing& finish();

  /// Inter- and intra-session loops in the order found. Map frames are 0..M−1 and session frame i is M + i in
  /// their edges; query and match are the names in the merged map.
  const std::vector<ClosingLoop>& loops() const { return loops_; }
  /// The session's poses: after finish(), in the map's world if placed; before, its odometry.
  const std::vector<Eigen::Isometry3d>& poses() const;
  int mapFrames() const { return relocalizer_.map().size(); }
  const map::Map& map() const { return relocalizer_.map(); }  ///< the map the session runs against
  const LoopClosingPipeline& session() const { return own_; }
  const SessionClosing* closing() const { return closing_.get(); }

  /// The map with the session appended: the session's frames that add to it (SessionClosing::kept) after the map's, at their merged poses, named
  /// NAME/FRAME, with a session entry of their own. Throws sgtllc::Error before finish() or if the session was not
  /// placed.
  map::Map mergedMap() const;
  /// Per session frame, whether mergedMap() keeps it (after finish(); all true before).
  std::vector<bool> framesKept() const;

 private:
  SessionOptions options_;
  map::Relocalizer relocalizer_;
  LoopClosingPipeline own_;
  std::unique_ptr<FrameReducer> reducer_;
  std::vector<ClosingLoop> loops_;
  std::vector<int> inter_loop_;  ///< per session frame: its inter-session loop's index in loops_, or −1
  std::unique_ptr<SessionClosing> closing_;
};

}  // namespace sgtllc::pipeline
