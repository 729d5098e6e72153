#include "sgtllc/consistent_matching.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace sgtllc {

std::vector<NodeMatch> hypothesisPairs(const DescribedFrame& query, const DescribedFrame& match, int per_node,
                                       const AssociationConfig& association, const DescriptorConfig& descriptor,
                                       int max_pairs) {
  return hypothesisPairs(nodeSimilarities(query, match, association, descriptor), per_node, max_pairs);
}

std::vector<NodeMatch> hypothesisPairs(const NodeSimilarities& similarities, int per_node, int max_pairs) {
  std::vector<NodeMatch> out;
  std::vector<NodeMatch> ranked;
  for (size_t k = 0; k + 1 < similarities.start.size(); ++k) {
    ranked.assign(similarities.pairs.begin() + similarities.start[k],
                  similarities.pairs.begin() + similarities.start[k + 1]);
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

/// The distances between the distinct points of the first @p n entries of @p points, each named by its entry of
/// @p ids (one point per id): computed once per pair of points instead of once per pair of entries, where each
/// point is an entry of up to consistency_pairs hypotheses. The same values, bit for bit, as the entries' own
/// differences: (p − q).norm() and (q − p).norm() square the same numbers.
class PointDistances {
 public:
  PointDistances(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& ids, int n) : slot_(n) {
    std::vector<int> distinct(ids.begin(), ids.begin() + n);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    m_ = static_cast<int>(distinct.size());
    std::vector<int> first(static_cast<size_t>(m_), -1);  // an entry holding each point
    for (int a = 0; a < n; ++a) {
      slot_[a] = static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), ids[a]) - distinct.begin());
      if (first[slot_[a]] < 0) first[slot_[a]] = a;
    }
    d_.assign(static_cast<size_t>(m_) * static_cast<size_t>(m_), 0.0);
    for (int s = 0; s < m_; ++s) {
      for (int t = s + 1; t < m_; ++t) {
        const double d = (points[first[s]] - points[first[t]]).norm();
        d_[static_cast<size_t>(s) * m_ + t] = d;
        d_[static_cast<size_t>(t) * m_ + s] = d;
      }
    }
  }
  double operator()(int a, int b) const { return d_[static_cast<size_t>(slot_[a]) * m_ + slot_[b]]; }

 private:
  std::vector<int> slot_;
  int m_ = 0;
  std::vector<double> d_;
};

}  // namespace

std::vector<int> largestConsistentSet(const std::vector<Eigen::Vector3d>& source,
                                      const std::vector<Eigen::Vector3d>& target, const std::vector<int>& source_ids,
                                      const std::vector<int>& target_ids, double tolerance, int max_steps) {
  const int n = std::min<int>(static_cast<int>(source.size()), kMaxPairs);
  std::vector<Bits> adjacent(static_cast<size_t>(n), Bits{});
  const PointDistances source_distance(source, source_ids, n), target_distance(target, target_ids, n);
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (source_ids[a] == source_ids[b] || target_ids[a] == target_ids[b]) continue;
      if (std::abs(source_distance(a, b) - target_distance(a, b)) >= tolerance) continue;
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
