#include "sgtllc/eval/ground_truth.h"

#include <Eigen/LU>

#include "sgtllc/io/kitti.h"

namespace sgtllc::eval {

GroundTruth::GroundTruth(std::vector<Eigen::Matrix4d> lidar_poses) : poses_(std::move(lidar_poses)) {}

GroundTruth GroundTruth::fromKitti(const std::string& poses_path, const std::string& calib_path) {
  return GroundTruth(io::lidarPoses(io::readKittiPoses(poses_path), io::readKittiCalibTr(calib_path)));
}

double GroundTruth::distance(long a, long b) const {
  return (pose(a).topRightCorner<3, 1>() - pose(b).topRightCorner<3, 1>()).norm();
}

Eigen::Matrix4d GroundTruth::relative(long match, long query) const { return pose(match).inverse() * pose(query); }

}  // namespace sgtllc::eval
