#include "loop_closing.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/g2o.h"
#include "sgtllc/pipeline/loop_closing_pipeline.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

/// Count, median, p99 and max of a list of times or distances, as the JSON and the summary line give them.
struct Stats {
  size_t count = 0;
  double median = 0.0, p99 = 0.0, max = 0.0;
};

Stats statsOf(const std::vector<double>& v) {
  return {v.size(), eval::percentile(v, 0.5), eval::percentile(v, 0.99),
          v.empty() ? 0.0 : *std::max_element(v.begin(), v.end())};
}

Json statsJson(const std::vector<double>& v) {
  const Stats s = statsOf(v);
  return {{"count", s.count}, {"median", s.median}, {"p99", s.p99}, {"max", s.max}};
}

}  // namespace

void addPoseFrameOption(CLI::App& cmd, io::PoseFrame& frame, const std::string& what) {
  cmd.add_option_function<std::string>(
         "--pose-frame", [&frame](const std::string& name) { frame = io::parsePoseFrame(name); },
         "frame of " + what + " if it is KITTI-format (12 columns): lidar (x forward, z up: KISS-ICP on most data), "
         "cam0 (KITTI's poses.txt: z forward, y down; needs --calib), or auto (default: --calib means cam0, else "
         "the motion decides and the choice is printed). TUM files are LiDAR poses")
      ->check(CLI::IsMember({"auto", "lidar", "cam0"}));
}

void checkPoseFrameOptions(const std::string& command, const std::string& calib, io::PoseFrame frame,
                           bool calib_has_other_use) {
  if (!calib.empty() && frame == io::PoseFrame::kLidar && !calib_has_other_use) {
    throw CLI::ValidationError(command, "--calib converts cam0 poses, --pose-frame lidar says they are LiDAR poses: "
                                        "give one of them");
  }
}

Odometry readOdometry(const std::string& path, const std::string& calib, io::PoseFrame frame, size_t frames) {
  Odometry o;
  o.path = path;
  io::FramedTrajectory read = io::readTrajectory(path, calib, frame);
  if (!read.choice.note.empty()) {
    std::cerr << (read.choice.warning ? "warning: " : "note: ") << read.choice.note << "\n";
  }
  o.trajectory = std::move(read.trajectory);
  if (frames > 0) io::checkPoseCount(path, o.trajectory, frames);
  for (const Eigen::Isometry3d& T : o.trajectory.poses) o.poses.push_back(pipeline::orthonormalised(T));
  return o;
}

std::string sequenceCalib(const std::string& calib, const std::string& sequence) {
  if (!calib.empty() || sequence.empty()) return calib;
  const fs::path candidate = fs::path(sequence) / "calib.txt";
  return fs::exists(candidate) ? candidate.string() : std::string();
}

void addClosingOutputOptions(CLI::App& cmd, ClosingOutputs& o) {
  cmd.add_option("--out-trajectory", o.trajectory,
                 "write the corrected trajectory (same format and frame as --odometry)");
  cmd.add_option("--out-graph", o.graph, "write the pose graph as g2o: corrected poses, odometry and accepted loops");
  cmd.add_option("--out-loops", o.loops,
                 "write every loop as a g2o EDGE_SE3:QUAT line; rejected ones follow a '# rejected' comment");
}

void checkClosingOutputs(const ClosingOutputs& o, bool force) {
  for (const std::string* path : {&o.trajectory, &o.graph, &o.loops}) {
    if (!path->empty()) checkWritable(*path, force);
  }
}

std::string onlineUpdateLine(const pipeline::BackendResult& r, double ms) {
  const pipeline::LoopReport& last = r.loops.back();
  return std::string("  back end: ") + pipeline::loopDecisionName(last.decision) + " (consistent with " +
         std::to_string(last.consistent_with) + " other loops, chi2 " + fixed(last.chi2, 2) + "); " +
         std::to_string(r.num_accepted) + " accepted, " + std::to_string(r.num_rejected) + " rejected so far; " +
         std::to_string(r.iterations) + " iterations, " + fixed(ms, 1) + " ms\n";
}

