#include "sgtllc/eval/node_repeatability.h"

#include <string>

namespace sgtllc::eval {
namespace {

size_t classIndex(const Node& n) {
  if (n.label < 0 || n.label >= kMaxClasses) {
    throw Error("node label " + std::to_string(n.label) + " is not a stable class index 0.." +
                std::to_string(kMaxClasses - 1));
  }
  return static_cast<size_t>(n.label);
}

bool inView(const Eigen::Vector3d& p, const Eigen::Vector3d& sensor, double range) {
  return range <= 0.0 || (p - sensor).head<2>().squaredNorm() <= range * range;
}

/// Counts the nodes of @p from (already in the frame of @p to, whose sensor is at the origin; @p from's sensor at
/// @p from_sensor) against the nodes of @p to.
void countSide(const std::vector<Eigen::Vector3d>& from, const std::vector<Node>& from_nodes,
               const Eigen::Vector3d& from_sensor, const std::vector<Node>& to, const RepeatabilityOptions& o,
               NodeRepeatability& r) {
  const double r2 = o.radius * o.radius;
  for (size_t i = 0; i < from.size(); ++i) {
    if (!inView(from[i], Eigen::Vector3d::Zero(), o.range) || !inView(from[i], from_sensor, o.range)) continue;
    const size_t c = classIndex(from_nodes[i]);
    bool same = false, other = false;
    for (const Node& n : to) {
      if ((n.centre - from[i]).squaredNorm() > r2) continue;
      (classIndex(n) == c ? same : other) = true;
    }
    ++r.nodes[c];
    if (same) {
      ++r.repeated[c];
    } else if (other) {
      ++r.other_class[c];
    }
  }
}

std::vector<Eigen::Vector3d> moved(const std::vector<Node>& nodes, const Eigen::Isometry3d& T) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(nodes.size());
  for (const Node& n : nodes) out.push_back(T * n.centre);
  return out;
}

}  // namespace

void NodeRepeatability::add(const NodeRepeatability& other) {
  for (size_t c = 0; c < nodes.size(); ++c) {
    nodes[c] += other.nodes[c];
    repeated[c] += other.repeated[c];
    other_class[c] += other.other_class[c];
  }
}

int NodeRepeatability::totalNodes() const {
  int n = 0;
  for (int v : nodes) n += v;
  return n;
}

int NodeRepeatability::totalRepeated() const {
  int n = 0;
  for (int v : repeated) n += v;
  return n;
}

double NodeRepeatability::share() const {
  const int n = totalNodes();
  return n > 0 ? static_cast<double>(totalRepeated()) / n : 0.0;
}

double NodeRepeatability::share(int c) const {
  return nodes.at(c) > 0 ? static_cast<double>(repeated.at(c)) / nodes.at(c) : 0.0;
}

NodeRepeatability nodeRepeatability(const std::vector<Node>& a, const std::vector<Node>& b,
                                    const Eigen::Isometry3d& T_b_a, const RepeatabilityOptions& options) {
  for (const std::vector<Node>* nodes : {&a, &b}) {
    for (const Node& n : *nodes) classIndex(n);
  }
  NodeRepeatability r;
  // a's nodes in b's frame (b's sensor at the origin, a's at T_b_a's translation), then b's in a's frame.
  countSide(moved(a, T_b_a), a, T_b_a.translation(), b, options, r);
  const Eigen::Isometry3d T_a_b = T_b_a.inverse();
  countSide(moved(b, T_a_b), b, T_a_b.translation(), a, options, r);
  return r;
}

}  // namespace sgtllc::eval
