// Shared by the graph and descriptor suites (test_graph.cpp, test_descriptor.cpp): node builders, a hand-made node
// set and an O(N³) brute-force graph straight from algorithm §3.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/graph.h"
#include "sgtllc/types.h"

namespace sgtllc::test {

constexpr int slot(int m, int n, int num_classes = kNumPaperClasses) { return num_classes * m + n; }

inline Node node(double x, double y, double z, int label) { return Node{Eigen::Vector3d(x, y, z), label}; }

/// 0 building (0,0,0), 1 fence (3,0,0), 2 vegetation (0,4,0): a 3-4-5 right triangle; 3 pole at (30,0,0), exactly
/// σ_d from node 0 (not adjacent), 27 m from node 1; 4 trunk far away (isolated).
inline std::vector<Node> handNodes() {
  return {node(0, 0, 0, kBuilding), node(3, 0, 0, kFence), node(0, 4, 0, kVegetation), node(30, 0, 0, kPole),
          node(100, 0, 0, kTrunk)};
}

inline std::vector<Node> randomNodes(uint32_t seed, int n, bool lattice, int num_classes = kNumPaperClasses) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> xy(0.0, 80.0), z(0.0, 4.0);
  std::uniform_int_distribution<int> label(0, num_classes - 1), grid(0, 40);
  std::vector<Node> nodes(n);
  for (Node& nd : nodes) {
    // Lattice nodes tie often (equal path lengths, distances of exactly σ_d = 30 m).
    nd.centre = lattice ? Eigen::Vector3d(grid(rng), grid(rng), 0.0) : Eigen::Vector3d(xy(rng), xy(rng), z(rng));
    nd.label = label(rng);
  }
  return nodes;
}

// --- Brute-force references ----------------------------------------------------------------------------------------

struct RefGraph {
  std::vector<std::vector<bool>> adj;
  std::vector<bool> isolated;
  std::vector<std::vector<std::pair<int, int>>> paths;  ///< paths[i][C·m + n] = (j, k) or (−1, −1)
};

inline double dist(const std::vector<Node>& nodes, int a, int b) { return (nodes[a].centre - nodes[b].centre).norm(); }

/// O(N³) path search straight from algorithm §3: lowest j, then lowest k, wins a tie (strict >).
inline RefGraph bruteGraph(const std::vector<Node>& nodes, double sigma_d, bool allow_k_equals_i,
                           int num_classes = kNumPaperClasses) {
  const int n = static_cast<int>(nodes.size());
  RefGraph g;
  g.adj.assign(n, std::vector<bool>(n, false));
  g.isolated.assign(n, true);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      g.adj[a][b] = a != b && dist(nodes, a, b) < sigma_d;
      if (g.adj[a][b]) g.isolated[a] = false;
    }
  }
  g.paths.assign(n, std::vector<std::pair<int, int>>(static_cast<size_t>(num_classes * num_classes)));
  for (int i = 0; i < n; ++i) {
    for (int m = 0; m < num_classes; ++m) {
      for (int c = 0; c < num_classes; ++c) {
        std::pair<int, int> best(-1, -1);
        double best_len = -1.0;
        for (int j = 0; j < n; ++j) {
          if (!g.adj[i][j] || nodes[j].label != m) continue;
          for (int k = 0; k < n; ++k) {
            if (!g.adj[j][k] || nodes[k].label != c || (k == i && !allow_k_equals_i)) continue;
            const double len = dist(nodes, i, j) + dist(nodes, j, k);
            if (len > best_len) {
              best_len = len;
              best = {j, k};
            }
          }
        }
        g.paths[i][slot(m, c, num_classes)] = best;
      }
    }
  }
  return g;
}

/// (a_i, a_j, a_k) written out from the definition (algorithm §4).
inline Eigen::Vector3d terms(const Eigen::Vector3d& pi, const Eigen::Vector3d& pj, const Eigen::Vector3d& pk) {
  return {(pj - pi).dot(pk - pi), (pi - pj).dot(pk - pj), (pi - pk).dot(pj - pk)};
}

}  // namespace sgtllc::test
