// Closing the loop from the command line (docs/backend.md): the odometry input, and the corrected trajectory / g2o
// outputs and summaries shared by `run`, `optimize` and `eval`. The closing itself is the pipeline's
// (sgtllc/pipeline/closing.h).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/Geometry>

#include "common.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/pipeline/closing.h"

namespace sgtllc::cli {

/// The --odometry file: as read (so the corrected trajectory is written back in its format and frame) and its
/// poses in the LiDAR frame with rotations projected onto SO(3) (the KITTI Tr conversion leaves them orthonormal
/// to ~1e-7 only).
struct Odometry {
  std::string path;
  io::Trajectory trajectory;
  std::vector<Eigen::Isometry3d> poses;
};

/// Adds `--pose-frame auto|lidar|cam0` (the frame of a KITTI-format --odometry, described by @p what) to @p cmd.
void addPoseFrameOption(CLI::App& cmd, io::PoseFrame& frame, const std::string& what);

/// Throws CLI::ValidationError if an explicit --calib (@p calib) is given with `--pose-frame lidar` and nothing
/// else (@p calib_has_other_use: optimize's --ground-truth) reads it.
void checkPoseFrameOptions(const std::string& command, const std::string& calib, io::PoseFrame frame,
                           bool calib_has_other_use = false);

/// Reads a KITTI or TUM trajectory in the LiDAR frame by the pose-frame rule (io/trajectory_frame.h: @p calib means
/// cam0, @p frame, else the motion decides and a note says so on stderr); with @p frames > 0 it must have one pose
/// per frame. Throws sgtllc::Error naming the file, the line and the problem, or what to add.
Odometry readOdometry(const std::string& path, const std::string& calib, io::PoseFrame frame, size_t frames);

/// The calib for a KITTI odometry of a sequence folder: @p calib if given, else SEQ_DIR/calib.txt if it exists (the
/// KITTI convention: poses in cam0, Tr in the sequence's calib.txt), else none.
std::string sequenceCalib(const std::string& calib, const std::string& sequence);

using pipeline::Closing;
using pipeline::ClosingLoop;

/// Output files of the back end (empty = not written).
struct ClosingOutputs {
  std::string trajectory;  ///< --out-trajectory: corrected trajectory, same format and frame as the odometry
  std::string graph;       ///< --out-graph: g2o of the corrected poses, odometry and accepted loop edges
  std::string loops;       ///< --out-loops: every loop as a g2o edge line, rejected ones after a comment
};

void addClosingOutputOptions(CLI::App& cmd, ClosingOutputs& outputs);
/// checkWritable on every output, before any work.
void checkClosingOutputs(const ClosingOutputs& outputs, bool force);

/// One line on a loop's decision after an online update.
std::string onlineUpdateLine(const pipeline::BackendResult& r, double ms);

/// Writes the outputs that are set. The g2o graph holds the corrected poses, the odometry edges and the accepted
/// loops; the loop list every loop, each rejected or injected one after a `# ` comment saying so.
void writeClosingOutputs(const ClosingOutputs& outputs, const Odometry& odometry,
                         const std::vector<ClosingLoop>& loops, const Closing& closing,
                         const Config& config, bool force);

/// Summary: loops / accepted / rejected by reason (and of the injected ones), solves, iterations, time.
Json closingJson(const std::vector<ClosingLoop>& loops, const Closing& closing);
std::string closingSummary(const std::vector<ClosingLoop>& loops, const Closing& closing);

}  // namespace sgtllc::cli
