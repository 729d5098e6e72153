#include "frame_reducer.h"

#include <chrono>
#include <string>

#include "elapsed.h"

namespace sgtllc::pipeline {

FrameReducer::FrameReducer(const Config& config)
    : labeller_(config.labels, config.labeller),
      extractor_(config.cluster, labeller_.nodeLabels(), config.graph.max_nodes),
      store_(config.registration, labeller_.nodeLabels()),
      verification_(config.verification) {}

LoadedFrame FrameReducer::reduce(const LabeledCloud& input) const {
  LoadedFrame f;
  auto start = std::chrono::steady_clock::now();
  LabeledCloud labelled;
  if (labeller_.changesLabels()) labelled = labeller_.apply(input);
  const LabeledCloud& cloud = labeller_.changesLabels() ? labelled : input;
  NodeExtractionResult r = extractor_.extract(cloud, verification_, &f.footprint);
  f.extraction_ms = msSince(start);  // with the geometric labeller, labelling included
  f.nodes = std::move(r.nodes);
  f.stats = r.stats;
  start = std::chrono::steady_clock::now();
  f.clouds = store_.prepare(cloud);
  f.clouds_ms = msSince(start);
  return f;
}

void FrameReducer::checkLabels(const LabeledCloud& scan, int frame) const {
  if (scan.labels.size() == scan.points.size() || !readsLabels()) return;
  throw Error("frame " + std::to_string(frame) + ": " + std::to_string(scan.points.size()) + " points but " +
              std::to_string(scan.labels.size()) +
              " labels (a label per point is needed unless labeller.source is geometric)");
}

LoadedFrame FrameReducer::reduceScan(const LabeledCloud& scan, int frame) const {
  checkLabels(scan, frame);
  if (scan.labels.size() == scan.points.size()) return reduce(scan);
  LabeledCloud copy = scan;
  copy.labels.assign(copy.points.size(), 0);
  return reduce(copy);
}

}  // namespace sgtllc::pipeline
