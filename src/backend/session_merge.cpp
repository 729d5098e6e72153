#include "sgtllc/backend/session_merge.h"

#include <algorithm>
#include <string>

#include "ceres_pose_graph.h"
#include "sgtllc/backend/information.h"
#include "sgtllc/backend/loop_consistency.h"
#include "sgtllc/types.h"

namespace sgtllc::backend {
namespace {

/// The solve over a set of kept loops: the map frames those loops name (fixed) first, then the session's frames.
class MergeSolve {
 public:
  MergeSolve(const SessionGraph& graph, const BackendConfig& config, const std::vector<int>& kept, bool placed)
      : graph_(graph), config_(config), placed_(placed), m_(static_cast<int>(graph.map_poses.size())),
        block_of_map_(graph.map_poses.size(), -1) {
    Eigen::Isometry3d T_world_odometry = Eigen::Isometry3d::Identity();
    if (placed_) {
      for (int k : kept) {
        const Edge& e = graph.loops[k];
        if (e.from >= m_) continue;
        if (first_inter_ < 0) first_inter_ = k;
        block_of_map_[e.from] = 0;
      }
      for (int f = 0; f < m_; ++f) {
        if (block_of_map_[f] < 0) continue;
        block_of_map_[f] = used_++;
        poses_.push_back(graph.map_poses[f]);
      }
      // Started where the first kept inter-session loop puts it: T_world_q = T_world_m · T_m_q.
      const Edge& e = graph.loops[first_inter_];
      T_world_odometry = graph.map_poses[e.from] * e.T_from_to * graph.odometry[e.to - m_].inverse();
    }
    start_ = T_world_odometry;
    for (const Eigen::Isometry3d& T : graph.odometry) poses_.push_back(T_world_odometry * T);
    odometry_ = odometryEdges(graph.odometry, config.odometry);
    for (Edge& e : odometry_) {
      e.from += used_;
      e.to += used_;
    }
  }

  /// Solves with the loops @p kept (indices into the graph's loops).
  internal::SolveSummary solve(const std::vector<int>& kept) {
    std::vector<Edge> active;
    for (int k : kept) active.push_back(remapped(graph_.loops[k]));
    return internal::solve(odometry_, active, poses_, config_, placed_ ? used_ : 1);
  }

  /// eᵀΩe of loop @p k at the current poses (0 for an inter-session loop of an unplaced session: its frames are in
  /// two unrelated worlds).
  double chi2(int k) const {
    const Edge& e = graph_.loops[k];
    if (!placed_ && e.from < m_) return 0.0;
    const Eigen::Matrix<double, 6, 1> r = internal::edgeError(e, poseOf(e.from), poseOf(e.to));
    return r.dot(e.information * r);
  }

  std::vector<Eigen::Isometry3d> sessionPoses() const {
    return std::vector<Eigen::Isometry3d>(poses_.begin() + used_, poses_.end());
  }
  const Eigen::Isometry3d& start() const { return start_; }

 private:
  int blockOf(int frame) const { return frame < m_ ? block_of_map_[frame] : used_ + frame - m_; }
  Edge remapped(Edge e) const {
    e.from = blockOf(e.from);
    e.to = blockOf(e.to);
    return e;
  }
  const Eigen::Isometry3d& poseOf(int frame) const {
    return frame < m_ ? graph_.map_poses[frame] : poses_[used_ + frame - m_];
  }

