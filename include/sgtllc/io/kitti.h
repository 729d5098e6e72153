/// @file kitti.h
/// @brief KITTI / SemanticKITTI files: velodyne .bin scans, .label files, poses.txt and calib.txt.
///
/// Every reader throws sgtllc::Error with a message that names the file and the problem, e.g.
/// `cannot open PATH: No such file or directory`, `PATH: size 17 bytes is not a multiple of 16 (x y z intensity
/// float32)`, `PATH:LINE: expected 12 numbers (row-major 3x4), found 11`. Binary files are little-endian.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

/// Reads a KITTI velodyne scan: N × 4 little-endian float32 (x, y, z, intensity); the size must be 16·N bytes.
/// An empty file is a scan with 0 points. Non-finite coordinates are kept (the pipeline drops and counts them).
/// Intensities go to @p intensity if given (resized to N).
std::vector<Eigen::Vector3f> readKittiBin(const std::string& path, std::vector<float>* intensity = nullptr);

/// Reads a SemanticKITTI .label file: N little-endian uint32 words (semantic id = low 16 bits, instance = high 16).
/// The size must be a multiple of 4 bytes; an empty file gives no labels.
std::vector<uint32_t> readLabelFile(const std::string& path);

/// Reads the label file of a scan of @p point_count points. LabelFormat::kUint32 needs 4·N bytes (as above),
/// kUint8 N bytes (one id 0..255 a point: nuScenes-lidarseg and its KITTI-layout conversions), kAuto takes
/// whichever of the two the file size is (they differ for N > 0). Any other size throws, naming N, the file, its
/// size and the size(s) that fit: `point/label count mismatch: the scan has 5 points but A.label has 17 bytes,
/// neither 20 (uint32 labels, 4 bytes a point) nor 5 (uint8 labels, 1 byte a point)`.
std::vector<uint32_t> readLabelFile(const std::string& path, size_t point_count, LabelFormat format = LabelFormat::kAuto);

/// readLabelFile(path, point_count, format) for the scan @p scan_path (any format: a PCD or PLY scan's labels may
/// be a .label file too), whose name the size error gives instead of "the scan".
std::vector<uint32_t> readLabelFileOf(const std::string& path, const std::string& scan_path, size_t point_count,
                                      LabelFormat format = LabelFormat::kAuto);

/// Reads a scan and its labels (in @p format; see readLabelFile) and checks that there is one label a point; the
/// error names both files, the point count and the label file's size (`point/label count mismatch: A.bin has 3
/// points but A.label has 8 bytes, neither 12 (uint32 labels, 4 bytes a point) nor 3 (uint8 labels, 1 byte a
/// point)`).
LabeledCloud readLabeledScan(const std::string& bin_path, const std::string& label_path,
                             LabelFormat format = LabelFormat::kAuto);

/// Label file that belongs to a scan: `DIR/../labels/NAME.label` for a scan `DIR/NAME.bin` (the SemanticKITTI
/// layout `seq/velodyne/NAME.bin` + `seq/labels/NAME.label`) if that file exists, else `DIR/NAME.label` next to the
/// scan. Returns the chosen path even if it does not exist (reading it then gives the usual "cannot open" error).
std::string defaultLabelPath(const std::string& bin_path);

/// Reads KITTI odometry poses: one row-major 3×4 [R|t] per line (cam0 of frame i in cam0 of frame 0), as 4×4.
/// Numbers may be written as `1`, `1.5` or `1.000000e+00` and are parsed as doubles independently of the C locale.
/// Blank lines at the end are ignored; a blank line followed by more poses is an error (frame i must be line i), as
/// is a line without exactly 12 finite numbers (the message gives `PATH:LINE`). An empty file gives no poses.
std::vector<Eigen::Matrix4d> readKittiPoses(const std::string& path);

/// Reads the `Tr:` line of a KITTI odometry calib.txt (velodyne → cam0, p_cam = Tr · p_velo) as a 4×4 matrix.
/// Throws if the file has no `Tr:` line, has two, or the line does not hold 12 numbers.
Eigen::Matrix4d readKittiCalibTr(const std::string& path);

/// LiDAR-frame poses from cam0 poses: T_lidar_i = Tr⁻¹ · P_i · Tr (the exact 4×4 inverse of Tr is used).
/// The relative pose of scan b in scan a is then T_a_b = T_lidar_a⁻¹ · T_lidar_b (p_a = T_a_b · p_b).
/// Throws if Tr is not invertible.
std::vector<Eigen::Matrix4d> lidarPoses(const std::vector<Eigen::Matrix4d>& cam_poses, const Eigen::Matrix4d& Tr);

}  // namespace sgtllc::io
