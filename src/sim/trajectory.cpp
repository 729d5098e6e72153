#include "sgtllc/sim/trajectory.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {
namespace {

constexpr double kStep = 1.0;            // m between path samples
constexpr int kSmoothHalfWidth = 6;      // box filter half width (samples) ...
constexpr int kSmoothPasses = 3;         // ... applied this often: turns of about 10 m radius
constexpr double kLateralAccel = 2.0;    // m/s² allowed in turns
constexpr double kAccel = 1.5, kDecel = 2.5;  // m/s²
constexpr double kSpeedFloor = 5.0, kSpeedCeiling = 15.0;

struct Path {
  std::vector<Eigen::Vector2d> p;
  std::vector<int> leg;
};

/// Lane-offset polylines of the legs, resampled every kStep metres.
Path rawPath(const RoadNetwork& net, const std::vector<Leg>& legs) {
  std::vector<Eigen::Vector2d> pts;
  std::vector<int> owner;
  for (size_t i = 0; i < legs.size(); ++i) {
    const RoadEdge& e = net.edges()[legs[i].edge];
    const int n = std::max(1, static_cast<int>(std::ceil(e.length() / kStep)));
    for (int k = 0; k <= n; ++k) {
      const double along = e.length() * k / n;
      const double at = legs[i].forward ? along : e.length() - along;
      const Eigen::Vector2d q = e.sidePoint(at, legs[i].forward ? legs[i].offset : -legs[i].offset);
      if (!pts.empty() && (q - pts.back()).norm() < 0.3) continue;
      pts.push_back(q);
      owner.push_back(static_cast<int>(i));
    }
  }
  // Uniform resampling by arc length.
  Path out;
  if (pts.empty()) return out;
  double carry = 0.0;
  out.p.push_back(pts[0]);
  out.leg.push_back(owner[0]);
  for (size_t k = 1; k < pts.size(); ++k) {
    const double len = (pts[k] - pts[k - 1]).norm();
    double at = kStep - carry;
    while (at <= len) {
      out.p.push_back(pts[k - 1] + (pts[k] - pts[k - 1]) * (at / len));
      out.leg.push_back(owner[k]);
      at += kStep;
    }
    carry = len - (at - kStep);
  }
  return out;
}

void smooth(std::vector<Eigen::Vector2d>& p) {
  const int n = static_cast<int>(p.size());
  for (int pass = 0; pass < kSmoothPasses; ++pass) {
    std::vector<Eigen::Vector2d> q(p.size());
    for (int i = 0; i < n; ++i) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      for (int k = -kSmoothHalfWidth; k <= kSmoothHalfWidth; ++k) sum += p[std::clamp(i + k, 0, n - 1)];
      q[i] = sum / (2 * kSmoothHalfWidth + 1);
    }
    p.swap(q);
  }
}

/// Sum of two slow sines: body pitch/roll wobble (rad) or bounce (m).
struct Wobble {
  double a1, p1, f1, a2, p2, f2;
  Wobble(Rng& rng, double amplitude)
      : a1(amplitude * rng.uniform(0.5, 1.0)), p1(rng.uniform(0, 2 * M_PI)), f1(rng.uniform(0.1, 0.3)),
        a2(0.5 * amplitude * rng.uniform(0.5, 1.0)), p2(rng.uniform(0, 2 * M_PI)), f2(rng.uniform(0.5, 1.2)) {}
  double at(double t) const { return a1 * std::sin(2 * M_PI * f1 * t + p1) + a2 * std::sin(2 * M_PI * f2 * t + p2); }
};

}  // namespace

std::vector<FramePose> driveRoute(const World& world, const std::vector<Leg>& legs, const TrajectoryConfig& config) {
  Rng rng(config.seed, Stream::kTrajectory);
  Path path = rawPath(world.roads, legs);
  const int n = static_cast<int>(path.p.size());
  if (n < 3) return {};
  smooth(path.p);

  // Speed: each leg's cruise speed, capped in turns, then limited by acceleration and braking.
  std::vector<double> cruise(legs.size());
  for (double& c : cruise) c = rng.uniform(config.speed_min, config.speed_max);
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = path.p[std::max(0, i - 2)], b = path.p[i], c = path.p[std::min(n - 1, i + 2)];
    const double turn = std::abs(std::atan2((b - a).x() * (c - b).y() - (b - a).y() * (c - b).x(), (b - a).dot(c - b)));
    const double curvature = turn / std::max(1e-6, 0.5 * ((b - a).norm() + (c - b).norm()));
    v[i] = std::clamp(std::min(cruise[path.leg[i]], std::sqrt(kLateralAccel / std::max(curvature, 1e-9))),
                      kSpeedFloor, kSpeedCeiling);
  }
  // Smoothing draws samples closer together in turns: use the true spacing from here on.
  std::vector<double> ds(n, 0.0);
  for (int i = 1; i < n; ++i) ds[i] = (path.p[i] - path.p[i - 1]).norm();
  for (int i = 1; i < n; ++i) v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2 * kAccel * ds[i]));
  for (int i = n - 2; i >= 0; --i) v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * kDecel * ds[i + 1]));
  std::vector<double> t(n, 0.0);
  for (int i = 1; i < n; ++i) t[i] = t[i - 1] + 2.0 * ds[i] / (v[i - 1] + v[i]);

  const Wobble pitch_wobble(rng, 0.25 * M_PI / 180.0), roll_wobble(rng, 0.2 * M_PI / 180.0), bounce(rng, 0.01);
  std::vector<FramePose> frames;
  int i = 0;
  for (int f = 0; f < config.frames; ++f) {
    const double time = f * config.period;
    while (i + 1 < n && t[i + 1] <= time) ++i;
    if (i + 1 >= n) break;  // the route ended
    const double u = (time - t[i]) / (t[i + 1] - t[i]);
    const Eigen::Vector2d xy = (1 - u) * path.p[i] + u * path.p[i + 1];
    const Eigen::Vector2d dir = (path.p[std::min(n - 1, i + 2)] - path.p[std::max(0, i - 1)]).normalized();
    const Eigen::Vector2d left(-dir.y(), dir.x());
    const Eigen::Vector2d grad = world.ground.gradient(xy.x(), xy.y());
    const double pitch = -std::atan(grad.dot(dir)) + pitch_wobble.at(time);
    const double roll = std::atan(grad.dot(left)) + roll_wobble.at(time);
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(std::atan2(dir.y(), dir.x()), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    FramePose pose;
    pose.time = time;
    pose.T_world_lidar.topLeftCorner<3, 3>() = R;
    pose.T_world_lidar.topRightCorner<3, 1>() =
        Eigen::Vector3d(xy.x(), xy.y(), world.ground.height(xy.x(), xy.y())) +
        R * Eigen::Vector3d(0, 0, config.sensor_height + bounce.at(time));
    pose.speed = (1 - u) * v[i] + u * v[i + 1];
    pose.leg = path.leg[i];
    pose.kind = legs[pose.leg].kind;
    frames.push_back(pose);
  }
  return frames;
}

}  // namespace sgtllc::sim
