// Trajectory errors of the odometry and the corrected trajectory against ground truth (docs/backend.md), as text, JSON
// and a report section, and the top-view plot with the loop edges.
#pragma once

#include <string>
#include <vector>

#include "common.h"
#include "loop_closing.h"
#include "sgtllc/eval/trajectory_error.h"

namespace sgtllc::cli {

/// ATE (aligned and unaligned), RPE over one frame and the KITTI segment error of one trajectory.
struct TrajectoryMetrics {
  eval::AteResult ate;
  eval::RpeResult rpe;
  eval::SegmentError segments;
};

TrajectoryMetrics trajectoryMetrics(const std::vector<Eigen::Isometry3d>& ground_truth,
                                    const std::vector<Eigen::Isometry3d>& estimate);

/// Keys `ate_aligned_rmse`, `ate_aligned_mean`, … `ate_unaligned_max`, `rpe_translation_rmse_m`,
/// `rpe_rotation_rmse_deg`, `kitti_translation_percent`, `kitti_rotation_deg_per_100m`, `kitti_segments`.
Json trajectoryMetricsJson(const TrajectoryMetrics& m);

/// The odometry and the corrected trajectory against ground truth.
struct TrajectoryComparison {
  TrajectoryMetrics odometry;
  TrajectoryMetrics corrected;
};

TrajectoryComparison compareTrajectories(const std::vector<Eigen::Isometry3d>& ground_truth, const Odometry& odometry,
                                         const Closing& closing);
/// {"odometry": {...}, "corrected": {...}}
Json comparisonJson(const TrajectoryComparison& c);
/// Two lines per trajectory (ATE aligned / unaligned: RMSE, mean, median, max; RPE; KITTI segments).
std::string comparisonText(const TrajectoryComparison& c);
/// A markdown section: the table of both trajectories and the plot.
std::string comparisonMarkdown(const TrajectoryComparison& c, const std::string& plot_file);

/// The top view: ground truth (may be empty), odometry, corrected, loops accepted (green) and rejected (red).
void plotClosing(const std::string& path, const std::vector<Eigen::Isometry3d>& ground_truth,
                 const Odometry& odometry, const std::vector<ClosingLoop>& loops, const Closing& closing);

}  // namespace sgtllc::cli
