#include "loop_closing.h"

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "sgtllc/backend/information.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/g2o.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Process CPU time: the online re-solve runs while the detector's threads wait, so this is the solve's own cost
// (with backend.solver.num_threads > 1, its threads' time summed).
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

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

std::vector<backend::Edge> acceptedLoopEdges(const std::vector<ClosingLoop>& loops, const backend::BackendResult& r) {
  std::vector<backend::Edge> edges;
  for (size_t k = 0; k < loops.size() && k < r.loops.size(); ++k) {
    if (r.loops[k].decision == backend::LoopDecision::kAccepted) edges.push_back(loops[k].edge);
  }
  return edges;
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
  o.poses = o.trajectory.poses;
  for (Eigen::Isometry3d& T : o.poses) {
    T.linear() = Eigen::Quaterniond(T.rotation()).normalized().toRotationMatrix();
  }
  return o;
}

std::string sequenceCalib(const std::string& calib, const std::string& sequence) {
  if (!calib.empty() || sequence.empty()) return calib;
  const fs::path candidate = fs::path(sequence) / "calib.txt";
  return fs::exists(candidate) ? candidate.string() : std::string();
}

backend::Matrix6d nominalLoopInformation(const backend::LoopNoise& noise) {
  // Eight centres on the corners of a 20 m cube around the sensor, fitted exactly: the rotation and translation
  // information of a typical urban loop (20–40 objects within ±25 m, about ten of them inliers).
  std::vector<Eigen::Vector3d> centres;
  for (int k = 0; k < 8; ++k) centres.emplace_back(k & 1 ? 10.0 : -10.0, k & 2 ? 10.0 : -10.0, k & 4 ? 10.0 : -10.0);
  return backend::loopInformation(centres, centres, Eigen::Isometry3d::Identity(), noise);
}

ClosingLoop detectedLoop(size_t query, const Candidate& c, const FrameDatabase& db, const pipeline::FrameSource& source,
                         const backend::LoopNoise& noise) {
  ClosingLoop loop;
  loop.query = source.name(query);
  loop.match = source.name(static_cast<size_t>(c.frame));
  const int q = static_cast<int>(query);
  if (c.refinement && c.refinement->used()) {
    // The ICP pose (registration.online) and its point-to-plane information (docs/registration.md).
    loop.edge.from = c.frame;
    loop.edge.to = q;
    loop.edge.T_from_to = Eigen::Isometry3d(c.match.T_match_query);
    loop.edge.information = c.refinement->information;
    loop.edge.kind = backend::EdgeKind::kLoop;
    return loop;
  }
  try {
    loop.edge = backend::loopEdge(c.frame, q, c.match, db.nodes(q), db.nodes(c.frame), noise);
  } catch (const Error&) {
    // Collinear inlier centres leave a rotation unobservable: fall back to the nominal information.
    loop.edge.from = c.frame;
    loop.edge.to = q;
    loop.edge.T_from_to = Eigen::Isometry3d(c.match.T_match_query);
    loop.edge.information = nominalLoopInformation(noise);
    loop.edge.kind = backend::EdgeKind::kLoop;
    loop.has_information = false;
  }
  return loop;
}

io::LoopRecord loopRecord(const ClosingLoop& loop, double score, double score_c) {
  io::LoopRecord r;
  r.query = loop.query;
  r.match = loop.match;
  r.query_index = loop.edge.to;
  r.match_index = loop.edge.from;
  r.score = score;
  r.score_c = score_c;
  r.T_match_query = loop.edge.T_from_to.matrix();
  if (loop.has_information) r.information = loop.edge.information;
  return r;
}