  const SessionGraph& graph_;
  const BackendConfig& config_;
  bool placed_;
  int m_;
  std::vector<int> block_of_map_;  // −1: a map frame no kept loop names, kept out of the problem
  int used_ = 0;
  int first_inter_ = -1;
  std::vector<Eigen::Isometry3d> poses_;
  std::vector<Edge> odometry_;
  Eigen::Isometry3d start_ = Eigen::Isometry3d::Identity();
};

/// The cycle map frame a →(map poses) c →(loop j) d →(session odometry) b →(loop i⁻¹) a of two inter-session
/// loops i = (a→b), j = (c→d). The map's leg counts its straight length: its poses are corrected, not dead-reckoned.
CycleError interCycle(const Edge& i, const Edge& j, const SessionGraph& g, const OdometryChain& chain, int m) {
  const Eigen::Isometry3d& A = g.map_poses[i.from];
  const Eigen::Isometry3d& C = g.map_poses[j.from];
  return cycleError(i, j, A.inverse() * C, chain.relative(j.to - m, i.to - m),
                    chain.pathLength(j.to - m, i.to - m) + (A.translation() - C.translation()).norm());
}

void checkGraph(const SessionGraph& g) {
  const int m = static_cast<int>(g.map_poses.size());
  const int total = m + static_cast<int>(g.odometry.size());
  if (g.odometry.empty()) throw Error("session merge: the session has no frames");
  for (size_t k = 0; k < g.loops.size(); ++k) {
    const Edge& e = g.loops[k];
    const std::string name = "session merge: loop " + std::to_string(k) + " (" + std::to_string(e.from) + " -> " +
                             std::to_string(e.to) + ")";
    if (e.from < 0 || e.to < 0 || e.from >= total || e.to >= total) {
      throw Error(name + " names a frame outside 0.." + std::to_string(total - 1));
    }
    if (e.from == e.to) throw Error(name + " joins a frame to itself");
    if (e.to < m) throw Error(name + " ends in a map frame: a loop goes from a map or session frame to a session frame");
  }
}

}  // namespace

SessionMerge mergeSession(const SessionGraph& graph, const BackendConfig& config) {
  config.validate();
  checkGraph(graph);
  const int m = static_cast<int>(graph.map_poses.size());
  OdometryChain chain;
  for (size_t i = 1; i < graph.odometry.size(); ++i) chain.append(graph.odometry[i - 1].inverse() * graph.odometry[i]);

  // Step 1: the two largest consistent sets. No cycle joins an inter-session loop to an intra-session one.
  ConsistencyGraph inter, intra;
  std::vector<int> inter_ids, intra_ids;  // consistency-graph index → loop index
  SessionMerge out;
  out.result.loops.resize(graph.loops.size());
  for (size_t k = 0; k < graph.loops.size(); ++k) {
    const Edge& e = graph.loops[k];
    out.result.loops[k].from = e.from;
    out.result.loops[k].to = e.to;
    out.result.loops[k].decision = LoopDecision::kInconsistent;
    if (e.from < m) {
      inter.add(e, [&](const Edge& earlier) { return consistent(interCycle(earlier, e, graph, chain, m), config.consistency); });
      inter_ids.push_back(static_cast<int>(k));
    } else {
      Edge local = e;
      local.from -= m;
      local.to -= m;
      intra.add(local, chain, config.consistency);
      intra_ids.push_back(static_cast<int>(k));
    }
  }
  for (size_t i = 0; i < inter_ids.size(); ++i) out.result.loops[inter_ids[i]].consistent_with = inter.degree(static_cast<int>(i));
  for (size_t i = 0; i < intra_ids.size(); ++i) out.result.loops[intra_ids[i]].consistent_with = intra.degree(static_cast<int>(i));
  out.inter_loops = static_cast<int>(inter_ids.size());

  std::vector<int> kept_inter, kept;
  for (int i : inter.maximumClique()) kept_inter.push_back(inter_ids[i]);
  for (int i : intra.maximumClique()) kept.push_back(intra_ids[i]);
  out.placed = static_cast<int>(kept_inter.size()) >= config.sessions.min_inter_loops;  // validated ≥ 1
  const std::vector<int> kept_intra = kept;
  if (out.placed) kept.insert(kept.end(), kept_inter.begin(), kept_inter.end());
  std::sort(kept.begin(), kept.end());

  // Steps 2 and 3: solve, then drop the worst loop over the bound and re-solve, as PoseGraphOptimizer does.
  auto run = [&](std::vector<int> loops, bool placed) {
    BackendResult& r = out.result;
    for (LoopReport& report : r.loops) report.decision = LoopDecision::kInconsistent;
    r.solves = r.iterations = 0;
    r.converged = true;
    MergeSolve solve(graph, config, loops, placed);
    for (int rounds = 0;; ++rounds) {
      const internal::SolveSummary s = solve.solve(loops);
      ++r.solves;
      r.iterations += s.iterations;
      r.final_cost = s.final_cost;
      r.converged = r.converged && s.converged;
      if (rounds >= config.max_rejection_rounds) break;
      int worst = -1;
      double worst_chi2 = config.max_loop_chi2;
      for (size_t k = 0; k < loops.size(); ++k) {
        const double c = solve.chi2(loops[k]);
        if (c > worst_chi2) {
          worst_chi2 = c;
          worst = static_cast<int>(k);
        }
      }
      if (worst < 0) break;
      r.loops[loops[worst]].decision = LoopDecision::kLargeResidual;
      loops.erase(loops.begin() + worst);
    }
    for (int k : loops) r.loops[k].decision = LoopDecision::kAccepted;
    r.num_accepted = r.num_rejected = 0;
    for (size_t k = 0; k < r.loops.size(); ++k) {
      r.loops[k].chi2 = solve.chi2(static_cast<int>(k));
      ++(r.loops[k].decision == LoopDecision::kAccepted ? r.num_accepted : r.num_rejected);
    }
    r.poses = solve.sessionPoses();
    r.num_poses_solved = static_cast<int>(r.poses.size());
    out.T_world_odometry = solve.start();
    out.inter_accepted = 0;
    for (int k : loops) out.inter_accepted += graph.loops[k].from < m;
  };
  run(kept, out.placed);
  if (out.placed && out.inter_accepted == 0) {
    // The residual check dropped every inter-session loop: nothing ties the session to the map any more.
    out.placed = false;
    run(kept_intra, false);
  }
  if (!out.placed) out.T_world_odometry = Eigen::Isometry3d::Identity();
  return out;
}

}  // namespace sgtllc::backend
