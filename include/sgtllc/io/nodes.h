/// @file nodes.h
/// @brief Plain-text node files, for users who extract their own objects: one node `x y z label` per line.
///
/// Format: whitespace-separated rows `x y z label`, where x, y, z are the node centre in metres (sensor frame) and
/// label is a raw semantic id (e.g. a SemanticKITTI raw id such as 50 = building) that a LabelMap maps to a stable
/// class, exactly like a per-point label. Blank lines and lines whose first non-blank character is '#' are
/// ignored; CRLF line ends are accepted. Numbers are parsed independently of the C locale.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/labels.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

/// What readNodesTxt saw. rows = nodes returned + dropped_known + unknown.
struct NodeFileStats {
  size_t rows = 0;           ///< data rows read (not counting blank and comment lines)
  size_t dropped_known = 0;  ///< rows skipped: id in the preset's label space but not a stable class (road = 40)
  size_t unknown = 0;        ///< rows skipped: id outside the preset's label space (LabelMap::isKnown is false)
};

/// Reads a node file. Each row's id becomes a stable class with @p labels (LabelMap::classOf, which uses the low
/// 16 bits of the id); rows whose id maps to kDropped are skipped and counted in @p stats (if given). Nodes keep
/// the order of their rows. An empty file, or one with only comments, gives no nodes.
///
/// Throws sgtllc::Error: `cannot open PATH: REASON` if the file cannot be read; `PATH:LINE: ...` for a row
/// without exactly 4 values, a coordinate that is not a finite number, or a label that is not an unsigned 32-bit
/// decimal integer.
std::vector<Node> readNodesTxt(const std::string& path, const LabelMap& labels, NodeFileStats* stats = nullptr);

/// Writes one row per node after a comment line `# x y z label (SemanticKITTI raw id)`. The label is written as
/// the SemanticKITTI raw id of the node's class (building 50, fence 51, vegetation 70, trunk 71, terrain 72,
/// pole 80, traffic-sign 81) and, for an extra class of @p labels, as its first id in ExtraClass::ids (with
/// preset custom and no ids: the lowest custom_map id of the class), so readNodesTxt with LabelMap(@p labels)
/// (the SemanticKITTI preset) reads the nodes back; coordinates are written as the shortest text that reads back
/// to the same double (std::to_chars), so the round trip is exact.
/// Throws sgtllc::Error naming the file, before creating it, if a label is outside 0..C−1 (C =
/// labels.numClasses()), an extra class has no id, or a coordinate is not finite; and if the file cannot be
/// written.
/// With Overwrite::kRefuse an existing file is kept and the call throws (output_file.h).
void writeNodesTxt(const std::string& path, const std::vector<Node>& nodes, const LabelConfig& labels = {},
                   Overwrite overwrite = Overwrite::kReplace);

}  // namespace sgtllc::io
