#include "sgtllc/eval/false_loops.h"

#include <algorithm>
#include <cmath>

#include "sgtllc/sim/rng.h"

namespace sgtllc::eval {

std::vector<pipeline::ClosingLoop> falseLoops(const std::vector<Eigen::Isometry3d>& odometry,
                                              const std::vector<pipeline::ClosingLoop>& real, double fraction,
                                              uint64_t seed, const std::vector<std::string>& frame_names,
                                              const backend::LoopNoise& noise, double min_distance) {
  std::vector<pipeline::ClosingLoop> out;
  if (!(fraction > 0.0)) return out;
  const int count = std::max(1, static_cast<int>(std::lround(fraction * static_cast<double>(real.size()))));
  const int n = static_cast<int>(odometry.size());
  // The Rng's own distributions (not <random>'s), so a seed gives the same loops with any standard library.
  sim::Rng rng(seed);
  constexpr int kAttemptsPerLoop = 10000;
  for (int attempt = 0; static_cast<int>(out.size()) < count; ++attempt) {
    if (attempt >= kAttemptsPerLoop * count || n < 2) {
      throw Error("false loops: found no frame pair more than " + std::to_string(std::lround(min_distance)) +
                  " m apart by the odometry in " + std::to_string(attempt) + " random draws");
    }
    int a = rng.uniformInt(0, n - 1), b = rng.uniformInt(0, n - 1);
    if (a > b) std::swap(a, b);
    if ((odometry[a].translation() - odometry[b].translation()).norm() <= min_distance) continue;
    pipeline::ClosingLoop l;
    l.edge.from = a;
    l.edge.to = b;
    l.edge.kind = backend::EdgeKind::kLoop;
    // One draw per statement, so every compiler draws in the same order (sgtllc/sim/rng.h); yaw, z, y, x is the
    // order GCC drew them in, kept so existing outputs stay the same.
    const double yaw = rng.uniform(-M_PI, M_PI);
    const double z = rng.uniform(-1.0, 1.0);
    const double y = rng.uniform(-10.0, 10.0);
    const double x = rng.uniform(-10.0, 10.0);
    l.edge.T_from_to = Eigen::Translation3d(x, y, z) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    l.edge.information = real.empty() ? pipeline::nominalLoopInformation(noise)
                                      : real[static_cast<size_t>(rng.uniformInt(0, static_cast<int>(real.size()) - 1))]
                                            .edge.information;
    l.query = frame_names.at(static_cast<size_t>(b));
    l.match = frame_names.at(static_cast<size_t>(a));
    l.injected = true;
    out.push_back(l);
  }
  return out;
}

std::vector<pipeline::ClosingLoop> falseInterSessionLoops(const std::vector<Eigen::Isometry3d>& map_poses,
                                                          const std::vector<pipeline::ClosingLoop>& loops,
                                                          double fraction, uint64_t seed,
                                                          const std::vector<std::string>& map_names,
                                                          double min_distance) {
  std::vector<pipeline::ClosingLoop> out;
  const int m = static_cast<int>(map_poses.size());
  std::vector<const pipeline::ClosingLoop*> inter;
  for (const pipeline::ClosingLoop& l : loops) {
    if (l.edge.from < m && l.edge.to >= m) inter.push_back(&l);
  }
  if (!(fraction > 0.0) || inter.empty()) return out;
  const int count = std::max(1, static_cast<int>(std::lround(fraction * static_cast<double>(inter.size()))));
  sim::Rng rng(seed);
  constexpr int kAttemptsPerLoop = 10000;
  for (int attempt = 0; static_cast<int>(out.size()) < count; ++attempt) {
    if (attempt >= kAttemptsPerLoop * count) {
      throw Error("false inter-session loops: found no map frame more than " + std::to_string(std::lround(min_distance)) +
                  " m from the map frames of the inter-session loops in " + std::to_string(attempt) + " random draws");
    }
    const pipeline::ClosingLoop& real = *inter[static_cast<size_t>(rng.uniformInt(0, static_cast<int>(inter.size()) - 1))];
    const int a = rng.uniformInt(0, m - 1);
    if ((map_poses[static_cast<size_t>(a)].translation() - map_poses[static_cast<size_t>(real.edge.from)].translation())
            .norm() <= min_distance) {
      continue;
    }
    pipeline::ClosingLoop l;
    l.edge.from = a;
    l.edge.to = real.edge.to;
    l.edge.kind = backend::EdgeKind::kLoop;
    const double yaw = rng.uniform(-M_PI, M_PI);  // one draw per statement (sgtllc/sim/rng.h)
    const double z = rng.uniform(-1.0, 1.0);
    const double y = rng.uniform(-10.0, 10.0);
    const double x = rng.uniform(-10.0, 10.0);
    l.edge.T_from_to = Eigen::Translation3d(x, y, z) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    l.edge.information = real.edge.information;
    l.query = real.query;
    l.match = map_names.at(static_cast<size_t>(a));
    l.injected = true;
    out.push_back(l);
  }
  return out;
}

}  // namespace sgtllc::eval
