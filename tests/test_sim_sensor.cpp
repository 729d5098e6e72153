// Sensor ray patterns (HDL-64E beams, Mid-70 rosette) and scans cast against hand-built scenes whose answer is
// known: ranges, labels, occlusion, things that exist only for part of the time.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <Eigen/LU>

#include "sgtllc/sim/raycast.h"
#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(SimSensor, Hdl64BeamsAndAzimuthSteps) {
  const SensorModel s(SensorConfig::preset(SensorKind::kHdl64));
  ASSERT_EQ(s.rows(), 64);
  ASSERT_EQ(s.columns(), 2083);
  EXPECT_NEAR(s.elevations().front(), 2.0, 1e-9);
  EXPECT_NEAR(s.elevations().back(), -24.8, 1e-9);
  for (size_t r = 1; r < s.elevations().size(); ++r) EXPECT_LT(s.elevations()[r], s.elevations()[r - 1]);
  std::vector<Eigen::Vector3f> d;
  s.directions(0, 1, d);
  ASSERT_EQ(d.size(), 64u * 2083u);
  for (const auto& v : d) ASSERT_NEAR(v.norm(), 1.0f, 1e-5f);
  // Neighbouring columns of one beam are 360° / 2083 ≈ 0.173° apart.
  const double step = std::acos(std::clamp(static_cast<double>(d[0].dot(d[64])), -1.0, 1.0)) /
                      std::cos(2.0 * kDeg) / kDeg;
  EXPECT_NEAR(step, 360.0 / 2083.0, 1e-3);
  // Each turn starts at its own azimuth.
  std::vector<Eigen::Vector3f> d1;
  s.directions(1, 1, d1);
  EXPECT_FALSE(d[0].isApprox(d1[0]));
}

TEST(SimSensor, Mid70RosetteStaysInItsFieldOfViewAndNeverRepeats) {
  const SensorModel s(SensorConfig::preset(SensorKind::kMid70));
  ASSERT_EQ(s.raysPerScan(), 10000);
  EXPECT_FALSE(s.wraps());
  auto cells = [&](int scans) {
    std::set<std::pair<int, int>> hit;  // 1° cells of the field of view
    std::vector<Eigen::Vector3f> d;
    for (int k = 0; k < scans; ++k) {
      s.directions(k, 1, d);
      for (const auto& v : d) {
        EXPECT_LE(std::acos(static_cast<double>(v.x())), 35.2 * kDeg + 1e-4);
        hit.insert({static_cast<int>(std::floor(std::atan2(v.y(), v.x()) / kDeg)),
                    static_cast<int>(std::floor(std::atan2(v.z(), v.x()) / kDeg))});
      }
    }
    return hit.size();
  };
  const size_t one = cells(1), ten = cells(10);
  EXPECT_GT(ten, one + one / 2);  // more scans cover more of the field (a non-repetitive pattern)
  EXPECT_GT(ten, 2500u);          // ~π·35² ≈ 3,900 cells in all
}

/// A flat road with a wall 20 m ahead across the x axis and a pole 10 m ahead, no agents.
World testScene(bool with_car) {
  World w;
  w.ground = GroundHeight(1, 0.0);
  w.zones = ZoneMap(Eigen::Vector2d(-200, -200), Eigen::Vector2d(200, 200), 1.0, Zone::kRoad, Zone::kRoad);
  w.objects = {Object{ObjectKind::kBuilding, 0}, Object{ObjectKind::kPole, 0}, Object{ObjectKind::kVehicle, 7}};
  std::vector<Primitive> prims = {
      makeBox(Eigen::Vector2f(20.15f, 0), -1.0f, 0.3f, 40.0f, 12.0f, 0.0f, semantic::kBuilding, 0),
      makeCylinder(Eigen::Vector2f(10, 0), 0.0f, 0.2f, 6.0f, semantic::kPole, 1)};
  if (with_car) {
    Primitive car = makeBox(Eigen::Vector2f(0, 6), 0.2f, 4.4f, 1.8f, 1.3f, 0.0f, semantic::kCar, 2);
    car.t_end = 5.0f;  // drives away at t = 5 s
    prims.push_back(car);
  }
  w.statics = Bvh(prims);
  return w;
}

SensorModel exactSensor() {
  SensorConfig c = SensorConfig::preset(SensorKind::kHdl64);
  c.columns = 720;
  c.range_noise = 0.0;
  c.dropout = 0.0;
  return SensorModel(c);
}

Eigen::Matrix4d sensorAt(double height) {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T(2, 3) = height;
  return T;
}

TEST(SimRaycast, PointsLieOnTheSurfacesTheyAreLabelledWith) {
  const World w = testScene(false);
  const RawScan scan = castScan(w, exactSensor(), sensorAt(1.73), 0.0, 0, 1);
  ASSERT_GT(scan.points.size(), 20000u);
  std::set<uint16_t> labels;
  for (size_t i = 0; i < scan.points.size(); ++i) {
    const Eigen::Vector3f& p = scan.points[i];
    labels.insert(scan.semantic[i]);
    if (scan.semantic[i] == semantic::kRoad) {
      EXPECT_NEAR(p.z(), -1.73f, 1e-3f);
      EXPECT_NEAR(scan.height[i], 0.0f, 1e-3f);
    } else if (scan.semantic[i] == semantic::kBuilding) {
      EXPECT_NEAR(p.x(), 20.0f, 1e-3f);
    } else if (scan.semantic[i] == semantic::kPole) {
      EXPECT_NEAR(std::hypot(p.x() - 10.0f, p.y()), 0.2f, 1e-3f);
      EXPECT_LT(p.x(), 10.0f);  // only the near side is seen
    }
    EXPECT_GE(scan.intensity[i], 0.0f);
    EXPECT_LE(scan.intensity[i], 0.99f);
    EXPECT_EQ(scan.instance[i], 0);
  }
  EXPECT_EQ(labels, (std::set<uint16_t>{semantic::kRoad, semantic::kBuilding, semantic::kPole}));
}

