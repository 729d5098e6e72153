#include "sgtllc/backend/loop_consistency.h"

#include <algorithm>
#include <numeric>

namespace sgtllc::backend {

CycleError cycleError(const Edge& i, const Edge& j, const OdometryChain& odometry) {
  return cycleError(i, j, odometry.relative(i.from, j.from), odometry.relative(j.to, i.to),
                    odometry.pathLength(i.from, j.from) + odometry.pathLength(j.to, i.to));
}

CycleError cycleError(const Edge& i, const Edge& j, const Eigen::Isometry3d& T_a_c, const Eigen::Isometry3d& T_d_b,
                      double path_length) {
  // Z_i = T_a_b and, around the cycle, T_a_c · Z_j · T_d_b ≈ T_a_b, so E = Z_i⁻¹ T_a_c Z_j T_d_b ≈ I.
  const Eigen::Isometry3d E = i.T_from_to.inverse() * T_a_c * j.T_from_to * T_d_b;
  CycleError e;
  e.translation = E.translation().norm();
  e.rotation = Eigen::AngleAxisd(E.rotation()).angle();
  e.path_length = path_length;
  return e;
}

bool consistent(const CycleError& e, const LoopConsistency& b) {
  return e.translation <= b.translation_m + b.translation_per_m * e.path_length &&
         e.rotation <= b.rotation_rad + b.rotation_per_m * e.path_length;
}

int ConsistencyGraph::add(const Edge& loop, const OdometryChain& odometry, const LoopConsistency& bounds) {
  return add(loop, [&](const Edge& earlier) { return consistent(cycleError(earlier, loop, odometry), bounds); });
}

int ConsistencyGraph::add(const Edge& loop, const std::function<bool(const Edge& earlier)>& consistent_with) {
  const int n = size();
  const size_t words = static_cast<size_t>(n) / 64 + 1;
  for (auto& row : rows_) row.resize(words, 0u);
  rows_.emplace_back(words, 0u);
  degree_.push_back(0);
  for (int i = 0; i < n; ++i) {
    if (!consistent_with(loops_[i])) continue;
    rows_[i][n / 64] |= uint64_t{1} << (n % 64);
    rows_[n][i / 64] |= uint64_t{1} << (i % 64);
    ++degree_[i];
    ++degree_[n];
  }
  loops_.push_back(loop);
  return n;
}

std::vector<int> ConsistencyGraph::maximumClique() const {
  const int n = size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return degree_[a] > degree_[b]; });
  std::vector<int> best;
  std::vector<uint64_t> in_best(rows_.empty() ? 0 : rows_[0].size(), 0u);
  for (int s = 0; s < n; ++s) {
    const int seed = order[s];
    if (degree_[seed] + 1 <= static_cast<int>(best.size())) break;  // no larger clique can grow from here
    // A member of the largest clique so far is not tried: growing from it mostly finds that clique again, and
    // trying each member cost O(n²) word operations per solve once most loops agree (docs/backend.md, "Online").
    if ((in_best[seed / 64] >> (seed % 64)) & 1u) continue;
    std::vector<uint64_t> candidates = rows_[seed];
    std::vector<int> clique{seed};
    int remaining = degree_[seed];
    // The highest-degree candidate first; candidates only shrink, so one pass over the order suffices.
    for (int k = 0; k < n && remaining > 0; ++k) {
      const int u = order[k];
      if (!((candidates[u / 64] >> (u % 64)) & 1u)) continue;
      clique.push_back(u);
      remaining = 0;
      for (size_t w = 0; w < candidates.size(); ++w) {
        candidates[w] &= rows_[u][w];
        remaining += __builtin_popcountll(candidates[w]);
      }
      if (static_cast<int>(clique.size()) + remaining <= static_cast<int>(best.size())) break;
    }
    if (clique.size() > best.size()) {
      best = clique;
      std::fill(in_best.begin(), in_best.end(), 0u);
      for (int u : best) in_best[u / 64] |= uint64_t{1} << (u % 64);
    }
  }
  std::sort(best.begin(), best.end());
  return best;
}

}  // namespace sgtllc::backend
