/// @file ground_truth.h
/// @brief Ground-truth LiDAR poses of a sequence and the distances and relative poses derived from them.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::eval {

class GroundTruth {
 public:
  GroundTruth() = default;
  /// LiDAR-frame poses, one per frame number.
  explicit GroundTruth(std::vector<Eigen::Matrix4d> lidar_poses);
  /// From a KITTI poses.txt (cam0 poses) and calib.txt (`Tr:`): T_lidar = Tr⁻¹ · P · Tr.
  static GroundTruth fromKitti(const std::string& poses_path, const std::string& calib_path);

  size_t size() const { return poses_.size(); }
  bool has(long frame) const { return frame >= 0 && static_cast<size_t>(frame) < poses_.size(); }
  const Eigen::Matrix4d& pose(long frame) const { return poses_.at(static_cast<size_t>(frame)); }
  /// 3-D distance between the LiDAR positions of two frames (m).
  double distance(long a, long b) const;
  /// T_match_query = T_match⁻¹ · T_query: maps points of @p query into the frame of @p match.
  Eigen::Matrix4d relative(long match, long query) const;

 private:
  std::vector<Eigen::Matrix4d> poses_;
};

}  // namespace sgtllc::eval
