// A synthetic two-session world for the map tests: landmarks of the seven classes on a plane, and node frames
// seen from a closed circular route (frames 100.. revisit 0..), with seeded centre noise.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/map/map.h"

namespace sgtllc::test {

struct NodeSequence {
  std::vector<std::vector<Node>> frames;
  std::vector<Eigen::Matrix4d> poses;  ///< T_world_sensor
  std::vector<std::string> names;
};

inline std::vector<Node> landmarks(uint32_t seed = 7, int count = 400) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> xy(-110.0, 110.0), z(0.0, 6.0);
  std::uniform_int_distribution<int> label(0, kNumPaperClasses - 1);
  std::vector<Node> world(static_cast<size_t>(count));
  for (Node& n : world) {
    n.centre = Eigen::Vector3d(xy(rng), xy(rng), z(rng));
    n.label = label(rng);
  }
  return world;
}

/// @p frames poses on a circle of radius @p radius (100 per lap, so frame 100 + k revisits frame k), shifted by
/// @p offset (m) and turned by @p phase (rad); nodes are the landmarks within 35 m with N(0, noise²) per axis.
inline NodeSequence circleSequence(int frames, double offset = 0.0, double phase = 0.0, uint32_t seed = 1,
                                   double noise = 0.03, const std::string& prefix = "") {
  const std::vector<Node> world = landmarks();
  std::mt19937 rng(seed);
  std::normal_distribution<double> jitter(0.0, noise);
  NodeSequence s;
  for (int i = 0; i < frames; ++i) {
    const double a = phase + 2.0 * M_PI * i / 100.0;
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    T.topLeftCorner<3, 3>() = Eigen::AngleAxisd(a + M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.topRightCorner<3, 1>() = Eigen::Vector3d((60.0 + offset) * std::cos(a), (60.0 + offset) * std::sin(a), 1.7);
    const Eigen::Matrix4d T_sensor_world = T.inverse();
    std::vector<Node> nodes;
    for (const Node& n : world) {
      if ((n.centre - T.topRightCorner<3, 1>()).head<2>().norm() > 35.0) continue;
      Node seen = n;
      seen.centre = T_sensor_world.topLeftCorner<3, 3>() * n.centre + T_sensor_world.topRightCorner<3, 1>();
      for (int k = 0; k < 3; ++k) seen.centre[k] += jitter(rng);
      nodes.push_back(seen);
    }
    char name[16];
    std::snprintf(name, sizeof name, "%06d", i);
    s.frames.push_back(std::move(nodes));
    s.poses.push_back(T);
    s.names.push_back(prefix + name);
  }
  return s;
}

/// Runs @p s through a detector; returns it (its database is the map's).
inline LoopDetector runNodes(const NodeSequence& s, const Config& config, std::vector<FrameResult>* results = nullptr) {
  LoopDetector detector(config);
  for (const auto& nodes : s.frames) {
    FrameResult r = detector.process(nodes);
    if (results) results->push_back(std::move(r));
  }
  return detector;
}

}  // namespace sgtllc::test
