// The relocalization protocol (include/sgtllc/eval/relocalization.h, docs/relocalization.md).
#include "sgtllc/eval/relocalization.h"

#include <algorithm>
#include <limits>
#include <set>
#include <string>

#include "sgtllc/eval/metrics.h"
#include "sgtllc/types.h"

namespace sgtllc::eval {
namespace {

std::optional<double> ratio(int numerator, int denominator) {
  if (denominator == 0) return std::nullopt;
  return static_cast<double>(numerator) / denominator;
}

double distance(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

/// Distance from a query to its nearest map frame: a scan of every map frame, 2·10⁶ distances for the 2,000 +
/// 1,000-frame protocol (a spatial index would pay off only for maps far larger than a protocol run uses).
double nearestMapDistance(const Eigen::Isometry3d& query, const std::vector<Eigen::Isometry3d>& map) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Isometry3d& m : map) best = std::min(best, distance(query, m));
  return best;
}

nlohmann::ordered_json optionalJson(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

RelocalizationMetrics relocalizationMetrics(const std::vector<RelocalizationQuery>& queries,
                                            const std::vector<Eigen::Isometry3d>& map_poses,
                                            const std::vector<Eigen::Isometry3d>& query_poses,
                                            const RelocalizationProtocol& protocol) {
  if (!(protocol.positive_distance > 0.0 && protocol.negative_distance >= protocol.positive_distance)) {
    throw Error("relocalization protocol: need 0 < positive distance <= negative distance");
  }
  RelocalizationMetrics m;
  std::set<long> seen;
  std::vector<PoseError> correct_errors;
  for (const RelocalizationQuery& q : queries) {
    const std::string name = "relocalization query " + std::to_string(q.query_number);
    if (q.query_number < 0 || static_cast<size_t>(q.query_number) >= query_poses.size()) {
      throw Error(name + ": no ground-truth pose (the query sequence has " + std::to_string(query_poses.size()) +
                  ")");
    }
    if (!seen.insert(q.query_number).second) throw Error(name + " appears twice");
    const bool has_frame = q.map_frame >= 0;
    if (has_frame && static_cast<size_t>(q.map_frame) >= map_poses.size()) {
      throw Error(name + ": map frame " + std::to_string(q.map_frame) + " is not in the map (" +
                  std::to_string(map_poses.size()) + " frames)");
    }
    if (q.accepted && !has_frame) throw Error(name + " is accepted but names no map frame");
    const Eigen::Isometry3d& T_world_query = query_poses[static_cast<size_t>(q.query_number)];
    const double nearest = nearestMapDistance(T_world_query, map_poses);
    const bool positive = nearest <= protocol.positive_distance;
    const bool negative = nearest > protocol.negative_distance;
    ++m.queries;
    m.positives += positive;
    m.negatives += negative;
    if (!q.accepted) continue;
    ++m.accepted;
    m.accepted_negatives += negative;
    const Eigen::Isometry3d& T_world_map = map_poses[static_cast<size_t>(q.map_frame)];
    const PoseError placed = poseError((T_world_map * q.T_mapframe_query).matrix(), T_world_query.matrix());
    if (placed.succeeds(protocol.max_translation_m, protocol.max_rotation_deg)) {
      ++m.accepted_placed;
      m.positives_placed += positive;
    }
    const double returned = distance(T_world_query, T_world_map);
    if (returned > protocol.negative_distance) {
      ++m.accepted_far;
    } else if (returned > protocol.positive_distance) {
      ++m.accepted_between;
    } else {
      ++m.accepted_near;
      const Eigen::Isometry3d truth = T_world_map.inverse() * T_world_query;
      correct_errors.push_back(poseError(q.T_mapframe_query.matrix(), truth.matrix()));
    }
  }
  const PoseSummary poses = summarisePoses(correct_errors, protocol.max_translation_m, protocol.max_rotation_deg);
  m.pose_successes = poses.successes;
  m.recall_at_1 = ratio(m.accepted_near, m.positives);
  m.precision = ratio(m.accepted_near, m.accepted);
  m.precision_no_between = ratio(m.accepted_near, m.accepted - m.accepted_between);
  m.pose_success = ratio(m.pose_successes, m.accepted_near);
  if (m.pose_successes > 0) {
    m.rte_mean_m = poses.rte_mean;
    m.rre_mean_deg = poses.rre_mean;
  }
  m.false_rate = ratio(m.accepted_negatives, m.negatives);
  m.precision_pose = ratio(m.accepted_placed, m.accepted);
  m.recall_at_1_pose = ratio(m.positives_placed, m.positives);
  return m;
}

nlohmann::ordered_json relocalizationJson(const RelocalizationMetrics& m) {
  return {{"reloc_recall_at_1", optionalJson(m.recall_at_1)},
          {"reloc_precision", optionalJson(m.precision)},
          {"reloc_pose_success", optionalJson(m.pose_success)},
          {"reloc_false_rate", optionalJson(m.false_rate)},
          {"reloc_precision_no_between", optionalJson(m.precision_no_between)},
          {"reloc_rte_mean_m", optionalJson(m.rte_mean_m)},
          {"reloc_rre_mean_deg", optionalJson(m.rre_mean_deg)},
          {"reloc_precision_pose", optionalJson(m.precision_pose)},
          {"reloc_recall_at_1_pose", optionalJson(m.recall_at_1_pose)},
          {"reloc_queries", m.queries},
          {"reloc_positives", m.positives},
          {"reloc_negatives", m.negatives},
          {"reloc_accepted", m.accepted},
          {"reloc_accepted_near", m.accepted_near},
          {"reloc_accepted_between", m.accepted_between},
          {"reloc_accepted_far", m.accepted_far},
          {"reloc_accepted_negatives", m.accepted_negatives},
          {"reloc_pose_successes", m.pose_successes},
          {"reloc_accepted_placed", m.accepted_placed},
          {"reloc_positives_placed", m.positives_placed}};
}

}  // namespace sgtllc::eval
