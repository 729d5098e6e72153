/// @file relocalization.h
/// @brief The relocalization protocol's metrics: the frames of a second session relocalized in a map of the first
///        one, scored against both sessions' poses in one world frame (docs/relocalization.md).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

namespace sgtllc::eval {

/// What a relocalization returned for one query frame.
struct RelocalizationQuery {
  long query_number = 0;  ///< frame number of the query in its own sequence (index into the query poses)
  int map_frame = -1;     ///< the map frame returned (index into the map poses); −1 = none
  bool accepted = false;  ///< the relocalization passed its gates (a system would act on it)
  double score = 0;       ///< its score (reported, not used by the metrics)
  /// Maps points of the query frame into the returned map frame.
  Eigen::Isometry3d T_mapframe_query = Eigen::Isometry3d::Identity();
};

/// The protocol's thresholds; its defaults are the values of docs/relocalization.md, "The protocol".
struct RelocalizationProtocol {
  double positive_distance = 3.0;   ///< m: a query with a map frame at or within this is a positive, and a
                                    ///< returned map frame at or within this is correct
  double negative_distance = 20.0;  ///< m: a query with no map frame at or within this is a negative
  double max_translation_m = 2.0;   ///< pose success: RTE below this (m) ...
  double max_rotation_deg = 5.0;    ///< ... and RRE below this (deg)
};

/// The metrics, each ratio with the counts behind it; a ratio is empty (n/a) when its denominator is 0.
struct RelocalizationMetrics {
  int queries = 0;    ///< query frames scored
  int positives = 0;  ///< queries with a map frame within positive_distance
  int negatives = 0;  ///< queries with no map frame within negative_distance
  int accepted = 0;   ///< accepted relocalizations, of any query
  /// Accepted relocalizations by where the returned map frame lies from the query: within positive_distance
  /// (correct), between the two distances, beyond negative_distance.
  int accepted_near = 0, accepted_between = 0, accepted_far = 0;
  int accepted_negatives = 0;  ///< accepted relocalizations of negative queries (all false by definition)
  int pose_successes = 0;      ///< correct relocalizations whose pose error is within the success thresholds
  /// Accepted relocalizations whose estimated pose in the world, T_world_map · T_mapframe_query, lies within the
  /// success thresholds of the query's true pose, whatever map frame was returned: the query is placed correctly.
  int accepted_placed = 0;
  int positives_placed = 0;  ///< accepted_placed of positive queries

  std::optional<double> recall_at_1;  ///< accepted_near / positives
  std::optional<double> precision;    ///< accepted_near / accepted
  /// accepted_near / (accepted − accepted_between): with the matches 3–20 m away left out, as the top-1 protocol
  /// of `sgtllc eval` also reports.
  std::optional<double> precision_no_between;
  std::optional<double> pose_success;  ///< pose_successes / accepted_near
  std::optional<double> rte_mean_m;    ///< mean RTE over the pose successes (as published tables), m
  std::optional<double> rre_mean_deg;  ///< mean RRE over the pose successes, deg
  std::optional<double> false_rate;    ///< accepted_negatives / negatives
  /// The pose-judged figures (docs/relocalization.md, "Judged by the pose"): accepted_placed / accepted, and
  /// positives_placed / positives.
  std::optional<double> precision_pose;
  std::optional<double> recall_at_1_pose;
};

/// Scores @p queries. @p map_poses and @p query_poses are T_world_lidar of every map frame and every frame of the
/// query sequence (index = frame number), in one world frame. Queries must be distinct frames; an accepted one must
/// name a map frame. Throws sgtllc::Error naming the first query that breaks this or that has no pose.
RelocalizationMetrics relocalizationMetrics(const std::vector<RelocalizationQuery>& queries,
                                            const std::vector<Eigen::Isometry3d>& map_poses,
                                            const std::vector<Eigen::Isometry3d>& query_poses,
                                            const RelocalizationProtocol& protocol = {});

/// The metrics as JSON: reloc_recall_at_1, reloc_precision, reloc_pose_success, reloc_false_rate (null when n/a),
/// the other ratios and every count, keys prefixed `reloc_` so they sit beside `sgtllc eval`'s own.
nlohmann::ordered_json relocalizationJson(const RelocalizationMetrics& m);

}  // namespace sgtllc::eval
