/// @file road_network.h
/// @brief A street graph: a jittered grid of intersections joined by straight and curved roads, some removed,
///        some diagonal, avenues along whole grid lines.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/sim/scene.h"

namespace sgtllc::sim {

struct RoadNode {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  std::vector<int> edges;  ///< incident edges
};

/// One road between two intersections, with its centre line sampled about every 2 m from node a to node b.
struct RoadEdge {
  int a = 0, b = 0;
  bool avenue = false;
  RoadProfile profile;
  std::vector<Eigen::Vector2d> line;
  std::vector<double> s;  ///< arc length at each line point (s.front() = 0)

  double length() const { return s.back(); }
  /// Point and unit tangent (direction a → b) at arc length @p at, clamped to the edge.
  Eigen::Vector2d pointAt(double at) const;
  Eigen::Vector2d tangentAt(double at) const;
  /// Heading (rad) at arc length @p at, along the edge (@p forward) or against it.
  double headingAt(double at, bool forward = true) const;
  /// The point @p offset metres to the right of the centre line (facing a → b); negative = left.
  Eigen::Vector2d sidePoint(double at, double offset) const;
};

class RoadNetwork {
 public:
  /// A grid of @p blocks_x × @p blocks_y blocks shaped by @p preset.
  static RoadNetwork generate(const ScenePreset& preset, int blocks_x, int blocks_y, uint64_t seed);

  const std::vector<RoadNode>& nodes() const { return nodes_; }
  const std::vector<RoadEdge>& edges() const { return edges_; }
  /// The node at the other end of @p edge from @p node.
  int otherEnd(int edge, int node) const { return edges_[edge].a == node ? edges_[edge].b : edges_[edge].a; }
  /// Distance from a node to where buildings may start along its roads: the widest incident road edge + 1 m.
  double clearance(int node) const;
  /// Total centre-line length (m).
  double totalLength() const;
  Eigen::Vector2d lo() const;
  Eigen::Vector2d hi() const;

 private:
  void addEdge(int a, int b, bool avenue, const RoadProfile& profile, double bulge);
  bool connectedWithout(int edge) const;

  std::vector<RoadNode> nodes_;
  std::vector<RoadEdge> edges_;
};

}  // namespace sgtllc::sim
