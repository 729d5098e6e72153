// Helpers shared by the test suites: bundled data paths, rigid transforms, pose errors (the bundled KITTI scans:
// test_kitti_support.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/types.h"

namespace sgtllc::test {

inline std::string dataPath(const std::string& relative) { return std::string(SGTLLC_DATA_DIR) + "/" + relative; }

/// Rigid transform from yaw, pitch, roll (degrees) and a translation (m).
inline Eigen::Matrix4d rigid(double yaw_deg, double pitch_deg, double roll_deg, const Eigen::Vector3d& t) {
  const double k = M_PI / 180.0;
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = (Eigen::AngleAxisd(yaw_deg * k, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(pitch_deg * k, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(roll_deg * k, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  T.topRightCorner<3, 1>() = t;
  return T;
}

/// The rigid transform with rotation @p R and translation @p t.
inline Eigen::Matrix4d makeT(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = R;
  T.topRightCorner<3, 1>() = t;
  return T;
}

/// T · p.
inline Eigen::Vector3d apply(const Eigen::Matrix4d& T, const Eigen::Vector3d& p) {
  return T.topLeftCorner<3, 3>() * p + T.topRightCorner<3, 1>();
}

/// Applies T to every point (in double, rounded back to float).
inline LabeledCloud transformed(const LabeledCloud& cloud, const Eigen::Matrix4d& T) {
  LabeledCloud out = cloud;
  for (auto& p : out.points) {
    p = (T.topLeftCorner<3, 3>() * p.cast<double>() + T.topRightCorner<3, 1>()).cast<float>();
  }
  return out;
}

/// Translation error (m) and rotation error (deg) of an estimate against a reference.
struct PoseError {
  double translation_m;
  double rotation_deg;
};

inline PoseError poseError(const Eigen::Matrix4d& estimate, const Eigen::Matrix4d& reference) {
  const Eigen::Matrix3d dR = estimate.topLeftCorner<3, 3>().transpose() * reference.topLeftCorner<3, 3>();
  const double c = std::clamp((dR.trace() - 1.0) / 2.0, -1.0, 1.0);
  return {(estimate.topRightCorner<3, 1>() - reference.topRightCorner<3, 1>()).norm(), std::acos(c) * 180.0 / M_PI};
}

/// ICP-refined reference T_a_b, a = 000052, b = 004501 (data/kitti/00/README.md, from the KITTI GT poses refined
/// by point-to-point ICP): maps points of 4501 into the frame of 52.
inline Eigen::Matrix4d referencePose4501To52() {
  Eigen::Matrix4d T;
  T << 0.999969, 0.000985, -0.007755, 2.988495,  //
      -0.000916, 0.999961, 0.008825, 0.177681,   //
      0.007763, -0.008817, 0.999931, 0.029293,   //
      0, 0, 0, 1;
  return T;
}

}  // namespace sgtllc::test
