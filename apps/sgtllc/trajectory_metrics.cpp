#include "trajectory_metrics.h"

#include "sgtllc/eval/trajectory_plot.h"

namespace sgtllc::cli {
namespace {

void addStats(Json& j, const std::string& prefix, const eval::ErrorStats& s) {
  j[prefix + "_rmse"] = s.rmse;
  j[prefix + "_mean"] = s.mean;
  j[prefix + "_median"] = s.median;
  j[prefix + "_max"] = s.max;
}

std::string statsText(const eval::ErrorStats& s, int digits) {
  return "RMSE " + fixed(s.rmse, digits) + ", mean " + fixed(s.mean, digits) + ", median " + fixed(s.median, digits) +
         ", max " + fixed(s.max, digits);
}

std::string metricsText(const char* name, const TrajectoryMetrics& m) {
  return std::string(name) + ": ATE aligned " + statsText(m.ate.aligned, 3) + " m; unaligned " +
         statsText(m.ate.unaligned, 3) + " m\n" + std::string(std::string(name).size() + 2, ' ') +
         "RPE (1 frame) translation RMSE " + fixed(m.rpe.translation_m.rmse, 4) + " m, rotation RMSE " +
         fixed(m.rpe.rotation_deg.rmse, 4) + " deg; KITTI segments " + fixed(m.segments.translation_percent, 3) +
         " %, " + fixed(m.segments.rotation_deg_per_100m, 3) + " deg/100 m (" + std::to_string(m.segments.segments) +
         " segments)\n";
}

std::string row(const char* what, double odometry, double corrected, int digits) {
  return std::string("| ") + what + " | " + fixed(odometry, digits) + " | " + fixed(corrected, digits) + " |\n";
}

/// @p ground_truth moved so its first pose is the odometry's first pose: a second simulated session's truth is in its
/// first session's frame, its odometry starts at the identity in its own (docs/relocalization.md). A truth that
/// already starts where the odometry does (within 1 cm and 0.1°: files of six decimals) is used as it is. Only the
/// unaligned error and the plot as drawn see the difference; the aligned error, RPE and segments do not depend on
/// the frame.
std::vector<Eigen::Isometry3d> fromOdometryStart(const std::vector<Eigen::Isometry3d>& ground_truth,
                                                 const Odometry& odometry) {
  if (ground_truth.empty() || odometry.poses.empty()) return ground_truth;
  const Eigen::Isometry3d move = odometry.poses.front() * ground_truth.front().inverse();
  if (move.translation().norm() < 0.01 && Eigen::AngleAxisd(move.linear()).angle() < 0.1 * M_PI / 180.0) {
    return ground_truth;
  }
  std::vector<Eigen::Isometry3d> out;
  out.reserve(ground_truth.size());
  for (const Eigen::Isometry3d& T : ground_truth) out.push_back(move * T);
  return out;
}

}  // namespace

TrajectoryMetrics trajectoryMetrics(const std::vector<Eigen::Isometry3d>& ground_truth,
                                    const std::vector<Eigen::Isometry3d>& estimate) {
  return {eval::absoluteTrajectoryError(ground_truth, estimate), eval::relativePoseError(ground_truth, estimate, 1),
          eval::kittiSegmentError(ground_truth, estimate)};
}

Json trajectoryMetricsJson(const TrajectoryMetrics& m) {
  Json j = Json::object();
  addStats(j, "ate_aligned", m.ate.aligned);
  addStats(j, "ate_unaligned", m.ate.unaligned);
  j["rpe_translation_rmse_m"] = m.rpe.translation_m.rmse;
  j["rpe_translation_mean_m"] = m.rpe.translation_m.mean;
  j["rpe_rotation_rmse_deg"] = m.rpe.rotation_deg.rmse;
  j["rpe_rotation_mean_deg"] = m.rpe.rotation_deg.mean;
  j["kitti_translation_percent"] = m.segments.translation_percent;
  j["kitti_rotation_deg_per_100m"] = m.segments.rotation_deg_per_100m;
  j["kitti_segments"] = m.segments.segments;
  j["poses"] = m.ate.aligned.count;
  return j;
}

TrajectoryComparison compareTrajectories(const std::vector<Eigen::Isometry3d>& ground_truth, const Odometry& odometry,
                                         const Closing& closing) {
  const std::vector<Eigen::Isometry3d> truth = fromOdometryStart(ground_truth, odometry);
  return {trajectoryMetrics(truth, odometry.poses), trajectoryMetrics(truth, closing.poses)};
}

Json comparisonJson(const TrajectoryComparison& c) {
  return {{"odometry", trajectoryMetricsJson(c.odometry)}, {"corrected", trajectoryMetricsJson(c.corrected)}};
}

std::string comparisonText(const TrajectoryComparison& c) {
  return metricsText("odometry", c.odometry) + metricsText("corrected", c.corrected);
}

std::string comparisonMarkdown(const TrajectoryComparison& c, const std::string& plot_file) {
  const TrajectoryMetrics &o = c.odometry, &k = c.corrected;
  std::string md = "## Trajectory error\n\nAgainst the ground truth, " + std::to_string(o.ate.aligned.count) +
                   " poses. ATE after SE(3) Umeyama alignment (no scale) and unaligned; RPE over one frame; the "
                   "KITTI benchmark's 100–800 m segment error.\n\n| metric | odometry | corrected |\n|---|---|---|\n";
  md += row("ATE aligned RMSE (m)", o.ate.aligned.rmse, k.ate.aligned.rmse, 3);
  md += row("ATE aligned mean (m)", o.ate.aligned.mean, k.ate.aligned.mean, 3);
  md += row("ATE aligned median (m)", o.ate.aligned.median, k.ate.aligned.median, 3);
  md += row("ATE aligned max (m)", o.ate.aligned.max, k.ate.aligned.max, 3);
  md += row("ATE unaligned RMSE (m)", o.ate.unaligned.rmse, k.ate.unaligned.rmse, 3);
  md += row("ATE unaligned mean (m)", o.ate.unaligned.mean, k.ate.unaligned.mean, 3);
  md += row("ATE unaligned median (m)", o.ate.unaligned.median, k.ate.unaligned.median, 3);
  md += row("ATE unaligned max (m)", o.ate.unaligned.max, k.ate.unaligned.max, 3);
  md += row("RPE translation RMSE (m)", o.rpe.translation_m.rmse, k.rpe.translation_m.rmse, 4);
  md += row("RPE rotation RMSE (deg)", o.rpe.rotation_deg.rmse, k.rpe.rotation_deg.rmse, 4);
  md += row("KITTI segment translation (%)", o.segments.translation_percent, k.segments.translation_percent, 3);
  md += row("KITTI segment rotation (deg/100 m)", o.segments.rotation_deg_per_100m, k.segments.rotation_deg_per_100m,
            3);
  md += "\n![trajectories, top view](" + plot_file + ")\n\n";
  return md;
}

void plotClosing(const std::string& path, const std::vector<Eigen::Isometry3d>& ground_truth,
                 const Odometry& odometry, const std::vector<ClosingLoop>& loops, const Closing& closing) {
  eval::TrajectoryPlotData data;
  data.ground_truth = fromOdometryStart(ground_truth, odometry);
  data.odometry = odometry.poses;
  data.corrected = closing.poses;
  if (!ground_truth.empty()) {
    const eval::AteResult o = eval::absoluteTrajectoryError(data.ground_truth, odometry.poses);
    const eval::AteResult c = eval::absoluteTrajectoryError(data.ground_truth, closing.poses);
    data.odometry_ate = {o.aligned.rmse, o.unaligned.rmse};
    data.corrected_ate = {c.aligned.rmse, c.unaligned.rmse};
  }
  for (size_t k = 0; k < loops.size(); ++k) {
    data.loops.push_back({loops[k].edge.from, loops[k].edge.to,
                          closing.result.loops.at(k).decision == pipeline::LoopDecision::kAccepted});
  }
  eval::plotTrajectories(path, data);
}

}  // namespace sgtllc::cli
