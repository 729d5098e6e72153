// ASCII PLY export of semantic graphs (PLY format: Turk 1994 / Paul Bourke's "PLY - Polygon File Format").
#include "sgtllc/io/ply.h"

#include <algorithm>
#include <string>

#include "file_util.h"

namespace sgtllc::io {
namespace {

// SemanticKITTI's color_map (semantic-kitti.yaml) for ids 50, 51, 70, 71, 72, 80, 81, converted from its BGR
// order to RGB, so graphs look like the labelled scans in the usual viewers.
// Extra classes (7, 8, …) take the next colours: saturated hues far from the seven and from the grey edges.
constexpr std::array<std::array<uint8_t, 3>, kMaxClasses> kPalette = {{
    {255, 200, 0},    // building
    {255, 120, 50},   // fence
    {0, 175, 0},      // vegetation
    {135, 60, 0},     // trunk
    {150, 240, 80},   // terrain
    {255, 240, 150},  // pole
    {255, 0, 0},      // traffic-sign
    {100, 150, 245},  // extra class 7 (blue, as SemanticKITTI's car)
    {160, 32, 240},   // 8: purple
    {0, 200, 200},    // 9: cyan
    {255, 0, 255},    // 10: magenta
    {30, 30, 160},    // 11: navy
    {0, 110, 110},    // 12: teal
    {200, 150, 255},  // 13: lavender
    {110, 50, 150},   // 14: plum
    {255, 150, 200},  // 15: pink
}};

void appendColor(std::string& out, const std::array<uint8_t, 3>& rgb) {
  for (uint8_t c : rgb) out += ' ' + std::to_string(static_cast<int>(c));
}

std::string header(size_t vertices, size_t edges, int num_classes) {
  const std::string extra = num_classes > kNumPaperClasses ? ", then the configuration's extra classes" : "";
  return "ply\n"
         "format ascii 1.0\n"
         "comment sgtllc semantic graph: label = stable class index (0 building .. 6 traffic-sign" + extra + ")\n"
         "element vertex " + std::to_string(vertices) + "\n"
         "property float x\n"
         "property float y\n"
         "property float z\n"
         "property uchar red\n"
         "property uchar green\n"
         "property uchar blue\n"
         "property uchar label\n"
         "element edge " + std::to_string(edges) + "\n"
         "property int vertex1\n"
         "property int vertex2\n"
         "property uchar red\n"
         "property uchar green\n"
         "property uchar blue\n"
         "end_header\n";
}

void checkGraph(const std::string& path, const std::vector<Node>& nodes, const std::vector<PlyEdge>& edges,
                int num_classes) {
  detail::checkNodeLabels(path, nodes, num_classes);
  const auto n = static_cast<long long>(nodes.size());
  for (size_t k = 0; k < edges.size(); ++k) {
    const PlyEdge& e = edges[k];
    if (e.a < 0 || e.b < 0 || e.a >= n || e.b >= n) {
      throw Error("cannot write " + path + ": edge " + std::to_string(k) + " joins vertices " + std::to_string(e.a) +
                  " and " + std::to_string(e.b) + " but there are " + std::to_string(n) + " vertices");
    }
  }
}

}  // namespace

std::array<uint8_t, 3> classColor(int label, int num_classes) {
  if (label < 0 || label >= std::min(num_classes, kMaxClasses)) {
    throw Error("classColor: " + std::to_string(label) + " is not a stable class index 0.." +
                std::to_string(num_classes - 1));
  }
  return kPalette[static_cast<size_t>(label)];
}

void writeGraphPly(const std::string& path, const std::vector<Node>& nodes, const std::vector<PlyEdge>& edges,
                   int num_classes, Overwrite overwrite) {
  checkGraph(path, nodes, edges, num_classes);
  std::string out = header(nodes.size(), edges.size(), num_classes);
  for (const Node& node : nodes) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out += ' ';
      // Declared float: most viewers ignore double vertices.
      detail::appendShortest(out, static_cast<float>(node.centre[k]));
    }
    appendColor(out, classColor(node.label, num_classes));
    out += ' ' + std::to_string(node.label) + '\n';
  }
  for (const PlyEdge& e : edges) {
    out += std::to_string(e.a) + ' ' + std::to_string(e.b);
    appendColor(out, e.color);
    out += '\n';
  }
  writeFileAtomically(path, out, overwrite);
}

}  // namespace sgtllc::io
