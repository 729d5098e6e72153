// Helpers shared by the test suites: bundled data paths, rigid transforms, pose errors.
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/types.h"

namespace sgtllc::test {

inline std::string dataPath(const std::string& relative) { return std::string(SGTLLC_DATA_DIR) + "/" + relative; }

/// A bundled KITTI 00 scan with its SemanticKITTI labels, e.g. kittiScan("004501").
inline LabeledCloud kittiScan(const std::string& frame) {
  return io::readLabeledScan(dataPath("kitti/00/velodyne/" + frame + ".bin"),
                             dataPath("kitti/00/labels/" + frame + ".label"));
}

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

/// Writes a SemanticKITTI-layout sequence of 54 frames into @p dir: the real scans 52 and 88, 50 frames
/// without any stable class (one road point), 850, and 4501 (frame 53, a revisit of frame 0 2.96 m away).
/// poses.txt gives the real KITTI poses of the real scans and far-away poses (> 1 km) to the padding frames;
/// calib.txt is KITTI 00's.
inline void makePlantedSequence(const std::string& dir) {
  namespace fs = std::filesystem;
  fs::create_directories(fs::path(dir) / "velodyne");
  fs::create_directories(fs::path(dir) / "labels");
  const std::vector<Eigen::Matrix4d> kitti = io::readKittiPoses(dataPath("kitti/00/poses.txt"));
  std::ofstream poses(fs::path(dir) / "poses.txt");
  poses.precision(17);
  int index = 0;
  auto add = [&](const std::string& bin, const std::string& label, const Eigen::Matrix4d& pose) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d", index++);
    fs::copy_file(bin, fs::path(dir) / "velodyne" / (std::string(name) + ".bin"));
    fs::copy_file(label, fs::path(dir) / "labels" / (std::string(name) + ".label"));
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) poses << pose(r, c) << (r == 2 && c == 3 ? "\n" : " ");
    }
  };
  auto real = [&](int frame) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d", frame);
    add(dataPath("kitti/00/velodyne/" + std::string(name) + ".bin"),
        dataPath("kitti/00/labels/" + std::string(name) + ".label"), kitti.at(static_cast<size_t>(frame)));
  };
  real(52);
  real(88);
  const std::string one_bin = (fs::path(dir) / "one.bin").string(), one_label = (fs::path(dir) / "one.label").string();
  std::ofstream(one_bin, std::ios::binary).write("\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0", 16);
  const uint32_t road = 40;
  std::ofstream(one_label, std::ios::binary).write(reinterpret_cast<const char*>(&road), 4);
  for (int k = 0; k < 50; ++k) {
    Eigen::Matrix4d far = Eigen::Matrix4d::Identity();
    far(0, 3) = 2000.0 + 100.0 * k;
    add(one_bin, one_label, far);
  }
  fs::remove(one_bin);
  fs::remove(one_label);
  real(850);
  real(4501);
  fs::copy_file(dataPath("kitti/00/calib.txt"), fs::path(dir) / "calib.txt");
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
