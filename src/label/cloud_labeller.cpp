#include "sgtllc/label/cloud_labeller.h"

#include <string>

namespace sgtllc::label {
namespace {

/// An id outside SemanticKITTI's label space, for ids outside the label file's.
constexpr uint32_t kUnknownId = 0xFFFFu;

}  // namespace

CloudLabeller::CloudLabeller(const LabelConfig& labels, const LabellerConfig& labeller)
    : source_(labeller.source),
      geometric_(labeller),
      file_map_(labels),
      node_labels_(effectiveLabelConfig(labels, labeller)),
      splits_(hybridSplits(labels)) {
  if (source_ == LabelSource::kHybrid && !splits_.any()) source_ = LabelSource::kFile;  // the label file as it is
}

LabeledCloud CloudLabeller::apply(LabeledCloud cloud) const {
  if (source_ == LabelSource::kFile) return cloud;
  const Labelling shapes = geometric_.classify(cloud.points);
  return apply(std::move(cloud), shapes);
}

LabeledCloud CloudLabeller::apply(LabeledCloud cloud, const Labelling& shapes) const {
  if (source_ == LabelSource::kFile) return cloud;
  if (shapes.classes.size() != cloud.points.size()) {
    throw Error("labelling of " + std::to_string(shapes.classes.size()) + " points for a cloud of " +
                std::to_string(cloud.points.size()));
  }
  if (source_ == LabelSource::kGeometric) {
    cloud.labels = semanticKittiIds(shapes);
    return cloud;
  }
  if (cloud.labels.size() != cloud.points.size()) {
    throw Error("hybrid labels: " + std::to_string(cloud.labels.size()) + " labels for " +
                std::to_string(cloud.points.size()) + " points");
  }
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
