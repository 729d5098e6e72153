#include "sgtllc/label/cloud_labeller.h"

#include <string>

namespace sgtllc::label {
namespace {

/// An id outside SemanticKITTI's label space, for ids outside the label file's.
constexpr uint32_t kUnknownId = 0xFFFFu;

}  // namespace

CloudLabeller::CloudLabeller(const LabelConfig& labels, const LabellerConfig& labeller)
    : source_(labeller.source), geometric_(labeller), file_map_(labels), node_labels_(labels) {
  if (source_ == LabelSource::kFile) return;
  node_labels_ = LabelConfig{};
  if (source_ == LabelSource::kHybrid) {
    splits_ = hybridSplits(labels);
    if (!splits_.any()) {
      source_ = LabelSource::kFile;  // nothing to split: the label file as it is
      node_labels_ = labels;
    }
  }
}

LabeledCloud CloudLabeller::apply(LabeledCloud cloud) const {
  if (source_ == LabelSource::kFile) return cloud;
  if (source_ == LabelSource::kGeometric) return labelCloud(std::move(cloud.points), geometric_);
  if (cloud.labels.size() != cloud.points.size()) {
    throw Error("hybrid labels: " + std::to_string(cloud.labels.size()) + " labels for " +
                std::to_string(cloud.points.size()) + " points");
  }
  const Labelling shapes = geometric_.classify(cloud.points);
  for (size_t i = 0; i < cloud.labels.size(); ++i) {
    if (!file_map_.isKnown(cloud.labels[i])) {
      cloud.labels[i] = kUnknownId;  // still counted as an unknown id by the node extraction
      continue;
    }
    int c = file_map_.classOf(cloud.labels[i]);
    if (shapes.classes[i] == kPole) {
      if (c == kBuilding && splits_.pole) c = kPole;
      if (c == kVegetation && splits_.trunk) c = kTrunk;
    }
    cloud.labels[i] = semanticKittiId(c);
  }
  return cloud;
}

}  // namespace sgtllc::label