TEST(SimRaycast, ThePoleHidesTheWallBehindIt) {
  const World w = testScene(false);
  const RawScan scan = castScan(w, exactSensor(), sensorAt(1.73), 0.0, 0, 1);
  int pole = 0;
  for (size_t i = 0; i < scan.points.size(); ++i) {
    const Eigen::Vector3f& p = scan.points[i];
    // Wall points inside the pole's shadow (seen from the sensor) would mean a ray went through the pole.
    if (scan.semantic[i] == semantic::kBuilding && p.z() < 6.0f - 1.73f) {
      EXPECT_GT(std::abs(p.y()) / p.x(), 0.2f / 10.0f - 1e-4f) << "wall point behind the pole at y " << p.y();
    }
    pole += scan.semantic[i] == semantic::kPole;
  }
  EXPECT_GT(pole, 50);
}

TEST(SimRaycast, ChangedObjectsAppearOnlyWhileTheyExist) {
  const World w = testScene(true);
  auto cars = [&](double time) {
    const RawScan scan = castScan(w, exactSensor(), sensorAt(1.73), time, 0, 1);
    int n = 0;
    for (size_t i = 0; i < scan.points.size(); ++i) {
      if (scan.semantic[i] == semantic::kCar) {
        ++n;
        EXPECT_EQ(scan.instance[i], 7);
      }
    }
    return n;
  };
  EXPECT_GT(cars(1.0), 200);
  EXPECT_EQ(cars(6.0), 0);
}

TEST(SimRaycast, RangeLimitAndNoiseAndDropout) {
  const World w = testScene(false);
  SensorConfig c = SensorConfig::preset(SensorKind::kHdl64);
  c.columns = 720;
  c.max_range = 15.0;  // the wall at 20 m is out of reach
  const RawScan scan = castScan(w, SensorModel(c), sensorAt(1.73), 0.0, 0, 1);
  double noise = 0.0;
  int road = 0;
  for (size_t i = 0; i < scan.points.size(); ++i) {
    EXPECT_LE(scan.points[i].norm(), 15.0f + 0.2f);
    EXPECT_NE(scan.semantic[i], semantic::kBuilding);
    if (scan.semantic[i] == semantic::kRoad) {
      noise += std::pow(scan.points[i].z() + 1.73, 2);  // range noise moves points along their rays
      ++road;
    }
  }
  ASSERT_GT(road, 1000);
  EXPECT_GT(std::sqrt(noise / road), 0.001);
  const RawScan exact = castScan(w, exactSensor(), sensorAt(1.73), 0.0, 0, 1);
  EXPECT_LT(scan.points.size(), 0.98 * exact.points.size());  // 4 % dropout plus the range limit
}

TEST(SimRaycast, SameArgumentsSameScan) {
  SimConfig config;
  config.frames = 30;
  config.seed = 12;
  config.sensor.columns = 512;
  const Simulator sim(config);
  const RawScan a = castScan(sim.world(), sim.sensor(), sim.poses()[20].T_world_lidar, sim.poses()[20].time, 20, 12);
  const RawScan b = castScan(sim.world(), sim.sensor(), sim.poses()[20].T_world_lidar, sim.poses()[20].time, 20, 12);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (size_t i = 0; i < a.points.size(); ++i) {
    ASSERT_EQ(a.points[i], b.points[i]);
    ASSERT_EQ(a.semantic[i], b.semantic[i]);
  }
}

TEST(SimRaycast, Mid70AccumulatesScansIntoTheLastFrame) {
  SimConfig config;
  config.frames = 12;
  config.seed = 2;
  config.sensor = SensorConfig::preset(SensorKind::kMid70);
  const Simulator sim(config);
  EXPECT_EQ(config.scansPerFrame(), 10);
  const SimFrame first = sim.frame(0), last = sim.frame(11);
  EXPECT_GT(first.points.size(), 5000u);
  EXPECT_GT(last.points.size(), 8 * first.points.size());
  EXPECT_EQ(last.labels.size(), last.points.size());
  // The merged frame starts with raw scan 2 moved into the LiDAR frame of frame 11.
  const RawScan raw = castScan(sim.world(), sim.sensor(), sim.poses()[2].T_world_lidar, sim.poses()[2].time, 2, 2);
  const Eigen::Matrix4d T = sim.poses()[11].T_world_lidar.inverse() * sim.poses()[2].T_world_lidar;
  for (size_t k = 0; k < raw.points.size(); k += 97) {
    const Eigen::Vector3d want = T.topLeftCorner<3, 3>() * raw.points[k].cast<double>() + T.topRightCorner<3, 1>();
    ASSERT_LT((last.points[k].cast<double>() - want).norm(), 1e-3) << k;
  }
}

}  // namespace
}  // namespace sgtllc::sim
