/// @file trajectory_error.h
/// @brief Trajectory errors against ground truth: ATE (aligned and unaligned), RPE per frame step, and the KITTI
///        odometry benchmark's segment errors.
///
/// Conventions (so numbers compare with the tools people use):
/// - ATE as evo_ape's translation part: per frame ‖t_gt,i − t_est,i‖ (m), after the SE(3) alignment of the
///   estimate's positions onto the ground truth's by Umeyama's method without scale (evo `--align`), and as given
///   (unaligned: both trajectories in the same world frame, usually starting at the identity).
/// - RPE as evo_rpe with `--delta D -u f`: E_i = (G_i⁻¹ G_{i+D})⁻¹ (P_i⁻¹ P_{i+D}) for every i, translation ‖t(E_i)‖
///   (m) and rotation angle of E_i (deg). No alignment needed: relative poses do not depend on the world frame.
/// - Per distance, the KITTI odometry devkit's metric (evaluate_odometry.cpp): from every 10th frame, segments of
///   100, 200, …, 800 m of ground-truth path; the errors of each segment's relative pose divided by its length,
///   averaged over all segments: translation in %, rotation in deg/100 m. (The devkit computes it in the cam0
///   frame; in the LiDAR frame the numbers differ slightly, since the relative poses are conjugated by Tr.)
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace sgtllc::eval {

/// Summary of a list of errors (all 0 for an empty list).
struct ErrorStats {
  double rmse = 0.0;
  double mean = 0.0;
  double median = 0.0;  ///< middle value; the mean of the two middle values for an even count (as numpy)
  double max = 0.0;
  size_t count = 0;
};

ErrorStats errorStats(std::vector<double> errors);

/// Absolute trajectory error (m).
struct AteResult {
  ErrorStats aligned;    ///< after aligning the estimate with T_gt_est
  ErrorStats unaligned;  ///< positions compared as given
  /// The rigid alignment (rotation + translation, no scale) minimising Σ‖t_gt,i − T · t_est,i‖².
  Eigen::Isometry3d T_gt_est = Eigen::Isometry3d::Identity();
};

/// The rigid transform T (no scale) minimising Σ‖dst_i − T · src_i‖² (Umeyama 1991, Eigen::umeyama).
/// Throws sgtllc::Error if the lists differ in length or are empty.
Eigen::Isometry3d alignRigid(const std::vector<Eigen::Vector3d>& src, const std::vector<Eigen::Vector3d>& dst);

/// ATE of @p estimate against @p ground_truth (pose i = frame i). Throws sgtllc::Error if the counts differ or there
/// are no poses.
AteResult absoluteTrajectoryError(const std::vector<Eigen::Isometry3d>& ground_truth,
                                  const std::vector<Eigen::Isometry3d>& estimate);

/// Relative pose error over a fixed frame step.
struct RpeResult {
  int delta_frames = 1;
  ErrorStats translation_m;
  ErrorStats rotation_deg;
};

/// RPE over all pairs (i, i + @p delta_frames). Throws sgtllc::Error if the counts differ or delta_frames < 1;
/// with fewer than delta_frames + 1 poses the stats are empty (count 0).
RpeResult relativePoseError(const std::vector<Eigen::Isometry3d>& ground_truth,
                            const std::vector<Eigen::Isometry3d>& estimate, int delta_frames = 1);

/// The KITTI odometry benchmark's segment error.
struct SegmentError {
  double translation_percent = 0.0;    ///< mean over segments of ‖t(E)‖ / length × 100
  double rotation_deg_per_100m = 0.0;  ///< mean over segments of angle(E) / length, in deg per 100 m
  size_t segments = 0;                 ///< segments evaluated (0: the trajectory is shorter than every length)
};

/// Segment error as the KITTI devkit computes it: segments start at every @p step_frames -th frame; a segment of
/// length L ends at the first frame whose ground-truth path distance from the start exceeds L.
SegmentError kittiSegmentError(const std::vector<Eigen::Isometry3d>& ground_truth,
                               const std::vector<Eigen::Isometry3d>& estimate,
                               const std::vector<double>& lengths_m = {100, 200, 300, 400, 500, 600, 700, 800},
                               int step_frames = 10);

/// Rotation angle of @p R in degrees, accurate near 0 and π (atan2 of sine and cosine rather than acos).
double rotationAngleDeg(const Eigen::Matrix3d& R);

}  // namespace sgtllc::eval
