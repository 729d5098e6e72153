/// @file trajectory_frame.h
/// @brief The frame of a KITTI-format trajectory, stated by the user or read from the file's motion.
///
/// KITTI-format (12-column) files come in two frames: KITTI's own poses and most tools that follow it are in cam0
/// (x right, y down, z forward); KISS-ICP and others write the LiDAR's (x forward, y left, z up). Read in the wrong
/// frame, the loop edges (LiDAR frame) disagree with the odometry and the back end rejects true loops, so the frame
/// is never guessed silently: `--calib` (cam0, its Tr converts), `--pose-frame lidar`, or the motion decides, and
/// then the choice is printed.
///
/// The motion: a car moves along its forward axis and turns about its up axis. For consecutive poses the step
/// T_i⁻¹ · T_{i+1} is expressed in the earlier pose's own axes, so its translation shows the forward axis (most
/// |displacement|) and its rotation vector the up axis (most |rotation|), whatever the world frame.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::io {

/// The frame a KITTI-format trajectory is read in (`--pose-frame`, Python's `pose_frame`).
enum class PoseFrame {
  kAuto,   ///< a calib means cam0; without one the motion decides (detectPoseFrame) and the choice is printed
  kLidar,  ///< LiDAR poses: taken as they are, no calib applied
  kCam0,   ///< KITTI cam0 poses: converted to the LiDAR frame by a calib's Tr (required)
};

/// "auto", "lidar", "cam0" → PoseFrame; throws sgtllc::Error naming the three otherwise.
PoseFrame parsePoseFrame(const std::string& name);
const char* poseFrameName(PoseFrame frame);

/// What the motion of a trajectory says about its frame.
struct FrameEvidence {
  enum class Verdict { kLidar, kCam0, kUndecided };
  Verdict verdict = Verdict::kUndecided;
  double path_m = 0.0;      ///< summed step length
  double turn_deg = 0.0;    ///< summed step rotation angle
  int forward_axis = -1;    ///< 0, 1, 2 = x, y, z: the axis of most summed |displacement| (-1: no motion)
  int up_axis = -1;         ///< the axis of most summed |rotation vector| (-1: no rotation)
  Eigen::Vector3d forward_share = Eigen::Vector3d::Zero();  ///< summed |displacement| per axis / total
  Eigen::Vector3d up_share = Eigen::Vector3d::Zero();       ///< summed |rotation vector| per axis / total
  std::string reason;       ///< why undecided (empty when decided)
};

/// Thresholds of detectPoseFrame.
struct FrameDetection {
  double min_path_m = 5.0;        ///< less motion than this: undecided (a standing or too short trajectory)
  double min_forward_share = 0.8; ///< the forward axis must carry this share of the summed |displacement|
  double min_turn_deg = 30.0;     ///< with this much turning the up axis must agree with the forward axis's frame
};

/// Decides the frame of @p poses (T_world_frame as 4×4, in file order) from their motion: forward x with up z is
/// LiDAR, forward z with up y is cam0. Undecided when the path is short, no axis carries a clear majority, the
/// forward axis is y, or (with enough turning) the up axis disagrees. Pure: no files, no printing.
FrameEvidence detectPoseFrame(const std::vector<Eigen::Matrix4d>& poses, const FrameDetection& thresholds = {});

/// "motion along x (97 %), turning about z (99 %), 212 m": the evidence, for messages.
std::string evidenceText(const FrameEvidence& evidence);

/// How a KITTI file is to be read, as frameChoice() settles it.
struct FrameChoice {
  bool through_calib = false;  ///< convert with the calib's Tr (cam0 poses); else take the poses as LiDAR poses
  std::string note;            ///< a line for the user when the motion decided (empty otherwise)
  bool warning = false;        ///< the note doubts what the user gave (a calib): print it as a warning
};

/// The rule for a KITTI-format file @p path with file poses @p poses, a calib given or not, and @p frame:
/// - lidar: as LiDAR poses (no calib applied);
/// - cam0: through the calib; without one, an error naming --calib;
/// - auto with a calib: through it (the calib says cam0); if the motion clearly says LiDAR, a warning (a LiDAR file
///   passed through a calib is wrong too) that names --pose-frame lidar;
/// - auto without a calib: motion LiDAR → read as LiDAR with a note; motion cam0 → an error naming --calib;
///   undecided → an error asking for --pose-frame lidar or --calib.
/// Throws sgtllc::Error with those messages, naming @p path.
FrameChoice frameChoice(const std::string& path, const std::vector<Eigen::Matrix4d>& poses, bool has_calib,
                        PoseFrame frame);

}  // namespace sgtllc::io
