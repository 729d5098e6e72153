/// @file pcd.h
/// @brief PCD input (ascii, binary and binary_compressed), with a per-point label field or points only, and PCD
///        node export.
///
/// Accepted: PCL's PCD v0.7 header (v0.6 files without VIEWPOINT, and a missing COUNT line meaning COUNT 1, are
/// accepted too; VERSION is informational). WIDTH × HEIGHT must equal POINTS; organised clouds are read row by
/// row. DATA ascii (one point per line, blank lines ignored), binary (little-endian records, point by point) and
/// binary_compressed (uint32 compressed size, uint32 uncompressed size, then LZF data holding each field's values
/// for all points, field after field).
#pragma once

#include <string>
#include <vector>

#include "sgtllc/io/output_file.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

/// Reads fields x, y, z and the label field @p label_field of a PCD file.
///
/// - x, y, z must be F4 or F8 with COUNT 1 (F8 is narrowed to float); NaN coordinates are kept.
/// - The label field must have COUNT 1 and may be U1/U2/U4/U8, I1/I2/I4/I8 or F4/F8. Float labels are rounded to
///   the nearest integer; negative labels wrap to uint32 (−1 → 0xFFFFFFFF, which is no stable class). Labels
///   outside [−2³¹, 2³²) or non-finite are an error.
/// - Every other field (any type, any COUNT, e.g. intensity, rgb, normals, "_" padding) is skipped.
///
/// Throws sgtllc::Error naming the file (and the line for header and ascii problems) if the file cannot be read, a
/// header line is malformed (`PATH:LINE: malformed header line: ...`), DATA is not one of the three kinds
/// (`unsupported DATA type 'X'`), a field is missing (`no field 'label' (fields: x y z rgb)`), the data is truncated
/// (`truncated binary data: N points need B bytes, found F`) or the LZF block is corrupt.
LabeledCloud readPcd(const std::string& path, const std::string& label_field = "label");

/// Reads fields x, y, z of a PCD file, as readPcd does, and no label (a raw scan for the geometric labeller; any
/// label field present is skipped like every other field). Throws sgtllc::Error as readPcd, except that no label
/// field is needed.
std::vector<Eigen::Vector3f> readPcdPoints(const std::string& path);

/// The FIELDS of a PCD file, in file order (its header only is parsed). Throws as readPcd for a missing file or a
/// malformed header.
std::vector<std::string> pcdFieldNames(const std::string& path);

/// Writes nodes as an ascii PCD v0.7 with fields x y z (F4) and label (U4, the stable class index 0..C−1 for
/// C = @p num_classes, Config::numClasses()), readable by PCL as pcl::PointXYZL. Coordinates are written as the
/// shortest text that reads back to the same float.
/// Throws sgtllc::Error naming the file if a label is outside 0..C−1 or the file cannot be written.
/// With Overwrite::kRefuse an existing file is kept and the call throws (output_file.h).
void writeNodesPcd(const std::string& path, const std::vector<Node>& nodes, int num_classes = kNumPaperClasses,
                   Overwrite overwrite = Overwrite::kReplace);

}  // namespace sgtllc::io
