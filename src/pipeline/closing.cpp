#include "sgtllc/pipeline/closing.h"

#include <chrono>
#include <ctime>

#include "elapsed.h"
#include "sgtllc/io/g2o.h"

namespace sgtllc::pipeline {
namespace {

// Process CPU time: the online re-solve runs while the detector's threads wait, so this is the solve's own cost
// (with backend.solver.num_threads > 1, its threads' time summed).
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

Closing closeLoopsBatch(const std::vector<Eigen::Isometry3d>& T_world_frame, const std::vector<ClosingLoop>& loops,
                        const backend::BackendConfig& config) {
  backend::PoseGraph graph = backend::odometryGraph(T_world_frame, config.odometry);
  for (const ClosingLoop& l : loops) graph.edges.push_back(l.edge);
  const auto start = std::chrono::steady_clock::now();
  Closing c;
  c.result = backend::optimize(graph, config);
  c.ms = msSince(start);
  c.poses = c.result.poses;
  return c;
}

OnlineClosing::OnlineClosing(const backend::BackendConfig& config, const Eigen::Isometry3d& T_world_first)
    : optimizer_(config, T_world_first), last_(T_world_first) {}

void OnlineClosing::addFrame(const Eigen::Isometry3d& T_world_frame) {
  optimizer_.addOdometry(last_.inverse() * T_world_frame);
  last_ = T_world_frame;
}

const backend::BackendResult& OnlineClosing::closeLoop(const ClosingLoop& loop) {
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = processCpuMs();
  const backend::BackendResult& r = optimizer_.closeLoop(loop.edge);
  solve_cpu_ms_.push_back(processCpuMs() - cpu_start);
  ms_ += msSince(start);
  return r;
}

Closing OnlineClosing::finish() {
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

ClosingCounts countLoops(const std::vector<ClosingLoop>& loops, const backend::BackendResult& r) {
  ClosingCounts c;
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

backend::PoseGraph correctedGraph(const std::vector<Eigen::Isometry3d>& T_world_odometry,
                                  const std::vector<ClosingLoop>& loops, const Closing& closing,
                                  const backend::BackendConfig& config) {
  backend::PoseGraph graph;
  graph.poses = closing.poses;
  graph.edges = backend::odometryEdges(T_world_odometry, config.odometry);
  for (size_t k = 0; k < loops.size() && k < closing.result.loops.size(); ++k) {
    if (closing.result.loops[k].decision == backend::LoopDecision::kAccepted) graph.edges.push_back(loops[k].edge);
  }
  return graph;
}

std::string loopListG2o(const std::vector<ClosingLoop>& loops, const Closing& closing) {
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
  return text;
}

}  // namespace sgtllc::pipeline
