/// @file ply_read.h
/// @brief PLY input: the points (x, y, z) of a point cloud's `vertex` element, with a per-point label property or
///        without one.
///
/// Accepted (Turk's PLY format, as written by PCL, Open3D, CloudCompare and `sgtllc label --export`): `format
/// ascii 1.0`, `binary_little_endian 1.0` and `binary_big_endian 1.0`; `comment` and `obj_info` lines; any
/// elements, of which `vertex` is read and the others (faces, edges, before or after it) are skipped; scalar
/// properties of the types char/int8, uchar/uint8, short/int16, ushort/uint16, int/int32, uint/uint32,
/// float/float32 and double/float64, and list properties (skipped). An ascii element is one line.
#pragma once

#include <string>
#include <vector>

#include "sgtllc/types.h"

namespace sgtllc::io {

/// Reads x, y, z and the label property @p label_field of a PLY file's vertex element.
///
/// - x, y, z must be float or double scalars (double is narrowed to float); NaN coordinates are kept.
/// - The label may be any scalar type. Float labels are rounded to the nearest integer; negative labels wrap to
///   uint32 (−1 → 0xFFFFFFFF), as readPcd does; non-finite labels or labels outside [−2³¹, 2³²) are an error.
/// - Every other property is skipped.
///
/// Throws sgtllc::Error naming the file (and the line for header and ascii problems) if it cannot be read, is not
/// a PLY file, has a malformed header line (`PATH:LINE: malformed header line: ...`), no vertex element, a missing
/// property (`no property 'label' in element vertex (properties: x y z red green blue)`), or truncated data.
LabeledCloud readPly(const std::string& path, const std::string& label_field = "label");

/// Reads x, y, z of a PLY file's vertex element, as readPly does, and no label (any label property is skipped).
std::vector<Eigen::Vector3f> readPlyPoints(const std::string& path);

/// The property names of a PLY file's vertex element, in file order (its header only is parsed). Throws as
/// readPly for a missing file, a malformed header or no vertex element.
std::vector<std::string> plyVertexProperties(const std::string& path);

}  // namespace sgtllc::io
