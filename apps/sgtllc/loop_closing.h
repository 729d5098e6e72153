// Closing the loop from the command line (docs/backend.md): the odometry input, loop edges for the back end, batch and
// online optimisation, and the corrected trajectory / g2o outputs shared by `run`, `optimize` and `eval`.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/Geometry>

#include "common.h"
#include "sgtllc/backend/pose_graph_optimizer.h"
#include "sgtllc/database.h"
#include "sgtllc/detector.h"
#include "sgtllc/io/loops_csv.h"
#include "sgtllc/io/trajectory.h"

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

/// Information of a loop whose own cannot be computed (a 16-column loops CSV, or inlier centres on one line): the
/// loopInformation of a nominal fit of 8 inliers spread 10 m around the sensor at σ = @p noise.sigma_min.
backend::Matrix6d nominalLoopInformation(const backend::LoopNoise& noise);

/// One loop for the back end, with its frame names and where it came from.
struct ClosingLoop {
  backend::Edge edge;         ///< from = match frame, to = query frame
  std::string query, match;   ///< frame names
  bool has_information = true;  ///< false: nominalLoopInformation
  bool injected = false;      ///< a false loop added by --add-false-loops
};

/// The loop edge of a detected loop: loopEdge() on the two frames' stored nodes, or the nominal information if the
/// inlier centres are collinear.
ClosingLoop detectedLoop(size_t query, const Candidate& c, const FrameDatabase& db, const pipeline::FrameSource& source,
                         const backend::LoopNoise& noise);

/// The loops CSV record of a loop (with its information, if any).
io::LoopRecord loopRecord(const ClosingLoop& loop, double score, double score_c);

/// Loops of a loops CSV read against @p frame_names (its information, or the nominal one).
std::vector<ClosingLoop> csvLoops(const std::vector<io::LoopRecord>& records, const backend::LoopNoise& noise);

/// Output files of the back end (empty = not written).
struct ClosingOutputs {
  std::string trajectory;  ///< --out-trajectory: corrected trajectory, same format and frame as the odometry
  std::string graph;       ///< --out-graph: g2o of the corrected poses, odometry and accepted loop edges
  std::string loops;       ///< --out-loops: every loop as a g2o edge line, rejected ones after a comment
};

void addClosingOutputOptions(CLI::App& cmd, ClosingOutputs& outputs);
/// checkWritable on every output, before any work.
void checkClosingOutputs(const ClosingOutputs& outputs, bool force);

/// What the back end made of the loops.
struct Closing {
  backend::BackendResult result;         ///< per-loop decisions (loops in the order given), solver statistics
  std::vector<Eigen::Isometry3d> poses;  ///< corrected trajectory, T_world_frame
  double ms = 0.0;                       ///< optimisation time (all solves)
  double final_ms = 0.0;                 ///< online: the full solve after the last frame (included in ms)
  /// Online: the process CPU time of each re-solve at a loop (ms), in the order of the loops; the final full solve
  /// is not among them.
  std::vector<double> online_solve_cpu_ms;
  /// Online: how far the final full solve moved each frame from the online estimate (m): the error of the online
  /// poses, had the drive ended before the last frame.
  std::vector<double> online_final_shift_m;
};

/// Odometry edges + all loops, optimised once (batch).
Closing closeLoopsBatch(const Odometry& odometry, const std::vector<ClosingLoop>& loops,
                        const backend::BackendConfig& config);

/// The online back end: frames as they arrive, a re-optimisation at every loop (PoseGraphOptimizer::closeLoop).
class OnlineClosing {
 public:
  OnlineClosing(const Odometry& odometry, const backend::BackendConfig& config);
  /// Adds frames up to @p frame (odometry steps), then the loop, and re-optimises.
  const backend::BackendResult& closeLoop(int frame, const ClosingLoop& loop);
  /// Adds the remaining frames; the result of the last re-optimisation with every frame (odometry after it).
  Closing finish();

 private:
  const Odometry& odometry_;
  backend::PoseGraphOptimizer optimizer_;
  double ms_ = 0.0;
  std::vector<double> solve_cpu_ms_;
  void addFramesUpTo(int frame);
};

/// One line on a loop's decision after an online update.
std::string onlineUpdateLine(const backend::BackendResult& r, double ms);

/// Writes the outputs that are set. The g2o graph holds the corrected poses, the odometry edges and the accepted
/// loops; the loop list every loop, each rejected or injected one after a `# ` comment saying so.
void writeClosingOutputs(const ClosingOutputs& outputs, const Odometry& odometry,
                         const std::vector<ClosingLoop>& loops, const Closing& closing,
                         const backend::BackendConfig& config, bool force);

/// Summary: loops / accepted / rejected by reason (and of the injected ones), solves, iterations, time.
Json closingJson(const std::vector<ClosingLoop>& loops, const Closing& closing);
std::string closingSummary(const std::vector<ClosingLoop>& loops, const Closing& closing);

}  // namespace sgtllc::cli
