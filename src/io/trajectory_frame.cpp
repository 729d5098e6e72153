// The frame of a KITTI-format trajectory from its motion, and the rule that combines it with --calib and
// --pose-frame (trajectory_frame.h).
#include "sgtllc/io/trajectory_frame.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "sgtllc/types.h"

namespace sgtllc::io {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

char axisName(int axis) { return axis < 0 ? '?' : static_cast<char>('x' + axis); }

std::string percent(double share) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "%.0f %%", 100.0 * share);
  return buf;
}

std::string rounded(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.0f", v);
  return buf;
}

int largest(const Eigen::Vector3d& v) {
  if (v.sum() <= 0.0) return -1;
  int k = 0;
  v.maxCoeff(&k);
  return k;
}

}  // namespace

PoseFrame parsePoseFrame(const std::string& name) {
  if (name == "auto") return PoseFrame::kAuto;
  if (name == "lidar") return PoseFrame::kLidar;
  if (name == "cam0") return PoseFrame::kCam0;
  throw Error("pose frame '" + name + "' is not one of auto, lidar, cam0");
}

const char* poseFrameName(PoseFrame frame) {
  switch (frame) {
    case PoseFrame::kLidar: return "lidar";
    case PoseFrame::kCam0: return "cam0";
    case PoseFrame::kAuto: break;
  }
  return "auto";
}

FrameEvidence detectPoseFrame(const std::vector<Eigen::Matrix4d>& poses, const FrameDetection& thresholds) {
  FrameEvidence e;
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero(), rotation = Eigen::Vector3d::Zero();
  for (size_t i = 0; i + 1 < poses.size(); ++i) {
    // The step in frame i's own axes: R_iᵀ (t_{i+1} − t_i) and the rotation R_iᵀ R_{i+1}. File rotations are
    // orthonormal to ~1e-6 (trajectory.h), so the transpose is the inverse here.
    const Eigen::Matrix3d Ri = poses[i].topLeftCorner<3, 3>();
    const Eigen::Vector3d d = Ri.transpose() * (poses[i + 1].topRightCorner<3, 1>() - poses[i].topRightCorner<3, 1>());
    const Eigen::Quaterniond q(Eigen::Matrix3d(Ri.transpose() * poses[i + 1].topLeftCorner<3, 3>()));
    const Eigen::AngleAxisd step(q.normalized());
    if (!d.allFinite() || !std::isfinite(step.angle())) continue;
    displacement += d.cwiseAbs();
    rotation += (step.axis() * step.angle()).cwiseAbs();
    e.path_m += d.norm();
    e.turn_deg += std::abs(step.angle()) * kRadToDeg;
  }
  if (displacement.sum() > 0.0) e.forward_share = displacement / displacement.sum();
  if (rotation.sum() > 0.0) e.up_share = rotation / rotation.sum();
  e.forward_axis = largest(displacement);
  e.up_axis = largest(rotation);

  if (e.path_m < thresholds.min_path_m) {
    e.reason = "only " + rounded(e.path_m) + " m of motion, at least " + rounded(thresholds.min_path_m) + " needed";
    return e;
  }
  const double forward = e.forward_share[e.forward_axis];
  if (forward < thresholds.min_forward_share) {
    e.reason = "no axis carries " + percent(thresholds.min_forward_share) + " of the motion: x " +
               percent(e.forward_share.x()) + ", y " + percent(e.forward_share.y()) + ", z " +
               percent(e.forward_share.z());
    return e;
  }
  if (e.forward_axis == 1) {
    e.reason = "motion along y, forward in neither frame (LiDAR: x, cam0: z)";
    return e;
  }
  const bool lidar = e.forward_axis == 0;
  const int expected_up = lidar ? 2 : 1;
  if (e.turn_deg >= thresholds.min_turn_deg && e.up_axis != expected_up) {
    e.reason = std::string("motion along ") + axisName(e.forward_axis) + " but turning about " +
               axisName(e.up_axis) + ", where " + (lidar ? "LiDAR" : "cam0") + " poses turn about " +
               axisName(expected_up);
    return e;
  }
  e.verdict = lidar ? FrameEvidence::Verdict::kLidar : FrameEvidence::Verdict::kCam0;
  return e;
}

std::string evidenceText(const FrameEvidence& e) {
  if (e.forward_axis < 0) return "no motion";
  std::string text = std::string("motion along ") + axisName(e.forward_axis) + " (" +
                     percent(e.forward_share[e.forward_axis]) + " of " + rounded(e.path_m) + " m)";
  if (e.up_axis < 0) return text + ", no turning";
  return text + ", turning about " + axisName(e.up_axis) + " (" + percent(e.up_share[e.up_axis]) + " of " +
         rounded(e.turn_deg) + " deg)";
}

FrameChoice frameChoice(const std::string& path, const std::vector<Eigen::Matrix4d>& poses, bool has_calib,
                        PoseFrame frame) {
  FrameChoice c;
  if (frame == PoseFrame::kLidar) return c;
  if (frame == PoseFrame::kCam0) {
    if (!has_calib) {
      throw Error(path + ": --pose-frame cam0 needs --calib CALIB.txt (its Tr brings cam0 poses into the LiDAR frame)");
    }
    c.through_calib = true;
    return c;
  }
  const FrameEvidence e = detectPoseFrame(poses);
  if (has_calib) {
    // The calib says cam0 and is applied: what the user states wins. Clear LiDAR motion is worth a warning, since
    // LiDAR poses passed through a calib are as wrong as cam0 poses read as LiDAR ones.
    c.through_calib = true;
    if (e.verdict == FrameEvidence::Verdict::kLidar) {
      c.warning = true;
      c.note = path + ": these KITTI poses move as LiDAR poses do (" + evidenceText(e) +
               "), yet the calib's Tr converts them as cam0 poses; --pose-frame lidar if they are LiDAR poses, "
               "--pose-frame cam0 to say they are cam0";
    }
    return c;
  }
  switch (e.verdict) {
    case FrameEvidence::Verdict::kLidar:
      c.note = path + ": KITTI poses read in the LiDAR frame (" + evidenceText(e) +
               "); --pose-frame lidar to say so, --calib for cam0 poses";
      return c;
    case FrameEvidence::Verdict::kCam0:
      throw Error(path + ": these KITTI poses move along their z axis, as KITTI's cam0 poses do (" + evidenceText(e) +
                  "); give --calib CALIB.txt (its Tr brings them into the LiDAR frame), or --pose-frame lidar if "
                  "they are LiDAR poses");
    case FrameEvidence::Verdict::kUndecided: break;
  }
  throw Error(path + ": cannot tell the frame of these KITTI poses from their motion (" + e.reason +
              "); give --pose-frame lidar for LiDAR poses (x forward, z up), or --calib CALIB.txt for cam0 poses "
              "(KITTI's poses.txt: z forward, y down)");
}

}  // namespace sgtllc::io
