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

/// A trajectory's ATE RMSE against the ground truth, in metres (negative: not known, not shown).
struct PlotAte {
  double aligned = -1.0;    ///< after SE(3) alignment (the report's headline figure)
  double unaligned = -1.0;  ///< as drawn
};

/// A trajectory's legend entry: "odometry: ATE 3.854 m aligned, 6.744 m as drawn", or @p name alone when the
/// ATE is not known.
std::string ateLabel(const std::string& name, const PlotAte& ate);

/// What to draw. Every trajectory may be empty (then it is left out, with its legend entry).
struct TrajectoryPlotData {
  std::vector<Eigen::Isometry3d> ground_truth;
  std::vector<Eigen::Isometry3d> odometry;
  std::vector<Eigen::Isometry3d> corrected;
  /// Loops as frame indices. Drawn between the positions of the ground truth if given (a false loop then shows as
  /// a long edge), else of the corrected trajectory, else of the odometry.
  std::vector<PlotLoop> loops;
  /// Printed in the legend entries of the odometry and the corrected trajectory, and the aligned ones in the title.
  PlotAte odometry_ate, corrected_ate;
  /// Top view of x–y (LiDAR frame: z up, the default) or of x–z (KITTI cam0 frame: y down).
  bool cam0_axes = false;
  std::string title = "Trajectories (top view) and loop edges";
};

/// Renders @p data to a PNG at @p path: ground truth as a wide light band underneath (a corrected trajectory that
/// follows it closely must not hide it), odometry orange dashed, corrected blue, accepted loops green, rejected
/// loops red, a black start marker; the legend lists only what is drawn, with the ATE where given. Throws
/// sgtllc::Error naming the file if it cannot be written, or if a loop names a frame that the trajectory it is drawn
/// on does not have.
/// Replaces an existing file: deciding whether that is allowed (--force) is the caller's job.
void plotTrajectories(const std::string& path, const TrajectoryPlotData& data);

}  // namespace sgtllc::eval
