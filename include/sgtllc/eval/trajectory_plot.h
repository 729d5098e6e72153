/// @file trajectory_plot.h
/// @brief Top view of trajectories and loop edges as a PNG: ground truth, odometry, corrected trajectory, and the
///        loop edges the back end accepted or rejected.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace sgtllc::eval {

/// A loop edge to draw between frames @p from and @p to.
struct PlotLoop {
  int from = 0;
  int to = 0;
  bool accepted = true;  ///< kept by the back end (else rejected as an outlier)
};

/// What to draw. Every trajectory may be empty (then it is left out, with its legend entry).
struct TrajectoryPlotData {
  std::vector<Eigen::Isometry3d> ground_truth;
  std::vector<Eigen::Isometry3d> odometry;
  std::vector<Eigen::Isometry3d> corrected;
  /// Loops as frame indices. Drawn between the positions of the ground truth if given (a false loop then shows as
  /// a long edge), else of the corrected trajectory, else of the odometry.
  std::vector<PlotLoop> loops;
  /// Top view of x–y (LiDAR frame: z up, the default) or of x–z (KITTI cam0 frame: y down).
  bool cam0_axes = false;
  std::string title = "Trajectories (top view) and loop edges";
};

/// Renders @p data to a PNG at @p path: ground truth grey, odometry orange, corrected blue, accepted loops green,
/// rejected loops red, a black start marker; the legend lists only what is drawn. Throws sgtllc::Error naming the
/// file if it cannot be written, or if a loop names a frame that the trajectory it is drawn on does not have.
/// Replaces an existing file: deciding whether that is allowed (--force) is the caller's job.
void plotTrajectories(const std::string& path, const TrajectoryPlotData& data);

}  // namespace sgtllc::eval
