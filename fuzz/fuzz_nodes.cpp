// Node files `x y z label` (io::readNodesTxt), with a write → re-read round trip of whatever was read.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/nodes.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("nodes.txt"), copy("nodes-copy.txt");
  static const LabelMap labels;  // the default SemanticKITTI raw-id preset
  file.write(fuzz::bytesOf(data, size));
  std::vector<Node> nodes;
  io::NodeFileStats stats;
  if (!fuzz::readsOrRejects([&] { nodes = io::readNodesTxt(file.path(), labels, &stats); })) return 0;
  fuzz::require(nodes.size() + stats.dropped_known + stats.unknown == stats.rows, "every row counted once");
  for (const Node& n : nodes) fuzz::require(n.label >= 0 && n.label < kNumPaperClasses, "stable class labels");

  // What was read must write and read back unchanged (the writer prints the shortest exact decimal).
  io::writeNodesTxt(copy.path(), nodes);
  const std::vector<Node> again = io::readNodesTxt(copy.path(), labels);
  fuzz::require(again.size() == nodes.size(), "round trip keeps the node count");
  for (size_t i = 0; i < nodes.size(); ++i) {
    fuzz::require(again[i].centre == nodes[i].centre && again[i].label == nodes[i].label, "round trip is exact");
  }
  return 0;
}
