#include "sgtllc/frame.h"

#include <utility>

namespace sgtllc {

DescribedFrame describeFrame(std::vector<Node> nodes, const GraphConfig& graph, const DescriptorConfig& descriptor,
                             bool with_global, int num_classes) {
  DescribedFrame f;
  f.graph = buildGraph(std::move(nodes), graph, num_classes);
  f.local = computeLocalDescriptors(f.graph, descriptor);
  if (with_global) f.global = computeGlobalDescriptor(f.graph, descriptor);
  return f;
}

}  // namespace sgtllc
