/// @file trajectory.h
/// @brief Trajectory files in the two formats of the field: KITTI poses (12 columns) and TUM (8 columns).
///
/// One pose per frame, frames in sequence order. The reader tells the formats apart by the column count of the
/// first pose line; every other line must have the same count. A trajectory remembers its format, its TUM time
/// stamps and whether it came through a KITTI calib, so writeTrajectory() writes a corrected trajectory in the
/// same format and frame as the odometry it came from (`evo_ape kitti gt.txt corrected.txt` then just works).
///
/// Errors are sgtllc::Error naming the file, the line and the problem, e.g.
/// `odo.txt:7: 10 columns; expected 12 (KITTI: row-major 3x4 [R|t]) or 8 (TUM: t x y z qx qy qz qw)`,
/// `odo.txt:3: 8 columns, but line 1 has 12 (one format per file)`,
/// `odo.txt:2: quaternion (2, 0, 0, 0) has norm 2, not 1`, `odo.txt:4: rotation is not orthonormal (|RᵀR − I| = 0.2)`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sgtllc/io/output_file.h"
#include "sgtllc/io/trajectory_frame.h"

namespace sgtllc::io {

/// The two trajectory formats.
enum class TrajectoryFormat {
  kKitti,  ///< `r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz` per line (KITTI odometry poses.txt)
  kTum,    ///< `t x y z qx qy qz qw` per line (TUM RGB-D; time stamp in seconds, Hamilton quaternion, w last)
};

/// A trajectory: pose i is frame i of the sequence.
struct Trajectory {
  TrajectoryFormat format = TrajectoryFormat::kKitti;
  /// T_world_frame (p_world = T · p_frame). In the LiDAR frame if read through a calib (KITTI) or from TUM
  /// (taken as given), else in the file's own frame (KITTI without calib: cam0 or LiDAR, as the file was written;
  /// the pose-frame overload of readTrajectory settles which). KITTI rotations are kept
  /// as written (orthonormal to the file's precision, checked to 1e-3), so a file written back is the same.
  std::vector<Eigen::Isometry3d> poses;
  /// TUM time stamps (s), one per pose; empty for KITTI.
  std::vector<double> stamps;
  /// The calib's Tr (velodyne → cam0) if the file was KITTI read with a calib: poses were converted
  /// T_lidar = Tr⁻¹ · P · Tr and are written back as P = Tr · T_lidar · Tr⁻¹.
  std::optional<Eigen::Matrix4d> calib_Tr;
};

/// Reads a KITTI or TUM trajectory (told apart by column count). Blank lines at the end are ignored; a blank line
/// followed by more poses is an error (pose i must be line i); `#` comment lines are allowed in TUM files only
/// (TUM's own files start with them). KITTI rows: 12 finite numbers, rotation orthonormal within 1e-3 with
/// determinant > 0. TUM rows: 8 finite numbers, quaternion norm within 1e-3 of 1 (it is normalised), time stamps
/// increasing. An empty file is an error (no poses).
///
/// @p calib_path (optional): a KITTI calib.txt whose `Tr:` converts KITTI cam0 poses to the LiDAR frame
/// (readKittiCalibTr / lidarPoses in kitti.h). It applies to KITTI files only: TUM files are taken as they are
/// (LiDAR frame, like KISS-ICP's TUM output), and `calib_Tr` stays empty for them.
/// Without a calib a KITTI file is returned in its own frame, whatever that is: the CLI and Python read through
/// the overload below, which never guesses the frame silently.
Trajectory readTrajectory(const std::string& path, const std::string& calib_path = "");

/// A trajectory read by the pose-frame rule, and how its frame was settled.
struct FramedTrajectory {
  Trajectory trajectory;  ///< poses in the LiDAR frame (calib_Tr set if converted)
  FrameChoice choice;     ///< choice.note: the line to print when the motion decided (TUM: empty)
};

/// Reads @p path with the rule of frameChoice() (trajectory_frame.h) for KITTI files: `--calib` (@p calib_path)
/// means cam0, `--pose-frame` is @p frame, else the motion decides and says so in `choice.note`. TUM files are
/// LiDAR poses as given (with @p frame cam0 an error). Throws sgtllc::Error naming the file and what to add.
FramedTrajectory readTrajectory(const std::string& path, const std::string& calib_path, PoseFrame frame);

/// The text of @p trajectory in its own format (and frame: cam0 again if it came through a calib). Numbers are
/// written in their shortest exact form, so readTrajectory() gives back the same poses (to rounding of the
/// calib and quaternion conversions, ~1e-15). TUM needs one stamp per pose; throws sgtllc::Error if not.
std::string trajectoryText(const Trajectory& trajectory);

/// Writes trajectoryText(@p trajectory) to @p path via a temporary file and a rename (a failure never leaves half
/// a file). Replaces an existing file: deciding whether that is allowed (--force) is the caller's job.
void writeTrajectory(const std::string& path, const Trajectory& trajectory,
                     Overwrite overwrite = Overwrite::kReplace);

/// @p trajectory with its poses replaced by @p poses (same format, stamps and calib): the corrected trajectory
/// of an odometry input. Throws sgtllc::Error if the counts differ.
Trajectory withPoses(const Trajectory& trajectory, std::vector<Eigen::Isometry3d> poses);

/// Throws sgtllc::Error `AT: rotation is not orthonormal (|RᵀR − I| = E, at most 0.001)` or `AT: rotation has
/// determinant D (a reflection)` unless @p R is a rotation to a KITTI file's precision: the check every trajectory
/// reader (and Python's pose arrays) applies.
void checkRotation(const Eigen::Matrix3d& R, const std::string& at);

/// Throws sgtllc::Error `PATH: N poses but the sequence has M frames (one pose per frame, in sequence order)`
/// unless @p trajectory has exactly @p frames poses; @p path names the file in the message.
void checkPoseCount(const std::string& path, const Trajectory& trajectory, size_t frames);

}  // namespace sgtllc::io
