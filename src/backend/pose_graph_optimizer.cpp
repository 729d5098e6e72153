#include "sgtllc/backend/pose_graph_optimizer.h"

#include <algorithm>
#include <map>
#include <string>

#include "ceres_pose_graph.h"
#include "reduced_graph.h"
#include "sgtllc/backend/information.h"
#include "sgtllc/types.h"

namespace sgtllc::backend {
namespace {

std::string edgeName(size_t index, const Edge& e) {
  return "pose graph: edge " + std::to_string(index) + " (" + std::to_string(e.from) + " -> " + std::to_string(e.to) +
         ")";
}

double chi2(const Edge& e, const std::vector<Eigen::Isometry3d>& poses) {
  const Eigen::Matrix<double, 6, 1> r = internal::edgeError(e, poses[e.from], poses[e.to]);
  return r.dot(e.information * r);
}

}  // namespace

const char* loopDecisionName(LoopDecision d) {
  switch (d) {
    case LoopDecision::kAccepted: return "accepted";
    case LoopDecision::kInconsistent: return "inconsistent";
    case LoopDecision::kLargeResidual: return "large_residual";
  }
  return "unknown";
}

PoseGraphOptimizer::PoseGraphOptimizer(const BackendConfig& config, const Eigen::Isometry3d& T_world_first)
    : config_(config), poses_{T_world_first} {
  config_.validate();
}

PoseGraphOptimizer::PoseGraphOptimizer(const PoseGraph& graph, const BackendConfig& config)
    : PoseGraphOptimizer(config, graph.poses.empty() ? Eigen::Isometry3d::Identity() : graph.poses[0]) {
  if (graph.poses.empty()) throw Error("pose graph: no poses");
  const int n = static_cast<int>(graph.poses.size());
  std::vector<int> step_edge(n, -1);
  for (size_t k = 0; k < graph.edges.size(); ++k) {
    const Edge& e = graph.edges[k];
    if (e.from < 0 || e.from >= n || e.to < 0 || e.to >= n) {
      throw Error(edgeName(k, e) + " names a frame outside 0.." + std::to_string(n - 1));
    }
    if (e.kind != EdgeKind::kOdometry) continue;
    if (e.to != e.from + 1) throw Error(edgeName(k, e) + " is odometry but does not join consecutive frames");
    if (step_edge[e.to] >= 0) throw Error(edgeName(k, e) + " repeats the odometry into frame " + std::to_string(e.to));
    step_edge[e.to] = static_cast<int>(k);
  }
  for (int i = 1; i < n; ++i) {
    if (step_edge[i] < 0) throw Error("pose graph: no odometry edge " + std::to_string(i - 1) + " -> " + std::to_string(i));
    const Edge& e = graph.edges[step_edge[i]];
    addOdometry(e.T_from_to, e.information);
  }
  poses_ = graph.poses;
  for (const Edge& e : graph.edges) {
    if (e.kind != EdgeKind::kOdometry) addLoop(e);
  }
}

int PoseGraphOptimizer::addOdometry(const Eigen::Isometry3d& T_prev_curr) {
  return addOdometry(T_prev_curr, odometryInformation(T_prev_curr, config_.odometry));
}

int PoseGraphOptimizer::addOdometry(const Eigen::Isometry3d& T_prev_curr, const Matrix6d& information) {
  const int frame = numFrames();
  Edge e;
  e.from = frame - 1;
  e.to = frame;
  e.T_from_to = T_prev_curr;
  e.information = information;
  e.kind = EdgeKind::kOdometry;
  odometry_.push_back(e);
  odometry_covariance_.push_back(information.inverse());
  chain_.append(T_prev_curr);
  poses_.push_back(poses_.back() * T_prev_curr);
  return frame;
}

void PoseGraphOptimizer::addLoop(const Edge& loop) {
  if (loop.from < 0 || loop.from >= numFrames() || loop.to < 0 || loop.to >= numFrames()) {
    throw Error(edgeName(loops_.size(), loop) + ": loop names a frame outside 0.." + std::to_string(numFrames() - 1));
  }
  if (loop.from == loop.to) throw Error(edgeName(loops_.size(), loop) + ": loop joins a frame to itself");
  loops_.push_back(loop);
  consistency_.add(loop, chain_, config_.consistency);
}

const BackendResult& PoseGraphOptimizer::closeLoop(const Edge& loop) {
  addLoop(loop);
  return config_.online.reduced_graph ? optimizeReduced() : optimize();
}

const BackendResult& PoseGraphOptimizer::optimize() { return run(false); }

const BackendResult& PoseGraphOptimizer::optimizeReduced() { return run(true); }

const BackendResult& PoseGraphOptimizer::run(bool reduced) {
  BackendResult result;
  result.reduced = reduced;
  result.loops.resize(loops_.size());
  for (size_t i = 0; i < loops_.size(); ++i) {
    result.loops[i].from = loops_[i].from;
    result.loops[i].to = loops_[i].to;
    result.loops[i].decision = LoopDecision::kInconsistent;
    result.loops[i].consistent_with = consistency_.degree(static_cast<int>(i));
  }
  std::vector<int> kept = consistency_.maximumClique();

  // Online, the loop endpoints within one stretch of path (backend.online.anchor_spacing_m) share one anchor, the
  // middle one, and the others are carried to it (or to the anchor on their other side, when nearer; a loop within
  // one stretch goes to two different anchors): a loop seldom carries far, and the anchors stay under the path
  // length over the spacing however many loops arrive. The warm start of optimize() keeps every endpoint an anchor.
  const bool warm_start = !reduced && config_.solver.reduced_warm_start && !kept.empty();
  internal::ReducedGraph graph;
  std::vector<Eigen::Isometry3d> anchor_poses;
  std::vector<Edge> carried;  // loops_ on the reduced graph
  if (reduced || warm_start) {
    const double spacing = reduced ? config_.online.anchor_spacing_m : 0.0;
    std::vector<int> anchors;
    std::map<int, std::vector<int>> stretches;  // first frame of a stretch → the loop endpoints in it
    for (const Edge& e : loops_) {
      stretches[chain_.stretchStart(e.from, spacing)].push_back(e.from);
      stretches[chain_.stretchStart(e.to, spacing)].push_back(e.to);
    }
    for (auto& [start, frames] : stretches) {
      std::sort(frames.begin(), frames.end());
      frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
      anchors.push_back(frames[frames.size() / 2]);
    }
    graph = internal::reduceOdometry(odometry_, odometry_covariance_, std::move(anchors));
    for (int a : graph.anchors) anchor_poses.push_back(poses_[a]);
    carried.reserve(loops_.size());
    for (const Edge& e : loops_) carried.push_back(internal::carryLoop(graph, e));
  }
  auto solveKept = [&](bool on_reduced) {
    std::vector<Edge> active;
    for (int i : kept) active.push_back(on_reduced ? carried[i] : loops_[i]);
    internal::SolveSummary s;
    if (on_reduced) {
      s = internal::solve(graph.chains, active, anchor_poses, config_);
      for (size_t k = 0; k < graph.anchors.size(); ++k) poses_[graph.anchors[k]] = anchor_poses[k];
      result.num_poses_solved = static_cast<int>(anchor_poses.size());
    } else {
      s = internal::solve(odometry_, active, poses_, config_);
      result.num_poses_solved = numFrames();
    }
    ++result.solves;
    result.iterations += s.iterations;
    result.final_cost = s.final_cost;
    result.converged = result.converged && s.converged;
  };
  if (warm_start) {
    solveKept(true);
    internal::redistribute(graph, poses_);
  }
  for (int rounds = 0;; ++rounds) {
    solveKept(reduced);
    if (rounds >= config_.max_rejection_rounds) break;
    // Drop the worst loop over the bound (ties: the first), then re-optimise without it.
    int worst = -1;
    double worst_chi2 = config_.max_loop_chi2;
    for (size_t k = 0; k < kept.size(); ++k) {
      const double c = reduced ? chi2(carried[kept[k]], anchor_poses) : chi2(loops_[kept[k]], poses_);
      if (c > worst_chi2) {
        worst_chi2 = c;
        worst = static_cast<int>(k);
      }
    }
    if (worst < 0) break;
    result.loops[kept[worst]].decision = LoopDecision::kLargeResidual;
    kept.erase(kept.begin() + worst);
  }
  if (reduced) internal::redistribute(graph, poses_);
  for (int i : kept) result.loops[i].decision = LoopDecision::kAccepted;
  for (size_t i = 0; i < loops_.size(); ++i) {
    // On the reduced graph, the χ² the residual check judged: of the loop as carried to its anchors.
    result.loops[i].chi2 = reduced ? chi2(carried[i], anchor_poses) : chi2(loops_[i], poses_);
    if (result.loops[i].decision == LoopDecision::kAccepted) {
      ++result.num_accepted;
    } else {
      ++result.num_rejected;
    }
  }
  result.poses = poses_;
  result_ = std::move(result);
  return result_;
}

BackendResult optimize(const PoseGraph& graph, const BackendConfig& config) {
  return PoseGraphOptimizer(graph, config).optimize();
}

}  // namespace sgtllc::backend
