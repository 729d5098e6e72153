#include "sgtllc/sim/route.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "sgtllc/sim/rng.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

constexpr double kMinRevisit = 80.0;     // m: shortest planned revisit
constexpr double kRevisitShare = 0.3;    // of the route spent on planned revisits (transfers come on top)
constexpr double kRecentGuard = 100.0;   // m: a revisit's source ends at least this far back along the route
constexpr double kMinLaneShift = 3.3;    // m: lateral shift per lane of a lane-shift revisit
// A second session (planSecondRoute): stretches along the first session's roads, then away from them.
constexpr double kFollowStretch = 350.0;  // m
constexpr double kFreshStretch = 250.0;   // m
constexpr double kFreshStart = 150.0;     // m: it starts at least this far from the first session's start if it can
constexpr double kPhaseBias = 8.0;        // weight of a road that suits the current stretch over one that does not

/// A directed edge: 2·edge + (forward ? 0 : 1).
int directed(int edge, bool forward) { return 2 * edge + (forward ? 0 : 1); }

class Planner {
 public:
  /// @p prior: the first session, for a second session's route (null for a first session); it starts at the
  /// intersection nearest the first session's start if @p start_where_prior_did.
  Planner(const RoadNetwork& net, uint64_t seed, const PriorRoute* prior = nullptr, bool start_where_prior_did = false)
      : net_(net), rng_(seed, Stream::kRoute), visits_(net.edges().size()) {
    // Start at a random intersection away from the border when there is one (and away from where the first
    // session started, so the second one's start differs).
    std::vector<int> inner;
    for (size_t n = 0; n < net.nodes().size(); ++n) {
      const bool fresh = !prior || (net.nodes()[n].p - prior->start).norm() >= kFreshStart;
      if (net.nodes()[n].edges.size() >= 4 && fresh) inner.push_back(static_cast<int>(n));
    }
    if (prior && inner.empty()) {
      for (size_t n = 0; n < net.nodes().size(); ++n) {
        if (net.nodes()[n].edges.size() >= 4) inner.push_back(static_cast<int>(n));
      }
    }
    node_ = inner.empty() ? 0 : inner[rng_.uniformInt(0, static_cast<int>(inner.size()) - 1)];
    if (prior && start_where_prior_did) {  // the same streets again: from the first session's start
      for (size_t n = 0; n < net.nodes().size(); ++n) {
        if ((net.nodes()[n].p - prior->start).norm() < (net.nodes()[node_].p - prior->start).norm()) {
          node_ = static_cast<int>(n);
        }
      }
    }
    if (prior) {
      known_.assign(net.edges().size(), 0);
      for (const Leg& leg : prior->legs) known_[leg.edge] = 1;
    }
  }

  /// A second session's stretch along the first session's roads: to the cheapest one not driven yet in this
  /// session, then on, preferring its roads, until @p length metres are driven.
  void follow(double length) {
    follow_ = true;
    const double goal = length_ + length;
    const std::vector<double> cost = costsFromHere();
    int target = -1;
    for (size_t d = 0; d < cost.size(); ++d) {
      const int e = static_cast<int>(d / 2);
      if (known_[e] && visits_[e] == 0 && std::isfinite(cost[d]) && (target < 0 || cost[d] < cost[target])) {
        target = static_cast<int>(d);
      }
    }
    if (target >= 0) {
      transferTo(target);
      drive(Leg{target / 2, target % 2 == 0, 0.0, VisitKind::kExplore, -1}, true);
    }
    if (length_ < goal) explore(goal - length_);
  }

  /// A second session that drives only the first session's roads: the least driven of them in this session,
  /// nearest first, reached by the cheapest path (which may cross a road the first session did not drive).
  void followAgain() {
    follow_ = true;
    int fewest = std::numeric_limits<int>::max();
    for (size_t e = 0; e < known_.size(); ++e) {
      if (known_[e]) fewest = std::min(fewest, visits_[e]);
    }
    const std::vector<double> cost = costsFromHere();
    int target = -1;
    for (size_t d = 0; d < cost.size(); ++d) {
      const int e = static_cast<int>(d / 2);
      if (known_[e] && visits_[e] == fewest && std::isfinite(cost[d]) && (target < 0 || cost[d] < cost[target])) {
        target = static_cast<int>(d);
      }
    }
    if (target < 0) {  // none reachable: on as a first session would
      explore(kFollowStretch);
      return;
    }
    transferTo(target);
    drive(Leg{target / 2, target % 2 == 0, 0.0, VisitKind::kExplore, -1}, true);
  }

