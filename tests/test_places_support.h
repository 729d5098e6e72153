// Many distinct "places" made from real node sets, for retrieval at scale (tests/test_retrieval_ivf.cpp and
// bench/bench_scale.cpp): a place is a crop of a real frame's nodes around a random centre, and a visit to it drops a
// tenth of the nodes and moves the rest by a few centimetres, so its key is near, not equal to, the place's others.
#pragma once

#include <random>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/graph.h"
#include "sgtllc/retrieval/retrieval_key.h"
#include "sgtllc/types.h"

namespace sgtllc::test {

/// A place: the nodes of @p frame within @p radius of a centre drawn within @p spread of the frame's origin.
inline std::vector<Node> cropPlace(const std::vector<Node>& frame, std::mt19937& rng, double spread = 25.0,
                                   double radius = 40.0) {
  std::uniform_real_distribution<double> u(-spread, spread);
  const Eigen::Vector3d centre(u(rng), u(rng), 0.0);
  std::vector<Node> out;
  for (const Node& n : frame) {
    if ((n.centre - centre).head<2>().norm() <= radius) out.push_back(n);
  }
  return out;
}

/// One visit to @p place: each node dropped with probability 0.1, the others jittered by N(0, 5 cm) per axis.
inline std::vector<Node> visit(const std::vector<Node>& place, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> jitter(0.0, 0.05);
  std::vector<Node> out;
  for (const Node& n : place) {
    if (u(rng) < 0.1) continue;
    const double dx = jitter(rng);
    const double dy = jitter(rng);
    const double dz = jitter(rng);
    out.push_back(Node{n.centre + Eigen::Vector3d(dx, dy, dz), n.label});
  }
  return out;
}

/// The retrieval key of @p nodes under @p config (graph, then retrieval.key).
inline std::vector<float> keyOf(const std::vector<Node>& nodes, const Config& config) {
  return retrieval::computeRetrievalKey(buildGraph(nodes, config.graph), config);
}

}  // namespace sgtllc::test
