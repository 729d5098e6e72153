/// @file scan_file.h
/// @brief One scan file in any of the formats sgtllc reads (KITTI .bin, PCD, PLY), told apart by its extension.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

enum class ScanFormat {
  kKittiBin,  ///< `.bin`: float32 x y z intensity (kitti.h); labels in a separate .label file
  kPcd,       ///< `.pcd` (pcd.h): labels in a label field or a separate .label file
  kPly,       ///< `.ply` (ply_read.h): labels in a label property or a separate .label file
};

/// The format of @p path by its extension (`.bin`, `.pcd`, `.ply`, in any letter case); nullopt for any other.
std::optional<ScanFormat> scanFormatOf(const std::string& path);

/// ".bin", ".pcd" or ".ply".
const char* scanExtension(ScanFormat format);

/// The points of a scan, x y z only: a .bin's intensity and a PCD's or PLY's other fields (a label too) are
/// skipped. Throws sgtllc::Error naming the file for an extension that is none of the three, or as the readers do.
std::vector<Eigen::Vector3f> readScanPoints(const std::string& path);

/// Whether a PCD or PLY scan has a per-point field (PLY: vertex property) @p name; only its header is parsed.
/// Always false for a .bin, whose labels are in a separate file.
bool scanHasField(const std::string& path, const std::string& name);

/// The points and the label field @p label_field of a PCD or PLY scan (readPcd / readPly). Throws sgtllc::Error
/// naming the file for a .bin (its labels are in a separate .label file) or an unknown extension.
LabeledCloud readScanWithLabelField(const std::string& path, const std::string& label_field);

/// The points of a scan in any format with the labels of @p label_path (uint32 or one byte a point, @p format;
/// readLabelFileOf): the count error names both files.
LabeledCloud readScanWithLabelFile(const std::string& path, const std::string& label_path,
                                   LabelFormat format = LabelFormat::kAuto);

}  // namespace sgtllc::io
