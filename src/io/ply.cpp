// ASCII PLY export of semantic graphs (PLY format: Turk 1994 / Paul Bourke's "PLY - Polygon File Format").
#include "sgtllc/io/ply.h"

#include <string>

#include "file_util.h"

namespace sgtllc::io {
namespace {

// SemanticKITTI's color_map (semantic-kitti.yaml) for ids 50, 51, 70, 71, 72, 80, 81, converted from its BGR
// order to RGB, so graphs look like the labelled scans in the usual viewers.
constexpr std::array<std::array<uint8_t, 3>, kNumClasses> kPalette = {{
    {255, 200, 0},    // building
    {255, 120, 50},   // fence
    {0, 175, 0},      // vegetation
    {135, 60, 0},     // trunk
    {150, 240, 80},   // terrain
    {255, 240, 150},  // pole
    {255, 0, 0},      // traffic-sign
}};

void appendColor(std::string& out, const std::array<uint8_t, 3>& rgb) {
  for (uint8_t c : rgb) out += ' ' + std::to_string(static_cast<int>(c));
}

std::string header(size_t vertices, size_t edges) {
  return "ply\n"
         "format ascii 1.0\n"
         "comment sgtllc semantic graph: label = stable class index (0 building .. 6 traffic-sign)\n"
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

void checkGraph(const std::string& path, const std::vector<Node>& nodes, const std::vector<PlyEdge>& edges) {
  detail::checkNodeLabels(path, nodes);
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

std::array<uint8_t, 3> classColor(int label) {
  if (label < 0 || label >= kNumClasses) {
    throw Error("classColor: " + std::to_string(label) + " is not a stable class index 0.." +
                std::to_string(kNumClasses - 1));
  }
  return kPalette[static_cast<size_t>(label)];
}

void writeGraphPly(const std::string& path, const std::vector<Node>& nodes, const std::vector<PlyEdge>& edges,
                   Overwrite overwrite) {
  checkGraph(path, nodes, edges);
  std::string out = header(nodes.size(), edges.size());
  for (const Node& node : nodes) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out += ' ';
      // Declared float: most viewers ignore double vertices.
      detail::appendShortest(out, static_cast<float>(node.centre[k]));
    }
    appendColor(out, classColor(node.label));
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
