// Shared by the back-end command suites (test_cli_backend*.cpp): a temporary folder, file helpers, and a
// synthetic drive with a known answer (a circle driven one and a bit times, drifting odometry, exact loops on the second lap).
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "sgtllc/io/loops_csv.h"
#include "sgtllc/io/trajectory.h"
#include "test_cli_support.h"
#include "test_kitti_support.h"

namespace sgtllc::test {

class CliBackend : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("sgtllc_cli_backend_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
  }
  std::string read(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  std::filesystem::path dir_;
};

/// Frame i's name as `sgtllc optimize` expects by default.
inline std::string frameName(size_t i) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%06zu", i);
  return buf;
}

/// Frames per lap of circleDrive: 1 m steps around a circle of radius 60 m (377 m).
inline constexpr size_t kLap = 377;

/// 420 frames 1 m apart on a circle of radius 60 m (one lap and 43 frames), LiDAR frame, z up, heading along the
/// circle: every step turns by the same angle, so a uniform yaw bias is what the optimiser can undo exactly.
inline std::vector<Eigen::Isometry3d> circleDrive(size_t frames = 420) {
  std::vector<Eigen::Isometry3d> poses;
  const double radius = 60.0;
  for (size_t i = 0; i < frames; ++i) {
    const double a = static_cast<double>(i) / radius;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(a + M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), 0.0);
    poses.push_back(T);
  }
  return poses;
}

/// The drive's odometry: every step with a yaw bias of 0.005° (1.9° per lap, 0.5°/100 m: twice KISS-ICP on KITTI 00). Scale drift is left out: loops
/// cannot observe it.
inline std::vector<Eigen::Isometry3d> driftedOdometry(const std::vector<Eigen::Isometry3d>& truth) {
  std::vector<Eigen::Isometry3d> odometry = {truth[0]};
  for (size_t i = 1; i < truth.size(); ++i) {
    Eigen::Isometry3d step = truth[i - 1].inverse() * truth[i];
    step.linear() = step.linear() * Eigen::AngleAxisd(0.005 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    odometry.push_back(odometry.back() * step);
  }
  return odometry;
}

/// Exact loops of the second lap: every 4th frame from 380 to 416 revisits frame q − kLap (10 loops).
inline std::vector<io::LoopRecord> exactLoops(const std::vector<Eigen::Isometry3d>& truth) {
  std::vector<io::LoopRecord> loops;
  for (size_t q = 380; q < truth.size(); q += 4) {
    io::LoopRecord l;
    l.query = frameName(q);
    l.match = frameName(q - kLap);
    l.score = 0.8;
    l.score_c = 0.9;
    l.T_match_query = (truth[q - kLap].inverse() * truth[q]).matrix();
    loops.push_back(l);
  }
  return loops;
}

/// TUM text of @p poses with stamps 0.1 s apart.
inline std::string tumText(const std::vector<Eigen::Isometry3d>& poses) {
  io::Trajectory t;
  t.format = io::TrajectoryFormat::kTum;
  t.poses = poses;
  for (size_t i = 0; i < poses.size(); ++i) t.stamps.push_back(0.1 * static_cast<double>(i));
  return io::trajectoryText(t);
}

}  // namespace sgtllc::test
