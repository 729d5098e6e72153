/// @file relocalizer.h
/// @brief Where is this frame in a prior map? A query against a loaded map without insertion (docs/relocalization.md).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/map/map.h"
#include "sgtllc/node_extraction.h"

namespace sgtllc::map {

/// The answer for one query frame.
struct Relocalization {
  /// Retrieval and verification of the query against every map frame, as the online detector's search
  /// (searchDatabase): candidates, best, is_loop (= localized), lateral and times. `frame` is −1 and `search`
  /// kSearched: nothing is stored.
  FrameResult search;
  /// The answer's map frame, or −1 if no candidate passed verification: with map poses, the map frame nearest to
  /// the query's estimated position T_world_query (the verified candidate, search.candidates[search.best], may be
  /// a neighbour of the place); without, the verified candidate itself.
  int map_frame = -1;
  /// The best candidate is a loop (score > verification.sigma_4), or a RelocalizationTracker accepted the answer
  /// (tracked).
  bool localized = false;
  double score = 0.0;      ///< score of the best candidate (0 if none)
  /// Maps query points into map frame @p map_frame (identity if none): with map poses,
  /// T_world_mapframe⁻¹ · T_world_query.
  Eigen::Matrix4d T_mapframe_query = Eigen::Matrix4d::Identity();
  /// The query's pose in the map's world frame, T_world_mapframe · T_mapframe_query, when the map has poses and a
  /// candidate was chosen.
  std::optional<Eigen::Matrix4d> T_world_query;
  /// Accepted by a RelocalizationTracker's agreement with the track, not by σ_4 (search.is_loop false; search.best
  /// is the candidate that agreed).
  bool tracked = false;
  /// The chosen candidate verified, but its inlier node centres lie so nearly on a line that the rotation about it
  /// is not fixed (RelocalizerOptions::max_rotation_uncertainty_deg): not localized, whatever the score.
  bool weak_rotation = false;
};

/// Query-time settings of a Relocalizer (docs/relocalization.md, "Relocalizer settings").
struct RelocalizerOptions {
  /// Candidates retrieved and verified per query; 0 = the configuration's retrieval.num_candidates. A relocalized
  /// frame has no recent frames to exclude and no loop to confirm later, so it affords a wider shortlist than the
  /// online detector's 15: on the tuning world (docs/relocalization.md) the true place was outside the top 15 but in
  /// the top 50 for a fifth of the misses, at about three times the verification time [0, 1000].
  int num_candidates = 50;
  /// An answer is accepted only if its rotation is fixed to within about this (degrees; 0 = no check) [0, 90).
  /// Inliers fit within ε = verification.inlier_threshold, so the rotation about the line the inlier centres lie
  /// nearest is uncertain by about ε / s₂, s₂ the second singular value of the centred inlier centres (m): the
  /// answer needs s₂ ≥ ε / tan(this). 5° is the protocol's pose-success bound (docs/relocalization.md).
  double max_rotation_uncertainty_deg = 5.0;
};

/// Queries frames against a map: every map frame is eligible (no recent-frame exclusion, no warm-up) and nothing
/// is inserted, so the answers do not depend on the order of the queries. Not thread-safe (a kd-tree database
/// grows its tree on the first query); uses config.threads internally, and the result does not depend on it.
class Relocalizer {
 public:
  /// Takes @p map over; throws MapError(kIncompatible) unless it was built with a configuration compatible with
  /// @p config (checkCompatible), and sgtllc::Error if @p config is invalid. @p source names the map in messages.
  Relocalizer(Map map, const Config& config, const std::string& source = "map", RelocalizerOptions options = {});

  /// A labelled scan (sensor frame): its nodes are extracted with the configuration's clustering.
  Relocalization localize(const LabeledCloud& cloud) const;
  /// Ready-made nodes, with the scan's footprint (computeFootprint) where the caller has one: with the map's
  /// footprints it keeps the footprint check and the consistency path (algorithm §7.7, §7.8). Throws sgtllc::Error
  /// as LoopDetector::process(nodes) does for bad nodes.
  Relocalization localize(std::vector<Node> nodes, Footprint footprint = {}) const;

  /// The answer that places the query by candidate @p candidate of @p search (an index into search.candidates,
  /// verified: rejection kNone): localized iff search.is_loop, the pose and, with map poses, the map frame nearest
  /// to the estimated position. @p candidate −1: no answer (map_frame −1).
  Relocalization answerWith(FrameResult search, int candidate) const;

  /// Whether candidate @p c's inlier centres (in its map frame's nodes) fix the rotation to within
  /// RelocalizerOptions::max_rotation_uncertainty_deg; always true when that is 0.
  bool rotationSupported(const Candidate& c) const;

  const Map& map() const { return map_; }
  const Config& config() const { return config_; }

 private:
  /// The map frames' positions in a kd-tree (maps with poses): the nearest map frame to an estimated pose is
  /// found without a pass over every pose.
  struct PositionIndex;
  int nearestMapFrame(const Eigen::Vector3d& at) const;

  Map map_;
  Config config_;
  double min_inlier_spread_ = 0.0;  ///< s₂ an answer needs (m), from the options; 0 = no check
  NodeExtractor extractor_;
  std::shared_ptr<const PositionIndex> positions_;  ///< null without map poses
};

}  // namespace sgtllc::map