  /// A second session's stretch preferring roads the first session never drove.
  void leave(double length) {
    follow_ = false;
    explore(length);
  }

  void explore(double length) {
    const double goal = length_ + length;
    while (length_ < goal) {
      const auto& options = net_.nodes()[node_].edges;
      std::vector<double> weight(options.size());
      double total = 0.0;
      for (size_t k = 0; k < options.size(); ++k) {
        const int e = options[k];
        if (e == last_edge_ && options.size() > 1) continue;  // no U-turns
        const double turn = turnCosine(e);
        weight[k] = (visits_[e] == 0 ? 6.0 : 1.0) * (1.5 + turn) * phaseBias(e);
        total += weight[k];
      }
      double pick = rng_.uniform(0.0, total);
      size_t k = 0;
      for (size_t c = 0; c < options.size(); ++c) {
        if (weight[c] == 0.0) continue;
        k = c;  // the last option with weight, should rounding leave pick ≥ 0 after all of them
        if (pick < weight[c]) break;
        pick -= weight[c];
      }
      drive(Leg{options[k], net_.edges()[options[k]].a == node_, 0.0, VisitKind::kExplore, -1}, true);
    }
  }

  /// Drives back to the stretch of earlier legs that is cheapest to reach and suits one of @p kinds, and along it
  /// again as that kind. Returns the kind driven, or kExplore if no stretch qualifies.
  VisitKind revisit(const std::vector<VisitKind>& kinds, double length) {
    const std::vector<double> cost = costsFromHere();
    double best = std::numeric_limits<double>::infinity();
    size_t best_i = 0, best_j = 0;
    VisitKind kind = VisitKind::kExplore;
    std::vector<double> start_at(legs_.size() + 1, 0.0);
    for (size_t i = 0; i < legs_.size(); ++i) start_at[i + 1] = start_at[i] + legLength(net_, legs_[i]);
    for (const VisitKind candidate : kinds) {
      for (size_t i = 0; i < legs_.size(); ++i) {
        double driven = 0.0;
        for (size_t j = i; j < legs_.size(); ++j) {
          if (used_[j] || isRevisit(legs_[j].kind) || !suits(candidate, legs_[j])) break;
          driven += legLength(net_, legs_[j]);
          if (driven < length) continue;
          if (start_at[j + 1] > length_ - kRecentGuard) break;
          const bool opposite = candidate == VisitKind::kOppositeDirection;
          const Leg& entry = opposite ? legs_[j] : legs_[i];
          const double c = cost[directed(entry.edge, opposite ? !entry.forward : entry.forward)] + rng_.uniform(0, 60);
          if (c < best) {
            best = c;
            best_i = i;
            best_j = j;
            kind = candidate;
          }
          break;
        }
      }
    }
    if (!std::isfinite(best)) return VisitKind::kExplore;
    const Leg& entry = kind == VisitKind::kOppositeDirection ? legs_[best_j] : legs_[best_i];
    transferTo(directed(entry.edge, kind == VisitKind::kOppositeDirection ? !entry.forward : entry.forward));
    std::vector<Leg> stretch;
    for (size_t k = best_i; k <= best_j; ++k) {
      used_[k] = 1;
      Leg leg = legs_[k];
      leg.kind = kind;
      leg.source = static_cast<int>(k);
      const RoadProfile& p = net_.edges()[leg.edge].profile;
      if (kind == VisitKind::kOppositeDirection) {
        leg.forward = !leg.forward;
        leg.offset = defaultOffset(p) + rng_.uniform(-0.2, 0.2);
      } else if (kind == VisitKind::kSameDirection) {
        leg.offset += rng_.uniform(-0.3, 0.3);
      } else {
        // At least 3.3 m per lane, so the passes lie clearly more than 3 m apart even on narrow lanes.
        leg.offset -= (kind == VisitKind::kLaneShift1 ? 1.0 : 2.0) * std::max(p.lane_width, kMinLaneShift);
      }
      stretch.push_back(leg);
    }
    if (kind == VisitKind::kOppositeDirection) std::reverse(stretch.begin(), stretch.end());
    for (const Leg& leg : stretch) drive(leg, false);
    return kind;
  }

