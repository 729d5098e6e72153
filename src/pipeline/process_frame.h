// A reduced frame handed to the detector, with what reducing it cost carried into the result: the one way the
// sequence stream (frame_source.cpp) and the pipeline (loop_closing_pipeline.cpp) feed the detector.
#pragma once

#include <utility>

#include "sgtllc/detector.h"
#include "sgtllc/pipeline/frame_source.h"

namespace sgtllc::pipeline {

/// LoopDetector::process of @p frame's nodes, clouds and footprint (moved out), with its extraction time, cloud
/// time and point bookkeeping in the result. Throws what process() throws; the frame is then not stored.
inline FrameResult processFrame(LoopDetector& detector, LoadedFrame& frame) {
  FrameResult r = detector.process(std::move(frame.nodes), std::move(frame.clouds), std::move(frame.footprint));
  r.timing.extraction_ms = frame.extraction_ms;
  r.timing.refinement_ms += frame.clouds_ms;
  r.extraction = frame.stats;
  return r;
}

}  // namespace sgtllc::pipeline
