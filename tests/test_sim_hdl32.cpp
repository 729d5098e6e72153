// The simulated Velodyne HDL-32E (nuScenes' LIDAR_TOP): its ray pattern analytically, and a short simulated
// sequence's points per scan against the rays of a turn.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "sgtllc/io/sequence.h"
#include "sgtllc/sim/manifest.h"
#include "sgtllc/sim/sensor.h"

namespace sgtllc::sim {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = M_PI / 180.0;

double elevationDeg(const Eigen::Vector3f& d) { return std::asin(std::clamp(double(d.z()), -1.0, 1.0)) / kDeg; }

TEST(SimHdl32, ThirtyTwoEvenBeamsFromPlusTenToMinusThirty) {
  const SensorModel s(SensorConfig::preset(SensorKind::kHdl32));
  ASSERT_EQ(s.rows(), 32);
  ASSERT_EQ(s.columns(), 1085);
  ASSERT_EQ(s.raysPerScan(), 34720);  // 32 × 1,085: the size of a nuScenes LIDAR_TOP scan
  EXPECT_TRUE(s.wraps());
  EXPECT_EQ(s.config().max_range, 70.0);
  ASSERT_EQ(s.elevations().size(), 32u);
  for (size_t r = 0; r < 32; ++r) EXPECT_NEAR(s.elevations()[r], 10.67 - r * 41.34 / 31.0, 1e-12) << r;
  EXPECT_NEAR(s.elevations().front(), 10.67, 1e-12);
  EXPECT_NEAR(s.elevations().back(), -30.67, 1e-12);

  std::vector<Eigen::Vector3f> d;
  s.directions(3, 11, d);
  ASSERT_EQ(d.size(), 34720u);
  double lo = 90, hi = -90;
  for (size_t i = 0; i < d.size(); ++i) {
    ASSERT_NEAR(d[i].norm(), 1.0f, 1e-5f);
    const double e = elevationDeg(d[i]);
    ASSERT_NEAR(e, s.elevations()[i % 32], 1e-4) << i;  // column-major: ray i is row i % 32
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  EXPECT_NEAR(hi - lo, 41.34, 1e-3);
  // Neighbouring columns of the horizon-nearest beam are 360° / 1,085 ≈ 0.332° apart in azimuth.
  const auto azimuth = [](const Eigen::Vector3f& v) { return std::atan2(double(v.y()), double(v.x())); };
  const double step = std::remainder(azimuth(d[32 + 8]) - azimuth(d[8]), 2 * M_PI) / kDeg;
  EXPECT_NEAR(step, 360.0 / 1085.0, 1e-4);
}

TEST(SimHdl32, FewerRowsAreEvenlyChosenAmongTheThirtyTwo) {
  SensorConfig c = SensorConfig::preset(SensorKind::kHdl32);
  c.rows = 4;
  const SensorModel s(c);
  ASSERT_EQ(s.elevations().size(), 4u);
  // Beams 0, 10, 21, 31 (round(r · 31 / 3)).
  EXPECT_NEAR(s.elevations()[1], 10.67 - 10 * 41.34 / 31.0, 1e-12);
  EXPECT_NEAR(s.elevations()[2], 10.67 - 21 * 41.34 / 31.0, 1e-12);
  EXPECT_NEAR(s.elevations()[3], -30.67, 1e-12);
  c.rows = 33;
  EXPECT_THROW(SensorModel{c}, Error);
  try {
    SensorModel{c};
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("sensor rows must be 1..32, not 33"));
  }
}

TEST(SimHdl32, NameParsesAndPrints) {
  EXPECT_EQ(parseSensorKind("hdl32"), SensorKind::kHdl32);
  EXPECT_STREQ(sensorName(SensorKind::kHdl32), "hdl32");
  EXPECT_STREQ(sensorName(SensorKind::kHdl64), "hdl64");
  EXPECT_STREQ(sensorName(SensorKind::kMid70), "mid70");
  EXPECT_THAT([] { parseSensorKind("hdl16"); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("expected hdl64, hdl32 or mid70")));
}

TEST(SimHdl32, ShortSequenceHasAboutThirtyThousandPointsAScan) {
  const fs::path dir = fs::temp_directory_path() / ("sgtllc_sim_hdl32_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string cmd = std::string(SGTLLC_CLI) + " simulate --out " + dir.string() +
                          " --frames 3 --seed 7 --sensor hdl32 --threads 2 --no-preview > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const io::SequenceDir seq(dir.string());
  ASSERT_EQ(seq.size(), 3u);
  for (size_t i = 0; i < seq.size(); ++i) {
    const LabeledCloud c = seq.load(i);
    // At most one return a ray (34,720); the sky above the upper beams and the 70 m range lose some. A real
    // nuScenes scan keeps all 34,720 rays, 24,854 of them real returns beyond the car in data/nuscenes/0001/000000.
    EXPECT_GT(c.points.size(), 25000u) << i;
    EXPECT_LE(c.points.size(), 34720u) << i;
    double far = 0;
    for (const auto& p : c.points) far = std::max(far, double(p.norm()));
    EXPECT_LT(far, 70.5) << i;  // 70 m and a few cm of range noise
  }
  EXPECT_EQ(readManifest(dir.string()).sensor.kind, SensorKind::kHdl32);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sgtllc::sim
