// Plain-text node files `x y z label` (label = raw semantic id).
#include "sgtllc/io/nodes.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "file_util.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io {
namespace {

// SemanticKITTI raw id of each stable class (semantic-kitti.yaml), in class-index order (algorithm §1 table).
constexpr std::array<uint32_t, kNumPaperClasses> kSemanticKittiRawId = {50, 51, 70, 71, 72, 80, 81};

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

/// Parses one data row into @p centre and @p id; @p where ("FILE:LINE") prefixes the error.
void parseRow(const std::vector<std::string_view>& tokens, const std::string& where, Eigen::Vector3d& centre,
              uint32_t& id) {
  if (tokens.size() != 4) {
    throw Error(where + ": expected 4 values (x y z label), found " + std::to_string(tokens.size()));
  }
  for (int k = 0; k < 3; ++k) {
    const std::string_view token = tokens[static_cast<size_t>(k)];
    if (!detail::parseReal(token, centre[k]) || !std::isfinite(centre[k])) {
      throw Error(where + ": " + kAxisNames[k] + " " + quoteContent(token) + " is not a finite number");
    }
  }
  if (!detail::parseInteger(tokens[3], id)) {
    throw Error(where + ": label " + quoteContent(tokens[3]) + " is not an unsigned 32-bit integer id");
  }
}

/// The raw id written for class @p c: SemanticKITTI's for the paper's seven, the first declared id of an extra
/// class, or (preset custom) the lowest custom_map id that targets it.
uint32_t rawIdOf(int c, const LabelConfig& labels, const std::string& path) {
  if (c < kNumPaperClasses) return kSemanticKittiRawId[static_cast<size_t>(c)];
  const ExtraClass& extra = labels.extra_classes[static_cast<size_t>(c - kNumPaperClasses)];
  if (!extra.ids.empty()) return extra.ids.front();
  for (const auto& [id, cls] : labels.custom_map) {
    if (cls == c) return id;
  }
  throw Error("cannot write " + path + ": class '" + extra.name + "' has no raw id to write");
}

}  // namespace

std::vector<Node> readNodesTxt(const std::string& path, const LabelMap& labels, NodeFileStats* stats) {
  const std::string text = detail::readWholeFile(path);
  std::vector<Node> nodes;
  NodeFileStats counts;
  size_t pos = 0;
  size_t line_no = 0;
  while (pos < text.size()) {
    ++line_no;
    const std::vector<std::string_view> tokens = detail::splitBlanks(detail::nextLine(text, pos));
    if (tokens.empty() || tokens.front().front() == '#') continue;
    Node node;
    uint32_t id = 0;
    parseRow(tokens, path + ":" + std::to_string(line_no), node.centre, id);
    ++counts.rows;
    const int8_t cls = labels.classOf(id);
    if (cls == kDropped) {
      ++(labels.isKnown(id) ? counts.dropped_known : counts.unknown);
      continue;
    }
    node.label = cls;
    nodes.push_back(node);
  }
  if (stats) *stats = counts;
  return nodes;
}

void writeNodesTxt(const std::string& path, const std::vector<Node>& nodes, const LabelConfig& labels,
                   Overwrite overwrite) {
  detail::checkNodeLabels(path, nodes, labels.numClasses());
  std::vector<uint32_t> ids(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) ids[i] = rawIdOf(nodes[i].label, labels, path);
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].centre.allFinite()) {
      throw Error("cannot write " + path + ": node " + std::to_string(i) + " has a non-finite centre");
    }
  }
  std::string out = "# x y z label (SemanticKITTI raw id)\n";
  for (size_t i = 0; i < nodes.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      detail::appendShortest(out, nodes[i].centre[k]);
      out += ' ';
    }
    out += std::to_string(ids[i]) + '\n';
  }
  writeFileAtomically(path, out, overwrite);
}

}  // namespace sgtllc::io
