/// @file ply.h
/// @brief ASCII PLY export of semantic graphs (vertices coloured by class, edges as PLY edge elements).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sgtllc/io/output_file.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

/// RGB colour of a stable class index 0..C−1 (C = @p num_classes, Config::numClasses()). The paper's classes
/// take SemanticKITTI's colour map (semantic-kitti.yaml, which lists BGR): building (255,200,0), fence
/// (255,120,50), vegetation (0,175,0), trunk (135,60,0), terrain (150,240,80), pole (255,240,150) and
/// traffic-sign (255,0,0). Extra classes 7..15 take fixed distinct colours by index: (100,150,245) blue,
/// (160,32,240) purple, (0,200,200) cyan, (255,0,255) magenta, (30,30,160) navy, (0,110,110) teal,
/// (200,150,255) lavender, (110,50,150) plum, (255,150,200) pink. Throws sgtllc::Error for any other label.
std::array<uint8_t, 3> classColor(int label, int num_classes = kNumPaperClasses);

/// One graph edge between vertex indices, with its own colour.
struct PlyEdge {
  int a = 0;                                       ///< index into the node list
  int b = 0;                                       ///< index into the node list
  std::array<uint8_t, 3> color = {128, 128, 128};  ///< RGB
};

/// Writes an ascii PLY 1.0: `element vertex` (float x y z, uchar red green blue, uchar label) and `element edge`
/// (int vertex1 vertex2, uchar red green blue). Vertex colours come from classColor(label, num_classes).
/// Throws sgtllc::Error naming the file, before creating it, if a node label is outside 0..C−1 (C =
/// @p num_classes) or an edge index is outside [0, nodes.size()); and if the file cannot be written.
/// With Overwrite::kRefuse an existing file is kept and the call throws (output_file.h).
void writeGraphPly(const std::string& path, const std::vector<Node>& nodes, const std::vector<PlyEdge>& edges,
                   int num_classes = kNumPaperClasses, Overwrite overwrite = Overwrite::kReplace);

}  // namespace sgtllc::io