void writeClosingOutputs(const ClosingOutputs& o, const Odometry& odometry, const std::vector<ClosingLoop>& loops,
                         const Closing& closing, const Config& config, bool force) {
  if (!o.trajectory.empty()) {
    io::writeTrajectory(o.trajectory, io::withPoses(odometry.trajectory, closing.poses), io::overwriteIf(force));
  }
  if (!o.graph.empty()) {
    io::writeG2o(o.graph, pipeline::correctedGraph(odometry.poses, loops, closing, config.backend),
                 io::overwriteIf(force));
  }
  if (!o.loops.empty()) writeOutput(o.loops, pipeline::loopListG2o(loops, closing), force);
}

Json closingJson(const std::vector<ClosingLoop>& loops, const Closing& closing) {
  const pipeline::ClosingCounts c = pipeline::countLoops(loops, closing.result);
  Json list = Json::array();
  for (size_t k = 0; k < loops.size(); ++k) {
    const pipeline::LoopReport& r = closing.result.loops[k];
    list.push_back({{"query", loops[k].query},
                    {"match", loops[k].match},
                    {"decision", pipeline::loopDecisionName(r.decision)},
                    {"consistent_with", r.consistent_with},
                    {"chi2", r.chi2},
                    {"injected", loops[k].injected}});
  }
  Json out = {{"loops", c.loops},
          {"accepted", c.accepted},
          {"rejected", c.loops - c.accepted},
          {"rejected_inconsistent", c.inconsistent},
          {"rejected_large_residual", c.large_residual},
          {"nominal_information", c.nominal},
          {"injected_false_loops", c.injected},
          {"injected_rejected", c.injected_rejected},
          {"solves", closing.result.solves},
          {"iterations", closing.result.iterations},
          {"converged", closing.result.converged},
          {"final_cost", closing.result.final_cost},
          {"optimisation_ms", closing.ms},
          {"loop_list", list}};
  if (!closing.online_final_shift_m.empty()) {
    out["online_solve_ms"] = statsJson(closing.online_solve_cpu_ms);
    out["online_final_shift_m"] = statsJson(closing.online_final_shift_m);
  }
  return out;
}

std::string closingSummary(const std::vector<ClosingLoop>& loops, const Closing& closing) {
  const pipeline::ClosingCounts c = pipeline::countLoops(loops, closing.result);
  std::string s = "back end: " + std::to_string(c.loops) + " loops, " + std::to_string(c.accepted) + " accepted, " +
                  std::to_string(c.loops - c.accepted) + " rejected (" + std::to_string(c.inconsistent) +
                  " inconsistent, " + std::to_string(c.large_residual) + " large residual); " +
                  std::to_string(closing.result.solves) + " solves, " + std::to_string(closing.result.iterations) +
                  " iterations" + (closing.result.converged ? "" : " (not converged)") + ", " +
                  fixed(closing.ms, 1) + " ms\n";
  if (!closing.online_final_shift_m.empty()) {
    const Stats t = statsOf(closing.online_solve_cpu_ms), d = statsOf(closing.online_final_shift_m);
    s += "  online re-solves: " + std::to_string(t.count) + ", CPU median " + fixed(t.median, 1) + " ms, p99 " +
         fixed(t.p99, 1) + " ms, max " + fixed(t.max, 1) + " ms; the final full solve moved the frames by median " +
         fixed(d.median, 3) + " m, max " + fixed(d.max, 3) + " m\n";
  }
  if (c.nominal > 0) {
    s += "  " + std::to_string(c.nominal) + " loops without their own information use the nominal model\n";
  }
  if (c.injected > 0) {
    s += "  injected false loops: " + std::to_string(c.injected) + ", rejected " +
         std::to_string(c.injected_rejected) + ", accepted " + std::to_string(c.injected - c.injected_rejected) +
         "\n";
  }
  return s;
}

}  // namespace sgtllc::cli
