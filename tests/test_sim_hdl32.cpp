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
#include "sgtllc/labels.h"
#include "sgtllc/sim/label_space.h"
#include "sgtllc/sim/manifest.h"
#include "sgtllc/sim/world.h"
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

TEST(SimHdl32, NuScenesIdsOfTheSimulatorsClasses) {
  using namespace semantic;  // the simulator's SemanticKITTI ids; sgtllc::kBuilding etc. are class indices
  const std::pair<uint32_t, int> table[] = {
      {kBuilding, 28}, {kOtherStructure, 28}, {kPole, 28}, {kTrafficSign, 28}, {kVegetation, 30}, {kTrunk, 30},
      {kTerrain, 27},  {kFence, 9},           {kRoad, 24}, {kParking, 24},     {kSidewalk, 26},   {kOtherGround, 25},
      {kCar, 17},      {kTruck, 23},          {kOtherVehicle, 16}, {kPerson, 2}, {kOtherObject, 29},
      {kMovingCar, 32}, {kMovingPerson, 39},  {kUnlabeled, 0}, {12345, 0}};
  for (const auto& [id, want] : table) {
    EXPECT_EQ(nuScenesId(id), want) << id;
    EXPECT_EQ(nuScenesId((77u << 16) | id), want) << id;  // instance bits ignored
  }
  // Through the nuscenes preset, the simulator's building/pole/sign become building, trunk vegetation.
  LabelConfig nuscenes;
  nuscenes.preset = LabelPreset::kNuScenes;
  const LabelMap map(nuscenes);
  EXPECT_EQ(map.classOf(nuScenesId(kPole)), sgtllc::kBuilding);
  EXPECT_EQ(map.classOf(nuScenesId(kTrunk)), sgtllc::kVegetation);
  EXPECT_EQ(map.classOf(nuScenesId(kFence)), sgtllc::kFence);
  EXPECT_EQ(map.classOf(nuScenesId(kTerrain)), sgtllc::kTerrain);
  EXPECT_EQ(map.classOf(nuScenesId(kCar)), sgtllc::kDropped);
  EXPECT_EQ(parseLabelSpace("nuscenes"), LabelSpace::kNuScenes);
  EXPECT_THROW(parseLabelSpace("kitti"), Error);
}

TEST(SimHdl32, LabelSpaceNuScenesWritesOneByteAPointOfTheSameScans) {
  const fs::path dir = fs::temp_directory_path() / ("sgtllc_sim_hdl32_ns_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string common = " --frames 2 --seed 5 --sensor hdl32 --threads 2 --no-preview > /dev/null 2>&1";
  const std::string cli = std::string(SGTLLC_CLI) + " simulate --out ";
  ASSERT_EQ(std::system((cli + (dir / "kitti").string() + common).c_str()), 0);
  ASSERT_EQ(std::system((cli + (dir / "nus").string() + " --label-space nuscenes" + common).c_str()), 0);
  const io::SequenceDir kitti((dir / "kitti").string()), nus((dir / "nus").string());
  ASSERT_EQ(nus.size(), 2u);
  for (size_t i = 0; i < nus.size(); ++i) {
    const LabeledCloud a = kitti.load(i), b = nus.load(i);
    ASSERT_EQ(fs::file_size(nus.labelPath(i)), b.points.size());  // one byte a point
    ASSERT_EQ(a.points, b.points);
    ASSERT_EQ(b.labels.size(), a.labels.size());
    for (size_t k = 0; k < a.labels.size(); ++k) ASSERT_EQ(b.labels[k], nuScenesId(a.labels[k])) << k;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sgtllc::sim
