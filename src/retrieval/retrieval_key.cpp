#include "sgtllc/retrieval/retrieval_key.h"

#include "sgtllc/global_descriptor.h"
#include "sgtllc/retrieval/distance_histogram.h"

namespace sgtllc::retrieval {

int retrievalKeySize(const Config& config) {
  if (config.retrieval.key == RetrievalKey::kGlobalDescriptor) {
    return globalDescriptorSize(config.descriptor.global_mode, config.numClasses());
  }
  return distanceHistogramSize(config.numClasses(), config.retrieval.histogram_bins);
}

std::vector<float> computeRetrievalKey(const SemanticGraph& graph, const Config& config) {
  if (config.retrieval.key == RetrievalKey::kGlobalDescriptor) return computeGlobalDescriptor(graph, config.descriptor);
  return computeDistanceHistogram(graph, config.retrieval);
}

}  // namespace sgtllc::retrieval
