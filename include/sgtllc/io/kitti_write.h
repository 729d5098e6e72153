/// @file kitti_write.h
/// @brief Writers for the KITTI / SemanticKITTI files that kitti.h reads: velodyne .bin, .label, poses.txt,
///        calib.txt and times.txt. Each throws sgtllc::Error `cannot write PATH: REASON` and writes little-endian.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include "sgtllc/io/output_file.h"

namespace sgtllc::io {

// Every writer writes a temporary file and renames it into place (output_file.h); @p overwrite says whether an
// existing file may be replaced.

/// N × 4 float32 (x, y, z, intensity). Throws if the two lists differ in length.
void writeKittiBin(const std::string& path, const std::vector<Eigen::Vector3f>& points,
                   const std::vector<float>& intensity, Overwrite overwrite = Overwrite::kReplace);

/// N uint32 words (semantic id in the low 16 bits, instance id in the high 16).
void writeLabelFile(const std::string& path, const std::vector<uint32_t>& labels,
                    Overwrite overwrite = Overwrite::kReplace);

/// One row-major 3×4 [R|t] per line (the top three rows of each 4×4). Numbers are written in their shortest form
/// that reads back to the same double, so readKittiPoses() returns exactly these poses.
void writeKittiPoses(const std::string& path, const std::vector<Eigen::Matrix4d>& poses,
                     Overwrite overwrite = Overwrite::kReplace);
/// The text writeKittiPoses() writes (for writers that add their own file handling, e.g. trajectory.h).
std::string kittiPosesText(const std::vector<Eigen::Matrix4d>& poses);

/// `P0:` … `P3:` (3×4 projection matrices) and `Tr:` (velodyne → cam0, top three rows), `%.12e` as KITTI's.
void writeKittiCalib(const std::string& path, const std::array<Eigen::Matrix<double, 3, 4>, 4>& P,
                     const Eigen::Matrix4d& Tr, Overwrite overwrite = Overwrite::kReplace);

/// One time stamp (s) per line, `%e` as KITTI's times.txt.
void writeKittiTimes(const std::string& path, const std::vector<double>& times,
                     Overwrite overwrite = Overwrite::kReplace);

/// KITTI odometry sequence 00's calibration (calib.txt of sequences 00–02): P0..P3 and Tr.
std::array<Eigen::Matrix<double, 3, 4>, 4> kittiProjections();
Eigen::Matrix4d kittiVelodyneToCam0();

}  // namespace sgtllc::io
