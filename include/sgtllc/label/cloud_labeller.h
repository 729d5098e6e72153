/// @file cloud_labeller.h
/// @brief The classes the node extraction sees, as labeller.source says: the scan's label file, the geometric
///        labeller alone, or the label file with the classes it lacks split off by geometry (docs/labeller.md §6).
///
/// Some label sets cannot tell apart classes the graph needs: nuScenes-lidarseg has one class, static.manmade, for
/// buildings, walls, poles and signs, and none for trunks. Poles and trunks are the nodes that come back best
/// across viewpoints (BENCHMARKS.md, "Node repeatability on real scans"), so with labeller.source hybrid the
/// geometric labeller's poles are taken from inside the label file's building class (as pole) and vegetation class
/// (as trunk) whenever the label set has no class of its own for them. With a label set that has both (the
/// SemanticKITTI presets) hybrid is the label file as it is.
#pragma once

#include "sgtllc/config.h"
#include "sgtllc/label/geometric_labeller.h"
#include "sgtllc/types.h"

namespace sgtllc::label {

/// Labels a cloud for the node extraction. Immutable after construction; safe to share between threads.
class CloudLabeller {
 public:
  /// @p labels: the label files' convention (Config::labels); @p labeller: labeller.source and its settings.
  CloudLabeller(const LabelConfig& labels, const LabellerConfig& labeller);

  /// False if apply() would return the cloud as it is (source file, or hybrid with nothing to split): callers then
  /// use the cloud without the copy.
  bool changesLabels() const { return source_ != LabelSource::kFile; }
  /// Whether the label files are read at all (not with source geometric).
  bool readsLabelFiles() const { return source_ != LabelSource::kGeometric; }

  /// @p cloud with the labels the node extraction is to see, in the convention of nodeLabels(): unchanged for
  /// source file; SemanticKITTI ids for geometric (its labels are not read) and hybrid. Throws sgtllc::Error if
  /// hybrid and the labels and points differ in length.
  LabeledCloud apply(LabeledCloud cloud) const;
  /// apply() with the geometric labeller's @p shapes of the cloud's points already at hand (the labeller is then
  /// not run again). Throws sgtllc::Error if @p shapes is of another length.
  LabeledCloud apply(LabeledCloud cloud, const Labelling& shapes) const;

  /// The label space of apply()'s output (effectiveLabelConfig).
  const LabelConfig& nodeLabels() const { return node_labels_; }

 private:
  LabelSource source_;
  GeometricLabeller geometric_;
  LabelMap file_map_;
  LabelConfig node_labels_;
  HybridSplits splits_;  // hybrid: building points the labeller calls pole become pole, vegetation ones trunk
};

}  // namespace sgtllc::label
