/// @file frame.h
/// @brief A frame's semantic graph with its local and global descriptors: everything matching needs.
#pragma once

#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/descriptor.h"
#include "sgtllc/footprint.h"
#include "sgtllc/global_descriptor.h"
#include "sgtllc/graph.h"

namespace sgtllc {

struct DescribedFrame {
  SemanticGraph graph;                ///< nodes, adjacency and second-order topology
  std::vector<LocalDescriptor> local; ///< one per node
  std::vector<float> global;          ///< Des^G
  Footprint footprint;                ///< the scan's structure cells (footprint.h); empty for node input

  int numNodes() const { return graph.size(); }
};

/// Graph (algorithm §3), local descriptors (§4) and global descriptor (§5) of a node set over @p num_classes classes
/// (Config::numClasses(); the paper's seven by default). A pure function of the nodes and the configuration, so a
/// database can store nodes alone and rebuild this on demand. Verifying a stored candidate needs no global
/// descriptor (retrieval used the stored one): @p with_global = false skips it and leaves `global` empty.
DescribedFrame describeFrame(std::vector<Node> nodes, const GraphConfig& graph, const DescriptorConfig& descriptor,
                             bool with_global = true, int num_classes = kNumPaperClasses);

}  // namespace sgtllc
