/// @file retrieval_key.h
/// @brief The key a frame is stored and searched by (RetrievalConfig::key).
#pragma once

#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/graph.h"

namespace sgtllc::retrieval {

/// Length of the key for @p config: distanceHistogramSize or globalDescriptorSize over Config::numClasses().
int retrievalKeySize(const Config& config);

/// The key of a frame with graph @p graph: its class-pair distance histogram (computeDistanceHistogram) or its
/// Des^G (computeGlobalDescriptor with config.descriptor), as config.retrieval.key says.
std::vector<float> computeRetrievalKey(const SemanticGraph& graph, const Config& config);

}  // namespace sgtllc::retrieval