std::vector<ClosingLoop> csvLoops(const std::vector<io::LoopRecord>& records, const backend::LoopNoise& noise) {
  const std::vector<backend::Edge> edges = io::loopEdges(records, nominalLoopInformation(noise));
  std::vector<ClosingLoop> loops;
  for (size_t k = 0; k < records.size(); ++k) {
    loops.push_back({edges[k], records[k].query, records[k].match, records[k].information.has_value(), false});
  }
  return loops;
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

Closing closeLoopsBatch(const Odometry& odometry, const std::vector<ClosingLoop>& loops,
                        const backend::BackendConfig& config) {
  backend::PoseGraph graph = backend::odometryGraph(odometry.poses, config.odometry);
  for (const ClosingLoop& l : loops) graph.edges.push_back(l.edge);
  const auto start = std::chrono::steady_clock::now();
  Closing c;
  c.result = backend::optimize(graph, config);
  c.ms = msSince(start);
  c.poses = c.result.poses;
  return c;
}

OnlineClosing::OnlineClosing(const Odometry& odometry, const backend::BackendConfig& config)
    : odometry_(odometry), optimizer_(config, odometry.poses.at(0)) {}

void OnlineClosing::addFramesUpTo(int frame) {
  for (int i = optimizer_.numFrames(); i <= frame; ++i) {
    optimizer_.addOdometry(odometry_.poses[i - 1].inverse() * odometry_.poses[i]);
  }
}

const backend::BackendResult& OnlineClosing::closeLoop(int frame, const ClosingLoop& loop) {
  addFramesUpTo(frame);
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = processCpuMs();
  const backend::BackendResult& r = optimizer_.closeLoop(loop.edge);
  solve_cpu_ms_.push_back(processCpuMs() - cpu_start);
  ms_ += msSince(start);
  return r;
}

Closing OnlineClosing::finish() {
  addFramesUpTo(static_cast<int>(odometry_.poses.size()) - 1);
  Closing c;
  // closeLoop() solved the reduced graph (docs/backend.md, "Online"); one full solve at the end makes the online
  // result the batch result, as a robot would do once the drive ends. No loop: the odometry is the optimum.
  const std::vector<Eigen::Isometry3d> online_poses = optimizer_.poses();
  const auto start = std::chrono::steady_clock::now();
  c.result = optimizer_.numLoops() > 0 ? optimizer_.optimize() : optimizer_.result();
  c.final_ms = msSince(start);
  c.poses = optimizer_.poses();
  c.online_solve_cpu_ms = solve_cpu_ms_;
  for (size_t i = 0; i < c.poses.size(); ++i) {
    c.online_final_shift_m.push_back((c.poses[i].translation() - online_poses[i].translation()).norm());
  }
  c.result.poses = c.poses;
  c.ms = ms_ + c.final_ms;
  return c;
}

std::string onlineUpdateLine(const backend::BackendResult& r, double ms) {
  const backend::LoopReport& last = r.loops.back();
  return std::string("  back end: ") + backend::loopDecisionName(last.decision) + " (consistent with " +
         std::to_string(last.consistent_with) + " other loops, chi2 " + fixed(last.chi2, 2) + "); " +
         std::to_string(r.num_accepted) + " accepted, " + std::to_string(r.num_rejected) + " rejected so far; " +
         std::to_string(r.iterations) + " iterations, " + fixed(ms, 1) + " ms\n";
}

void writeClosingOutputs(const ClosingOutputs& o, const Odometry& odometry, const std::vector<ClosingLoop>& loops,
                         const Closing& closing, const backend::BackendConfig& config, bool force) {
  if (!o.trajectory.empty()) {
    io::writeTrajectory(o.trajectory, io::withPoses(odometry.trajectory, closing.poses), io::overwriteIf(force));
  }
  if (!o.graph.empty()) {
    backend::PoseGraph graph;
    graph.poses = closing.poses;
    graph.edges = backend::odometryEdges(odometry.poses, config.odometry);
    for (const backend::Edge& e : acceptedLoopEdges(loops, closing.result)) graph.edges.push_back(e);
    io::writeG2o(o.graph, graph, io::overwriteIf(force));
  }
  if (!o.loops.empty()) {
    std::string text = "# sgtllc loops: EDGE_SE3:QUAT match query T_match_query information (g2o convention)\n";
    for (size_t k = 0; k < loops.size(); ++k) {
      const backend::LoopReport& r = closing.result.loops.at(k);
      if (r.decision != backend::LoopDecision::kAccepted || loops[k].injected) {
        text += std::string("# ") + (loops[k].injected ? "injected false loop, " : "") +
                (r.decision == backend::LoopDecision::kAccepted ? "accepted" : "rejected") + " (" +
                backend::loopDecisionName(r.decision) + "): " + loops[k].query + " -> " + loops[k].match + "\n";
      }
      text += io::g2oEdgesText({loops[k].edge});
    }
    writeOutput(o.loops, text, force);
  }
}

namespace {

struct Counts {
  int loops = 0, accepted = 0, inconsistent = 0, large_residual = 0, nominal = 0;
  int injected = 0, injected_rejected = 0;
};

Counts countLoops(const std::vector<ClosingLoop>& loops, const backend::BackendResult& r) {
  Counts c;
  for (size_t k = 0; k < loops.size(); ++k) {
    const backend::LoopDecision d = r.loops.at(k).decision;
    ++c.loops;
    c.accepted += d == backend::LoopDecision::kAccepted;
    c.inconsistent += d == backend::LoopDecision::kInconsistent;
    c.large_residual += d == backend::LoopDecision::kLargeResidual;
    c.nominal += !loops[k].has_information;
    c.injected += loops[k].injected;
    c.injected_rejected += loops[k].injected && d != backend::LoopDecision::kAccepted;
  }
  return c;
}

}  // namespace

Json closingJson(const std::vector<ClosingLoop>& loops, const Closing& closing) {
  const Counts c = countLoops(loops, closing.result);
  Json list = Json::array();
  for (size_t k = 0; k < loops.size(); ++k) {
    const backend::LoopReport& r = closing.result.loops[k];
    list.push_back({{"query", loops[k].query},
                    {"match", loops[k].match},
                    {"decision", backend::loopDecisionName(r.decision)},
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
  const Counts c = countLoops(loops, closing.result);
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
