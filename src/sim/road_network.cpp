#include "sgtllc/sim/road_network.h"

#include <algorithm>
#include <cmath>

#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {
namespace {

constexpr double kLineStep = 2.0;  // m between centre-line samples

/// Index of the last line point at or before arc length @p at, and the fraction to the next one.
size_t locate(const RoadEdge& e, double at, double& frac) {
  at = std::clamp(at, 0.0, e.length());
  const size_t i = std::min<size_t>(std::upper_bound(e.s.begin(), e.s.end(), at) - e.s.begin(), e.s.size() - 1);
  const size_t k = i == 0 ? 0 : i - 1;
  const double len = e.s[k + 1] - e.s[k];
  frac = len > 0.0 ? (at - e.s[k]) / len : 0.0;
  return k;
}

}  // namespace

Eigen::Vector2d RoadEdge::pointAt(double at) const {
  double f;
  const size_t k = locate(*this, at, f);
  return (1.0 - f) * line[k] + f * line[k + 1];
}

Eigen::Vector2d RoadEdge::tangentAt(double at) const {
  double f;
  const size_t k = locate(*this, at, f);
  return (line[k + 1] - line[k]).normalized();
}

double RoadEdge::headingAt(double at, bool forward) const {
  const Eigen::Vector2d t = tangentAt(at) * (forward ? 1.0 : -1.0);
  return std::atan2(t.y(), t.x());
}

Eigen::Vector2d RoadEdge::sidePoint(double at, double offset) const {
  double f;
  const size_t k = locate(*this, at, f);  // once for the point and the tangent
  const Eigen::Vector2d point = (1.0 - f) * line[k] + f * line[k + 1];
  const Eigen::Vector2d t = (line[k + 1] - line[k]).normalized();
  return point + offset * Eigen::Vector2d(t.y(), -t.x());
}

void RoadNetwork::addEdge(int a, int b, bool avenue, const RoadProfile& profile, double bulge) {
  RoadEdge e;
  e.a = a;
  e.b = b;
  e.avenue = avenue;
  e.profile = profile;
  const Eigen::Vector2d pa = nodes_[a].p, pb = nodes_[b].p;
  const Eigen::Vector2d dir = pb - pa;
  // Quadratic Bézier; bulge 0 is the straight segment.
  const Eigen::Vector2d ctrl = 0.5 * (pa + pb) + bulge * Eigen::Vector2d(-dir.y(), dir.x());
  const int n = std::max(2, static_cast<int>(std::ceil(dir.norm() * (1.0 + 2.0 * std::abs(bulge)) / kLineStep)));
  for (int k = 0; k <= n; ++k) {
    const double u = static_cast<double>(k) / n;
    e.line.push_back((1 - u) * (1 - u) * pa + 2 * u * (1 - u) * ctrl + u * u * pb);
    e.s.push_back(k == 0 ? 0.0 : e.s.back() + (e.line[k] - e.line[k - 1]).norm());
  }
  nodes_[a].edges.push_back(static_cast<int>(edges_.size()));
  nodes_[b].edges.push_back(static_cast<int>(edges_.size()));
  edges_.push_back(std::move(e));
}

bool RoadNetwork::connectedWithout(int skip) const {
  std::vector<char> seen(nodes_.size(), 0);
  std::vector<int> stack = {0};
  seen[0] = 1;
  size_t count = 1;
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    for (int e : nodes_[n].edges) {
      if (e == skip) continue;
      const int m = otherEnd(e, n);
      if (!seen[m]) {
        seen[m] = 1;
        ++count;
        stack.push_back(m);
      }
    }
  }
  return count == nodes_.size();
}

