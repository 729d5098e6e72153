// A labelled scan reduced to what the detector keeps of a frame: the labeller's classes (when it changes them), the
// nodes, the footprint and the registration clouds. Shared by the sequence reader (frame_source.cpp) and the
// pipeline's scan input (loop_closing_pipeline.cpp), so a scan given either way becomes the same frame.
#pragma once

#include "sgtllc/config.h"
#include "sgtllc/label/cloud_labeller.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/registration/cloud_store.h"

namespace sgtllc::pipeline {

class FrameReducer {
 public:
  explicit FrameReducer(const Config& config);

  /// Whether the scan's own labels are used (not with labeller.source geometric, which replaces them).
  bool readsLabels() const { return labeller_.readsLabelFiles(); }
  /// The frame of @p scan (points in the sensor frame). LoadedFrame::extraction_ms includes the labelling. A pure
  /// function of the scan: safe to call from several threads.
  LoadedFrame reduce(const LabeledCloud& scan) const;
  /// Throws sgtllc::Error naming frame @p frame unless @p scan has a label per point or the labels are not read.
  void checkLabels(const LabeledCloud& scan, int frame) const;
  /// reduce() of a scan given with a label per point or, when the labels are not read, with any (placeholders take
  /// their place until the geometric labeller replaces them); checkLabels() first.
  LoadedFrame reduceScan(const LabeledCloud& scan, int frame) const;

 private:
  label::CloudLabeller labeller_;
  NodeExtractor extractor_;
  CloudStore store_;  // prepare() only
  VerificationConfig verification_;
};

}  // namespace sgtllc::pipeline
