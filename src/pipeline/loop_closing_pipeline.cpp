#include "sgtllc/pipeline/loop_closing_pipeline.h"

#include <chrono>
#include <cstdio>
#include <utility>

#include "elapsed.h"
#include "frame_reducer.h"
#include "process_frame.h"
#include "sgtllc/accumulate/scan_accumulator.h"

namespace sgtllc::pipeline {

Eigen::Isometry3d orthonormalised(const Eigen::Isometry3d& T) {
  Eigen::Isometry3d out = T;
  out.linear() = Eigen::Quaterniond(T.rotation()).normalized().toRotationMatrix();
  return out;
}

LoopClosingPipeline::LoopClosingPipeline(const Config& config, PipelineOptions options)
    : options_(options), detector_(config), reducer_(std::make_unique<FrameReducer>(config)) {
  // Any other count than 1 makes an accumulator, whose constructor checks the range with its own message.
  if (options_.accumulate != 1) accumulator_ = std::make_unique<ScanAccumulator>(options_.accumulate);
}

LoopClosingPipeline::~LoopClosingPipeline() = default;
LoopClosingPipeline::LoopClosingPipeline(LoopClosingPipeline&&) noexcept = default;
LoopClosingPipeline& LoopClosingPipeline::operator=(LoopClosingPipeline&&) noexcept = default;

int LoopClosingPipeline::numFrames() const { return detector_.numFrames(); }

PipelineFrame LoopClosingPipeline::addScan(const LabeledCloud& scan,
                                           const std::optional<Eigen::Isometry3d>& T_world_frame, std::string name) {
  if (!accumulator_) return addFrame(reducer_->reduceScan(scan, numFrames()), T_world_frame, std::move(name));
  reducer_->checkLabels(scan, numFrames());
  LabeledCloud copy = scan;
  // The geometric labeller replaces the labels; placeholders keep points and labels paired until it does.
  if (copy.labels.size() != copy.points.size()) copy.labels.assign(copy.points.size(), 0);
  if (!T_world_frame) {
    throw Error("frame " + std::to_string(numFrames()) + ": accumulating scans needs each scan's pose");
  }
  checkPose(T_world_frame);  // before the scan joins the buffer
  const auto start = std::chrono::steady_clock::now();
  const LabeledCloud merged = accumulator_->add(std::move(copy), orthonormalised(*T_world_frame));
  const double accumulate_ms = msSince(start);
  LoadedFrame frame = reducer_->reduce(merged);
  frame.accumulate_ms = accumulate_ms;
  frame.buffer_bytes = accumulator_->bytes();
  return addFrame(std::move(frame), T_world_frame, std::move(name));
}

PipelineFrame LoopClosingPipeline::addNodes(std::vector<Node> nodes,
                                            const std::optional<Eigen::Isometry3d>& T_world_frame, std::string name) {
  LoadedFrame frame;
  frame.nodes = std::move(nodes);
  return addFrame(std::move(frame), T_world_frame, std::move(name));
}

void LoopClosingPipeline::checkPose(const std::optional<Eigen::Isometry3d>& T_world_frame) const {
  const std::string frame = "frame " + std::to_string(numFrames());
  if (closing_) throw Error(frame + ": the drive was finished (finish() was called)");
  if (numFrames() > 0 && T_world_frame.has_value() != hasPoses()) {
    throw Error(frame + (T_world_frame ? " has a pose, the frames before had none"
                                       : " has no pose, the frames before had one") +
                ": give a pose with every frame or with none");
  }
  if (!T_world_frame && options_.online) throw Error(frame + ": online solving needs each frame's odometry pose");
  if (T_world_frame && !T_world_frame->matrix().allFinite()) throw Error(frame + ": its pose is not finite");
}

void LoopClosingPipeline::addPose(const Eigen::Isometry3d& T_world_frame) {
  odometry_.push_back(orthonormalised(T_world_frame));
  if (!options_.online) return;
  if (!online_) {
    online_ = std::make_unique<OnlineClosing>(config().backend, odometry_.front());
  } else {
    online_->addFrame(odometry_.back());
  }
}

PipelineFrame LoopClosingPipeline::addFrame(LoadedFrame frame, const std::optional<Eigen::Isometry3d>& T_world_frame,
                                            std::string name) {
  checkPose(T_world_frame);
  PipelineFrame out;
  out.index = numFrames();
  // A frame the detector refuses (too many nodes, a bad centre) is not stored, and its pose is not kept either.
  out.detection = processFrame(detector_, frame);
  if (T_world_frame) addPose(*T_world_frame);
  if (name.empty()) {
    char text[16];
    std::snprintf(text, sizeof(text), "%06d", out.index);
    name = text;
  }
  names_.push_back(std::move(name));
  if (const Candidate* c = out.detection.loop()) {
    out.loop = loops_.emplace_back(detectedLoop(out.index, *c, detector_.database(), names_.back(),
                                                names_.at(static_cast<size_t>(c->frame)), config().backend.loops));
    if (online_) {
      const auto start = std::chrono::steady_clock::now();
      out.update = &online_->closeLoop(loops_.back());
      out.solve_ms = msSince(start);
      out.solved = true;
    }
  }
  return out;
}

const Closing& LoopClosingPipeline::finish() {
  if (closing_) throw Error("finish() was called already");
  if (!hasPoses()) throw Error("closing the loops needs the frames' odometry poses; none were given");
  closing_ = std::make_unique<Closing>(online_ ? online_->finish()
                                               : closeLoopsBatch(odometry_, loops_, config().backend));
  return *closing_;
}

const std::vector<Eigen::Isometry3d>& LoopClosingPipeline::poses() const {
  if (closing_) return closing_->poses;
  if (online_) return online_->poses();
  return odometry_;
}

map::Map LoopClosingPipeline::map(std::optional<std::vector<Eigen::Matrix4d>> poses) const {
  std::vector<Eigen::Matrix4d> placed;
  if (poses) {
    placed = std::move(*poses);
  } else {
    for (const Eigen::Isometry3d& T : this->poses()) placed.push_back(T.matrix());
  }
  return map::makeMap(detector_.database(), config(), names_, std::move(placed), detector_.footprints());
}

}  // namespace sgtllc::pipeline