  double length() const { return length_; }
  std::vector<Leg> legs() const { return legs_; }

 private:
  /// Cosine of the heading change when leaving the current node along edge e (1 = straight on).
  double turnCosine(int e) const {
    if (last_edge_ < 0) return 0.0;
    const RoadEdge& in = net_.edges()[last_edge_];
    const RoadEdge& out = net_.edges()[e];
    const Eigen::Vector2d t_in = in.b == node_ ? in.tangentAt(in.length()) : -in.tangentAt(0.0);
    const Eigen::Vector2d t_out = out.a == node_ ? out.tangentAt(0.0) : -out.tangentAt(out.length());
    return t_in.dot(t_out);
  }

  /// 1 for a first session; for a second one, favours the first session's roads while following them and the
  /// others while away from them.
  double phaseBias(int e) const {
    if (known_.empty()) return 1.0;
    return (known_[e] != 0) == follow_ ? kPhaseBias : 1.0;
  }

  bool suits(VisitKind kind, const Leg& leg) const {
    const RoadEdge& e = net_.edges()[leg.edge];
    if (kind == VisitKind::kLaneShift2) return e.avenue;
    // One lane aside on a street with parked cars would pass them at arm's length: avenues and streets without
    // parking lanes only.
    if (kind == VisitKind::kLaneShift1) return e.avenue || e.profile.parking_width <= 0.0;
    if (kind == VisitKind::kOppositeDirection) return !e.avenue;  // narrow roads: the other way is within 3 m
    return true;
  }

  void drive(Leg leg, bool default_offset) {
    const RoadEdge& e = net_.edges()[leg.edge];
    if (default_offset) leg.offset = defaultOffset(e.profile) + rng_.uniform(-0.2, 0.2);
    legs_.push_back(leg);
    used_.push_back(0);
    ++visits_[leg.edge];
    length_ += e.length();
    last_edge_ = leg.edge;
    node_ = leg.forward ? e.b : e.a;
  }

  /// Cheapest distance from the current position to the start of every directed edge (no U-turns); edge-based
  /// Dijkstra, ties broken by index so the result is deterministic.
  std::vector<double> costsFromHere() {
    const size_t n = 2 * net_.edges().size();
    std::vector<double> cost(n, std::numeric_limits<double>::infinity());
    prev_.assign(n, -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (int e : net_.nodes()[node_].edges) {
      if (e == last_edge_ && net_.nodes()[node_].edges.size() > 1) continue;
      const int d = directed(e, net_.edges()[e].a == node_);
      cost[d] = 0.0;
      queue.push({0.0, d});
    }
    while (!queue.empty()) {
      const auto [c, d] = queue.top();
      queue.pop();
      if (c > cost[d]) continue;
      const RoadEdge& e = net_.edges()[d / 2];
      const int end = d % 2 == 0 ? e.b : e.a;
      for (int next : net_.nodes()[end].edges) {
        if (next == d / 2 && net_.nodes()[end].edges.size() > 1) continue;
        const int nd = directed(next, net_.edges()[next].a == end);
        const double nc = c + e.length();
        if (nc < cost[nd]) {
          cost[nd] = nc;
          prev_[nd] = d;
          queue.push({nc, nd});
        }
      }
    }
    return cost;
  }

  /// Drives the cheapest path found by the last costsFromHere() up to (not including) directed edge @p target.
  void transferTo(int target) {
    std::vector<int> path;
    for (int d = prev_[target]; d >= 0; d = prev_[d]) path.push_back(d);
    std::reverse(path.begin(), path.end());
    for (int d : path) drive(Leg{d / 2, d % 2 == 0, 0.0, VisitKind::kTransfer, -1}, true);
  }

  const RoadNetwork& net_;
  Rng rng_;
  std::vector<int> visits_;
  std::vector<Leg> legs_;
  std::vector<char> used_;
  std::vector<int> prev_;
  int node_ = 0, last_edge_ = -1;
  double length_ = 0.0;
  std::vector<char> known_;  ///< second session: per edge, driven by the first session (empty for a first session)
  bool follow_ = false;      ///< second session: following the first session's roads (else away from them)
};

}  // namespace

