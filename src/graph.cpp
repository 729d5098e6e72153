#include "sgtllc/graph.h"

#include <algorithm>
#include <array>
#include <string>

namespace sgtllc {
namespace {

/// The farthest and second-farthest neighbour of node j of one class (ties to the lower index).
struct FarthestTwo {
  int first = -1;
  int second = -1;
};

/// T_i[m][n] for every node i from the two farthest neighbours of each node and class (algorithm §3). kClasses is the
/// class count when fixed at compile time, 0 to use @p num_classes.
template <int kClasses>
void longestPaths(SemanticGraph& g, const SlotRows<FarthestTwo>& far, bool allow_k_equals_i, int num_classes) {
  const int classes = kClasses > 0 ? kClasses : num_classes;
  const int n = g.size();
  std::array<double, kMaxSlots> best_length;
  for (int i = 0; i < n; ++i) {
    std::fill(best_length.begin(), best_length.begin() + classes * classes, -1.0);
    const SlotRow<TwoStepPath> paths = g.paths[i];
    for (int j = 0; j < n; ++j) {
      if (!g.adjacent(i, j)) continue;
      const int m = g.nodes[j].label;
      const SlotRow<const FarthestTwo> far_j = far[j];
      for (int c = 0; c < classes; ++c) {
        int k = far_j[c].first;
        if (k == i && !allow_k_equals_i) k = far_j[c].second;
        if (k < 0) continue;
        const double length = g.distance(i, j) + g.distance(j, k);
        const int alpha = classes * m + c;
        if (length > best_length[alpha]) {  // strict: the first path found (lowest j) keeps a tie
          best_length[alpha] = length;
          paths[alpha] = TwoStepPath{j, k};
        }
      }
    }
  }
}

}  // namespace

std::vector<std::pair<int, int>> SemanticGraph::edges() const {
  std::vector<std::pair<int, int>> out;
  for (int p = 0; p < size(); ++p) {
    for (int q = p + 1; q < size(); ++q) {
      if (adjacent(p, q)) out.emplace_back(p, q);
    }
  }
  return out;
}

void checkNodeCount(size_t count, const GraphConfig& config, const std::string& what) {
  if (count <= static_cast<size_t>(config.max_nodes)) return;
  throw Error(what + " has " + std::to_string(count) + " nodes, more than graph.max_nodes = " +
              std::to_string(config.max_nodes) + " (the graph is dense: memory and time grow with the square of " +
              "the node count; real scans have 20-70 nodes). Merge or drop nodes, or raise graph.max_nodes (at most " +
              std::to_string(kMaxGraphNodes) + ")");
}

SemanticGraph buildGraph(std::vector<Node> nodes, const GraphConfig& config, int num_classes) {
  checkNodeCount(nodes.size(), config);
  if (num_classes < 1 || num_classes > kMaxClasses) {
    throw Error("buildGraph: " + std::to_string(num_classes) + " classes, expected 1.." + std::to_string(kMaxClasses));
  }
  const int num_slots = num_classes * num_classes;
  // Nodes may come straight from a user (LoopDetector::process(nodes), node files): check what indexing relies on.
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].label < 0 || nodes[i].label >= num_classes) {
      throw Error("node " + std::to_string(i) + " has label " + std::to_string(nodes[i].label) +
                  ", not a stable class index 0.." + std::to_string(num_classes - 1));
    }
    if (!nodes[i].centre.allFinite()) throw Error("node " + std::to_string(i) + " has a NaN or Inf centre");
  }
  SemanticGraph g;
  g.num_classes = num_classes;
  g.nodes = std::move(nodes);
  const int n = g.size();
  g.distance.resize(n, n);
  g.adjacency.assign(static_cast<size_t>(n) * n, 0);
  g.isolated.assign(n, 1);
  for (int p = 0; p < n; ++p) {
    g.distance(p, p) = 0.0;
    for (int q = p + 1; q < n; ++q) {
      const double d = (g.nodes[p].centre - g.nodes[q].centre).norm();
      g.distance(p, q) = g.distance(q, p) = d;
      if (d < config.sigma_d) {  // strict, as the authors' getNeighbor (algorithm §3)
        g.adjacency[static_cast<size_t>(p) * n + q] = g.adjacency[static_cast<size_t>(q) * n + p] = 1;
        g.isolated[p] = g.isolated[q] = 0;
      }
    }
  }

  // For every j and class c: its two farthest neighbours of class c. The best k of a path i→j→k is the farthest
  // one unless that is i itself (excluded when k ≠ i is required), then the second.
  SlotRows<FarthestTwo> far;  // far[j][c], one row of C classes per node
  far.assign(n, num_classes, FarthestTwo{});
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < n; ++k) {
      if (!g.adjacent(j, k)) continue;
      FarthestTwo& f = far[j][g.nodes[k].label];
      const double d = g.distance(j, k);
      if (f.first < 0 || d > g.distance(j, f.first)) {
        f.second = f.first;
        f.first = k;
      } else if (f.second < 0 || d > g.distance(j, f.second)) {
        f.second = k;
      }
    }
  }

  g.paths.assign(n, num_slots, TwoStepPath{});
  // The paper's seven classes get a loop the compiler unrolls (the default must not pay for the runtime count).
  if (num_classes == kNumPaperClasses) {
    longestPaths<kNumPaperClasses>(g, far, config.allow_k_equals_i, num_classes);
  } else {
    longestPaths<0>(g, far, config.allow_k_equals_i, num_classes);
  }
  return g;
}

}  // namespace sgtllc
