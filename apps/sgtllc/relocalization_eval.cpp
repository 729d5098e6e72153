#include "relocalization_eval.h"

#include <filesystem>
#include <iostream>

#include "common.h"
#include "localization.h"
#include "sgtllc/eval/ground_truth.h"
#include "sgtllc/eval/metric_text.h"
#include "sgtllc/eval/relocalization.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/map/map_file.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

std::string ratio(const std::optional<double>& v) { return eval::metricText(v.value_or(0.0), v.has_value(), 4); }

std::string summaryText(const eval::RelocalizationMetrics& m) {
  return "relocalization: " + std::to_string(m.queries) + " query frames, " + std::to_string(m.positives) +
         " with a map frame within 3 m, " + std::to_string(m.negatives) + " with none within 20 m\n" +
         "recall@1 " + ratio(m.recall_at_1) + " (" + std::to_string(m.accepted_near) + " of " +
         std::to_string(m.positives) + "), precision " + ratio(m.precision) + " (" + std::to_string(m.accepted_near) +
         " of " + std::to_string(m.accepted) + " accepted; " + std::to_string(m.accepted_between) + " 3-20 m, " +
         std::to_string(m.accepted_far) + " beyond 20 m; without the 3-20 m ones " + ratio(m.precision_no_between) +
         ")\npose success " + ratio(m.pose_success) + " (" + std::to_string(m.pose_successes) + " of " +
         std::to_string(m.accepted_near) + "), mean RTE " +
         (m.rte_mean_m ? fixed(*m.rte_mean_m, 3) + " m" : std::string("n/a")) + ", RRE " +
         (m.rre_mean_deg ? fixed(*m.rre_mean_deg, 3) + " deg" : std::string("n/a")) +
         "\njudged by the pose (RTE < 2 m, RRE < 5 deg in the map's world frame, whatever frame is named): "
         "precision " + ratio(m.precision_pose) + " (" + std::to_string(m.accepted_placed) + " of " +
         std::to_string(m.accepted) + "), recall@1 " + ratio(m.recall_at_1_pose) + " (" +
         std::to_string(m.positives_placed) + " of " + std::to_string(m.positives) + ")" +
         "\nfalse relocalizations " + ratio(m.false_rate) + " (" + std::to_string(m.accepted_negatives) + " of " +
         std::to_string(m.negatives) + " frames with no map frame within 20 m)\n";
}

}  // namespace

void evalRelocalization(const std::string& map_path, const std::string& sequence, const std::string& nodes,
                        const std::string& labels_dir, const Config& config, bool json,
                        const std::optional<map::TrackingOptions>& tracking) {
  const pipeline::FrameSource source = frameSource(sequence, nodes, config, labels_dir);
  const std::string poses_path = (fs::path(sequence) / "poses.txt").string();
  if (!fs::exists(poses_path)) {
    throw Error(poses_path + ": missing (the relocalization protocol needs the query session's ground-truth poses)");
  }
  const eval::GroundTruth truth =
      eval::GroundTruth::fromKitti(poses_path, (fs::path(sequence) / "calib.txt").string());
  const map::Relocalizer relocalizer(map::readMapFile(map_path, config), config, map_path);
  const map::Map& m = relocalizer.map();
  if (!m.hasPoses()) {
    throw Error(map_path + ": the map has no frame poses, so relocalizations cannot be scored; save it with "
                "`sgtllc run SEQ --save-map` from a sequence with poses.txt and calib.txt (or with --odometry)");
  }
  std::vector<Eigen::Isometry3d> map_poses, query_poses;
  for (const Eigen::Matrix4d& T : m.poses) map_poses.emplace_back(T);
  for (size_t f = 0; f < truth.size(); ++f) query_poses.emplace_back(truth.pose(static_cast<long>(f)));

  const std::string query_name = nodes.empty() ? sequence : nodes;
  std::vector<eval::RelocalizationQuery> queries;
  std::vector<double> frame_ms;
  int accepted = 0;
  Progress progress("frames", source.size());
  const auto on_hit = [&](size_t index, const Hit& h) {
    eval::RelocalizationQuery q;
    q.query_number = source.number(index);
    if (q.query_number < 0) throw Error(query_name + ": frame " + io::quoteContent(source.name(index)) + " is not a frame number");
    q.map_frame = h.r.map_frame;
    q.accepted = h.r.localized;
    q.score = h.r.score;
    q.T_mapframe_query = Eigen::Isometry3d(h.r.T_mapframe_query);
    queries.push_back(q);
    frame_ms.push_back(h.r.search.timing.total_ms());
    accepted += q.accepted;
    progress.update(index + 1, std::to_string(accepted) + " relocalized");
  };
  pipeline::localizeSequence(source, relocalizer, query_name, map_path, config.threads, tracking, on_hit);
  progress.finish();
  const eval::RelocalizationMetrics metrics = eval::relocalizationMetrics(queries, map_poses, query_poses);
  const double median = eval::percentile(frame_ms, 0.5), p99 = eval::percentile(frame_ms, 0.99);
  if (json) {
    Json j = {{"map", map_path}, {"map_frames", m.size()}, {"sequence", query_name}, {"track", tracking.has_value()}};
    j.update(eval::relocalizationJson(metrics));
    j["ms_per_frame_median"] = median;
    j["ms_per_frame_p99"] = p99;
    std::cout << jsonText(j) << "\n";
  } else {
    std::cout << "map " << map_path << " (" << m.size() << " frames), queries " << query_name
              << (tracking ? " as one stream (--track)" : "") << "\n"
              << summaryText(metrics) << "ms per frame: median " << fixed(median, 2) << ", p99 " << fixed(p99, 2)
              << " (load not included)\n";
  }
}

}  // namespace sgtllc::cli
