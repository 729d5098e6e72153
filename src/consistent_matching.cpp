#include "sgtllc/consistent_matching.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace sgtllc {

std::vector<NodeMatch> hypothesisPairs(const DescribedFrame& query, const DescribedFrame& match, int per_node,
                                       const AssociationConfig& association, const DescriptorConfig& descriptor,
                                       int max_pairs) {
  std::vector<NodeMatch> out;
  std::vector<NodeMatch> ranked;
  for (int i = 0; i < query.numNodes(); ++i) {
    if (query.graph.isolated[i]) continue;
    ranked.clear();
    for (int j = 0; j < match.numNodes(); ++j) {
      if (match.graph.nodes[j].label != query.graph.nodes[i].label) continue;
      ranked.push_back({i, j, nodeSimilarity(query.local[i], match.local[j], association, descriptor)});
    }
    const size_t keep = std::min(ranked.size(), static_cast<size_t>(std::max(per_node, 0)));
    std::partial_sort(ranked.begin(), ranked.begin() + keep, ranked.end(), [](const NodeMatch& a, const NodeMatch& b) {
      return a.similarity != b.similarity ? a.similarity > b.similarity : a.match < b.match;
    });
    out.insert(out.end(), ranked.begin(), ranked.begin() + keep);
  }
  if (out.size() > static_cast<size_t>(max_pairs)) {
    // Too many for the set search: the most similar pairs stay, in their order.
    std::vector<size_t> order(out.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return out[a].similarity > out[b].similarity; });
    order.resize(static_cast<size_t>(max_pairs));
    std::sort(order.begin(), order.end());
    std::vector<NodeMatch> kept;
    for (size_t k : order) kept.push_back(out[k]);
    out.swap(kept);
  }
  return out;
}

namespace {

constexpr int kMaxPairs = 256;
constexpr int kWords = kMaxPairs / 64;
using Bits = std::array<uint64_t, kWords>;

int count(const Bits& b) {
  int n = 0;
  for (uint64_t w : b) n += __builtin_popcountll(w);
  return n;
}

/// Maximum clique by branch and bound (Carraghan–Pardalos order, bound = members + candidates left).
struct CliqueSearch {
  const std::vector<Bits>* adjacent = nullptr;
  std::vector<int> current, best;
  int steps = 0, max_steps = 0;

  void expand(Bits candidates) {
    if (++steps > max_steps) return;
    int left = count(candidates);
    if (left == 0) {
      if (current.size() > best.size()) best = current;
      return;
    }
    for (int w = 0; w < kWords; ++w) {
      while (candidates[w] != 0) {
        if (static_cast<int>(current.size()) + left <= static_cast<int>(best.size())) return;
        if (steps > max_steps) return;
        const int v = 64 * w + __builtin_ctzll(candidates[w]);
        candidates[w] &= candidates[w] - 1;
        --left;
        Bits next;
        for (int k = 0; k < kWords; ++k) next[k] = candidates[k] & (*adjacent)[v][k];
        current.push_back(v);
        expand(next);
        current.pop_back();
      }
    }
  }
};

}  // namespace

std::vector<int> largestConsistentSet(const std::vector<Eigen::Vector3d>& source,
                                      const std::vector<Eigen::Vector3d>& target, const std::vector<int>& source_ids,
                                      const std::vector<int>& target_ids, double tolerance, int max_steps) {
  const int n = std::min<int>(static_cast<int>(source.size()), kMaxPairs);
  std::vector<Bits> adjacent(static_cast<size_t>(n), Bits{});
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (source_ids[a] == source_ids[b] || target_ids[a] == target_ids[b]) continue;
      const double ds = (source[a] - source[b]).norm();
      const double dt = (target[a] - target[b]).norm();
      if (std::abs(ds - dt) >= tolerance) continue;
      adjacent[a][b / 64] |= uint64_t{1} << (b % 64);
      adjacent[b][a / 64] |= uint64_t{1} << (a % 64);
    }
  }
  CliqueSearch search;
  search.adjacent = &adjacent;
  search.max_steps = max_steps;
  Bits all{};
  for (int k = 0; k < n; ++k) all[k / 64] |= uint64_t{1} << (k % 64);
  search.expand(all);
  std::sort(search.best.begin(), search.best.end());
  return search.best;
}

}  // namespace sgtllc
