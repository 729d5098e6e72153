/// @file node_repeatability.h
/// @brief Do the nodes of one place come back in another scan of it? The share of two scans' nodes that have a
///        same-class node of the other scan close by once the known motion is applied (docs/labeller.md §5).
///
/// Loop closing needs nodes that repeat across viewpoints and sensors more than it needs correct semantics: a node
/// that is there in one scan and not in the other, or there with another class, is an association RANSAC can only
/// reject. This measures that directly on real scans with a known relative pose.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/config.h"
#include "sgtllc/types.h"

namespace sgtllc::eval {

/// How nodes are compared.
struct RepeatabilityOptions {
  double radius = 0.5;  ///< m: a node repeats if a same-class node of the other scan is within this distance
  /// m: only nodes within this horizontal distance of both sensors count (the two scans' common view); 0 = all.
  double range = 40.0;
};

/// Per-class counts over the nodes of both scans of one or more pairs.
struct NodeRepeatability {
  std::array<int, kMaxClasses> nodes{};     ///< nodes in the common view
  std::array<int, kMaxClasses> repeated{};  ///< of those, nodes with a same-class node of the other scan near
  std::array<int, kMaxClasses> other_class{};  ///< nodes with no same-class node near but one of another class

  void add(const NodeRepeatability& other);
  int totalNodes() const;
  int totalRepeated() const;
  /// repeated / nodes over all classes (0 if there are none).
  double share() const;
  double share(int c) const;
};

/// Repeatability of the nodes of scans @p a and @p b, where @p T_b_a maps a's sensor frame into b's
/// (p_b = T_b_a · p_a). Both scans' nodes are counted, each against the other scan's: the measure is symmetric.
/// Brute force over node pairs (a scan has at most a few hundred nodes). Throws sgtllc::Error for a node label
/// outside 0..kMaxClasses−1.
NodeRepeatability nodeRepeatability(const std::vector<Node>& a, const std::vector<Node>& b,
                                    const Eigen::Isometry3d& T_b_a, const RepeatabilityOptions& options = {});

}  // namespace sgtllc::eval
