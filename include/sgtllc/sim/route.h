/// @file route.h
/// @brief Where the vehicle drives: a walk over the road graph that explores, then comes back to stretches it has
///        driven before, in the same direction, the opposite direction, or one or two lanes aside.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/sim/road_network.h"

namespace sgtllc::sim {

/// Why a leg is driven.
enum class VisitKind : uint8_t {
  kExplore,            ///< new ground (or driven again by chance)
  kTransfer,           ///< on the way to a planned revisit
  kSameDirection,      ///< revisit, same lane and direction
  kOppositeDirection,  ///< revisit the other way round
  kLaneShift1,         ///< revisit, same direction, one lane towards the centre line
  kLaneShift2,         ///< revisit, same direction, two lanes aside (avenues)
};
const char* visitKindName(VisitKind kind);
inline bool isRevisit(VisitKind k) { return k != VisitKind::kExplore && k != VisitKind::kTransfer; }

/// One road driven end to end.
struct Leg {
  int edge = 0;
  bool forward = true;  ///< from node a to node b
  double offset = 0.0;  ///< lateral position, metres right of the centre line in the direction of travel
  VisitKind kind = VisitKind::kExplore;
  int source = -1;      ///< revisits: index of the leg driven before on the same road
};

/// Usual lateral position: near the middle of a one-lane-per-direction street, the outer lane of an avenue.
double defaultOffset(const RoadProfile& profile);

/// A route of at least @p length metres with @p revisits planned revisits (fewer if the route is too short for
/// them: each is at least 80 m). Every round of four revisits drives each kind (same direction, opposite, one and
/// two lanes aside) once, the one whose stretch is cheapest to reach first; two lanes need an avenue.
std::vector<Leg> planRoute(const RoadNetwork& net, double length, int revisits, uint64_t seed);

/// What a second session's planner knows of the first session through the same world.
struct PriorRoute {
  std::vector<Leg> legs;                           ///< the first session's route
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< where it started (world xy)
};

/// A second session's route of at least @p length metres through the network @p prior was driven on: it starts at
/// an intersection away from the first session's start, then alternates stretches along roads the first session
/// drove (either direction: the relocalization positives) and stretches of roads it never drove (the negatives),
/// about kFollowStretch and kFreshStretch metres each (route.cpp). No planned revisits of its own. With
/// @p follow_only, only stretches along the first session's roads: the same streets again, either way (where every
/// road the first session drove has been driven, it goes on preferring them).
std::vector<Leg> planSecondRoute(const RoadNetwork& net, double length, const PriorRoute& prior, uint64_t seed,
                                 bool follow_only = false);

/// Length of a leg (m).
inline double legLength(const RoadNetwork& net, const Leg& leg) { return net.edges()[leg.edge].length(); }

}  // namespace sgtllc::sim