RoadNetwork RoadNetwork::generate(const ScenePreset& preset, int blocks_x, int blocks_y, uint64_t seed) {
  Rng rng(seed, Stream::kRoads);
  RoadNetwork net;
  const int nx = blocks_x + 1, ny = blocks_y + 1;
  std::vector<double> xs = {0.0}, ys = {0.0};
  for (int i = 1; i < nx; ++i) xs.push_back(xs.back() + rng.uniform(preset.block_min, preset.block_max));
  for (int j = 1; j < ny; ++j) ys.push_back(ys.back() + rng.uniform(preset.block_min, preset.block_max));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      // y before x: the order GCC drew them in, kept so outputs stay the same (rng.h).
      const double jitter_y = rng.uniform(-1, 1);
      const double jitter_x = rng.uniform(-1, 1);
      const Eigen::Vector2d jitter(jitter_x, jitter_y);
      net.nodes_.push_back(RoadNode{Eigen::Vector2d(xs[i], ys[j]) + preset.node_jitter * jitter, {}});
    }
  }
  auto id = [nx](int i, int j) { return j * nx + i; };
  std::vector<char> avenue_row(ny), avenue_col(nx);
  for (auto& a : avenue_row) a = rng.chance(preset.avenue_probability);
  for (auto& a : avenue_col) a = rng.chance(preset.avenue_probability);
  auto streetProfile = [&] {
    RoadProfile p = preset.street;
    p.verge_width = rng.chance(preset.verge_probability) ? preset.street_verge_width : 0.0;
    if (!rng.chance(preset.street_parking_probability)) p.parking_width = 0.0;
    return p;
  };
  auto bulge = [&](bool avenue) {
    if (avenue || !rng.chance(preset.curve_probability)) return 0.0;
    const double sign = rng.chance(0.5) ? 1.0 : -1.0;
    return sign * preset.curve_bulge * rng.uniform(0.5, 1.0);
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const bool av = avenue_row[j];
      const double curve = bulge(av);  // drawn before the profile: the order GCC drew them in, kept (rng.h)
      net.addEdge(id(i, j), id(i + 1, j), av, av ? preset.avenue : streetProfile(), curve);
    }
  }
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j + 1 < ny; ++j) {
      const bool av = avenue_col[i];
      const double curve = bulge(av);  // drawn before the profile: the order GCC drew them in, kept (rng.h)
      net.addEdge(id(i, j), id(i, j + 1), av, av ? preset.avenue : streetProfile(), curve);
    }
  }
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      if (!rng.chance(preset.diagonal_probability)) continue;
      if (rng.chance(0.5)) {
        const double curve = bulge(false);  // drawn before the profile: the order GCC drew them in, kept (rng.h)
        net.addEdge(id(i, j), id(i + 1, j + 1), false, streetProfile(), curve);
      } else {
        const double curve = bulge(false);  // drawn before the profile: the order GCC drew them in, kept (rng.h)
        net.addEdge(id(i + 1, j), id(i, j + 1), false, streetProfile(), curve);
      }
    }
  }
  // Drop some streets, keeping the graph connected and every intersection with at least two roads (no dead
  // ends, so a route never needs a U-turn).
  std::vector<char> removed(net.edges_.size(), 0);
  for (size_t e = 0; e < net.edges_.size(); ++e) {
    const RoadEdge& edge = net.edges_[e];
    if (edge.avenue || !rng.chance(preset.remove_probability)) continue;
    if (net.nodes_[edge.a].edges.size() < 3 || net.nodes_[edge.b].edges.size() < 3) continue;
    if (!net.connectedWithout(static_cast<int>(e))) continue;
    removed[e] = 1;
    for (int n : {edge.a, edge.b}) {
      auto& list = net.nodes_[n].edges;
      list.erase(std::find(list.begin(), list.end(), static_cast<int>(e)));
    }
  }
  // Compact the edge list.
  RoadNetwork out;
  out.nodes_ = net.nodes_;
  for (auto& n : out.nodes_) n.edges.clear();
  for (size_t e = 0; e < net.edges_.size(); ++e) {
    if (removed[e]) continue;
    const int index = static_cast<int>(out.edges_.size());
    out.edges_.push_back(std::move(net.edges_[e]));
    out.nodes_[out.edges_.back().a].edges.push_back(index);
    out.nodes_[out.edges_.back().b].edges.push_back(index);
  }
  return out;
}

double RoadNetwork::clearance(int node) const {
  double widest = 0.0;
  for (int e : nodes_[node].edges) widest = std::max(widest, edges_[e].profile.edge());
  return widest + 1.0;
}

double RoadNetwork::totalLength() const {
  double sum = 0.0;
  for (const RoadEdge& e : edges_) sum += e.length();
  return sum;
}

Eigen::Vector2d RoadNetwork::lo() const {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300);
  for (const RoadEdge& e : edges_) {
    for (const auto& p : e.line) lo = lo.cwiseMin(p);
  }
  return lo;
}

Eigen::Vector2d RoadNetwork::hi() const {
  Eigen::Vector2d hi = Eigen::Vector2d::Constant(-1e300);
  for (const RoadEdge& e : edges_) {
    for (const auto& p : e.line) hi = hi.cwiseMax(p);
  }
  return hi;
}

}  // namespace sgtllc::sim
