// `--accumulate N` of `run` and `eval`: each frame merged with the N − 1 raw scans before it, moved by
// the --odometry poses or by the sequence's poses.txt, before node extraction (accumulate/scan_accumulator.h).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common.h"
#include "loop_closing.h"
#include "sgtllc/pipeline/frame_source.h"

namespace sgtllc::cli {

/// Adds `--accumulate N` to @p cmd (1 = off, the default).
void addAccumulateOption(CLI::App& cmd, int& scans);

/// With @p scans > 1, makes @p source accumulate: by @p odometry's poses if given (the --odometry file, read once
/// for the back end too), else by SEQ_DIR/poses.txt read by the pose-frame rule with @p calib (default
/// SEQ_DIR/calib.txt) and @p frame. Throws sgtllc::Error naming the file if it is missing, malformed or has not one
/// pose per frame, or if its frame is cam0 or undecided without a calib (readOdometry).
void applyAccumulation(pipeline::FrameSource& source, int scans, const Odometry* odometry, const std::string& sequence,
                       const std::string& calib, io::PoseFrame frame);

/// What accumulation cost over a run: merge time per frame and the largest buffer.
struct AccumulationCost {
  std::vector<double> ms;   ///< per frame
  size_t max_bytes = 0;     ///< LoadedFrame::buffer_bytes, largest over the run

  void add(const pipeline::LoadedFrame& frame);
  Json json(int scans) const;
  std::string text(int scans) const;
};

}  // namespace sgtllc::cli