const char* visitKindName(VisitKind kind) {
  switch (kind) {
    case VisitKind::kExplore: return "explore";
    case VisitKind::kTransfer: return "transfer";
    case VisitKind::kSameDirection: return "same direction";
    case VisitKind::kOppositeDirection: return "opposite direction";
    case VisitKind::kLaneShift1: return "one lane aside";
    case VisitKind::kLaneShift2: return "two lanes aside";
  }
  return "?";
}

double defaultOffset(const RoadProfile& p) {
  return p.lanes_per_direction == 1 ? 0.38 * p.lane_width : (p.lanes_per_direction - 0.5) * p.lane_width;
}

std::vector<Leg> planRoute(const RoadNetwork& net, double length, int revisits, uint64_t seed) {
  Planner planner(net, seed);
  const int k = std::clamp(revisits, 0, static_cast<int>(kRevisitShare * length / kMinRevisit));
  const double each = k > 0 ? std::clamp(kRevisitShare * length / k, kMinRevisit, 600.0) : 0.0;
  // Getting back to an earlier road without U-turns costs about a loop round a block.
  const double transfer = 3.0 * net.totalLength() / std::max<size_t>(1, net.edges().size());
  const std::vector<VisitKind> all = {VisitKind::kSameDirection, VisitKind::kOppositeDirection,
                                      VisitKind::kLaneShift1, VisitKind::kLaneShift2};
  std::vector<VisitKind> needed;
  planner.explore(each + kRecentGuard + 50.0);
  for (int r = 0; r < k; ++r) {
    // Each round of revisits covers every kind once, cheapest to reach first. A kind may find no suitable stretch
    // yet (no avenue driven for two lanes aside): explore a little more, then take one lane aside or the same
    // direction and start a new round.
    if (needed.empty()) needed = all;
    VisitKind done = VisitKind::kExplore;
    for (int attempt = 0; attempt < 4 && done == VisitKind::kExplore; ++attempt) {
      done = planner.revisit(needed, each);
      if (done == VisitKind::kExplore) planner.explore(1.0);
    }
    if (done == VisitKind::kExplore) {
      planner.revisit({VisitKind::kLaneShift1, VisitKind::kSameDirection}, each);
      needed.clear();
    }
    needed.erase(std::remove(needed.begin(), needed.end(), done), needed.end());
    // Spread the remaining revisits over the remaining length.
    const int left = k - r - 1;
    if (left > 0) planner.explore((length - planner.length()) / left - each - transfer);
  }
  // Spare road at the end: driving speed is only known once the path is smoothed.
  planner.explore(std::max(0.0, 1.2 * length + 100.0 - planner.length()));
  return planner.legs();
}

std::vector<Leg> planSecondRoute(const RoadNetwork& net, double length, const PriorRoute& prior, uint64_t seed,
                                 bool follow_only) {
  for (const Leg& leg : prior.legs) {
    if (leg.edge < 0 || leg.edge >= static_cast<int>(net.edges().size())) {
      throw Error("the first session's route does not belong to this road network");
    }
  }
  Planner planner(net, seed, &prior, follow_only);
  // Spare road at the end, as planRoute leaves.
  const double goal = 1.2 * length + 100.0;
  while (planner.length() < goal) {
    if (follow_only) {
      planner.followAgain();
      continue;
    }
    planner.follow(kFollowStretch);
    if (planner.length() < goal) planner.leave(kFreshStretch);
  }
  return planner.legs();
}

}  // namespace sgtllc::sim
