// Do the planned revisits fit in the frames (revisit_fit.h)? planRoute drops revisits that need more road than
// the frames drive (each is at least 80 m and they take 30 % of the route), and the route is cut at the last frame.
#include "sgtllc/sim/revisit_fit.h"

#include <algorithm>
#include <cmath>

namespace sgtllc::sim {
namespace {

constexpr int kAttempts = 16;         // routes planned at most, each a tenth longer: up to 4.6 times the estimate
constexpr int kMaxFrames = 1000000;   // the command's --frames limit

}  // namespace

int drivenRevisits(const Simulator& simulator) {
  int runs = 0;
  VisitKind previous = VisitKind::kExplore;
  for (const FramePose& p : simulator.poses()) {
    if (isRevisit(p.kind) && p.kind != previous) ++runs;
    previous = p.kind;
  }
  return runs;
}

int framesForRevisits(const SimConfig& config) {
  SimConfig probe = config;
  probe.revisits = config.plannedRevisits();
  // Start where the route's revisit share (30 %) can hold every planned revisit of 80 m, at 8.5 m/s and 10 Hz.
  const double metres = probe.revisits * 80.0 / 0.3;
  probe.frames = std::max(config.frames + 1, static_cast<int>(std::ceil(metres / 0.85)));
  for (int attempt = 0; attempt < kAttempts && probe.frames <= kMaxFrames; ++attempt) {
    if (drivenRevisits(Simulator(probe)) >= probe.revisits) return probe.frames;
    probe.frames += std::max(1, probe.frames / 10);
  }
  return 0;
}

}  // namespace sgtllc::sim
