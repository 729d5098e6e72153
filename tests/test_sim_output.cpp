// A simulated sequence on disk: readable by the project's own readers, poses/calib/loop pairs consistent with each
// other, byte-identical at 1 and 2 threads, and an output folder that is never clobbered by accident.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include <Eigen/LU>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/sim/odometry.h"
#include "sgtllc/sim/sequence_writer.h"

namespace sgtllc::sim {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A small, fast sequence with a revisit: low-resolution sensor, 600 frames.
SimConfig smallConfig() {
  SimConfig c;
  c.frames = 600;
  c.seed = 31;
  c.sensor.rows = 16;
  c.sensor.columns = 256;
  return c;
}

class SimOutput : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: ctest -j runs the tests of this suite side by side.
    root_ = fs::temp_directory_path() / ("sgtllc_sim_output_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    sim_ = new Simulator(smallConfig());
    WriteOptions o;
    o.dir = (root_ / "t1").string();
    o.threads = 1;
    stats_ = writeSequence(*sim_, o);
  }
  static void TearDownTestSuite() {
    delete sim_;
    sim_ = nullptr;
    fs::remove_all(root_);
  }
  static std::string dir() { return (root_ / "t1").string(); }

  static fs::path root_;
  static Simulator* sim_;
  static SequenceStats stats_;
};

fs::path SimOutput::root_;
Simulator* SimOutput::sim_ = nullptr;
SequenceStats SimOutput::stats_;

TEST_F(SimOutput, TheProjectsReadersReadEveryFrame) {
  const io::SequenceDir seq(dir());
  ASSERT_EQ(seq.size(), 600u);
  EXPECT_EQ(seq.frameName(0), "000000");
  EXPECT_EQ(seq.frameName(599), "000599");
  for (size_t i = 0; i < seq.size(); i += 37) {
    const LabeledCloud c = io::readLabeledScan(seq.binPath(i), seq.labelPath(i));
    EXPECT_EQ(c.points.size(), stats_.points[i]);
    EXPECT_GT(c.points.size(), 1000u);
    std::vector<float> intensity;
    io::readKittiBin(seq.binPath(i), &intensity);
    for (float v : intensity) ASSERT_TRUE(v >= 0.0f && v <= 0.99f);
  }
  for (const char* name : {"poses.txt", "calib.txt", "times.txt", "loop_pairs.txt", "odometry.txt",
                           "preview_scan.png", "preview_trajectory.png"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::path(dir()) / name)) << name;
  }
}

TEST_F(SimOutput, PosesCalibAndTimesAgree) {
  const Eigen::Matrix4d Tr = io::readKittiCalibTr(dir() + "/calib.txt");
  EXPECT_TRUE(Tr.isApprox(io::kittiVelodyneToCam0(), 1e-12));
  const std::vector<Eigen::Matrix4d> cam = io::readKittiPoses(dir() + "/poses.txt");
  ASSERT_EQ(cam.size(), 600u);
  EXPECT_TRUE(cam[0].isApprox(Eigen::Matrix4d::Identity(), 1e-9));
  const std::vector<Eigen::Matrix4d> lidar = io::lidarPoses(cam, Tr);
  const Eigen::Matrix4d world_to_0 = sim_->poses()[0].T_world_lidar.inverse();
  for (size_t i = 0; i < lidar.size(); ++i) {
    // The written poses are the simulator's own, expressed in the LiDAR frame of frame 0.
    ASSERT_TRUE(lidar[i].isApprox(world_to_0 * sim_->poses()[i].T_world_lidar, 1e-9)) << i;
  }
  std::ifstream times(dir() + "/times.txt");
  double t;
  int n = 0;
  while (times >> t) {
    EXPECT_NEAR(t, 0.1 * n, 1e-6);
    ++n;
  }
  EXPECT_EQ(n, 600);
}

TEST_F(SimOutput, OdometryIsTheModelsDriftFromTheWrittenPoses) {
  const Eigen::Matrix4d Tr = io::readKittiCalibTr(dir() + "/calib.txt");
  const std::vector<Eigen::Matrix4d> truth = io::lidarPoses(io::readKittiPoses(dir() + "/poses.txt"), Tr);
  const std::vector<Eigen::Matrix4d> odometry = io::lidarPoses(io::readKittiPoses(dir() + "/odometry.txt"), Tr);
  ASSERT_EQ(odometry.size(), 600u);
  const std::string odometry_text = slurp(dir() + "/odometry.txt"), poses_text = slurp(dir() + "/poses.txt");
  EXPECT_EQ(odometry_text.substr(0, odometry_text.find('\n')), poses_text.substr(0, poses_text.find('\n')));
  const std::vector<Eigen::Matrix4d> model = driftingOdometry(truth, OdometryNoise{}, smallConfig().seed);
  double length = 0.0;
  for (size_t i = 0; i < odometry.size(); ++i) {
    ASSERT_TRUE(odometry[i].isApprox(model[i], 1e-6)) << i;
    if (i > 0) length += (truth[i].topRightCorner<3, 1>() - truth[i - 1].topRightCorner<3, 1>()).norm();
  }
  const double end_error = (odometry.back().topRightCorner<3, 1>() - truth.back().topRightCorner<3, 1>()).norm();
  EXPECT_NEAR(stats_.path_length, length, 1e-6);
  EXPECT_NEAR(stats_.odometry_end_error, end_error, 1e-6);
  EXPECT_GT(end_error, 0.01);  // it drifts, and by no more than 10 % of the path
  EXPECT_LT(end_error, 0.1 * length);
}

TEST_F(SimOutput, LoopPairsAgreeWithTheWrittenPoses) {
  const std::vector<Eigen::Matrix4d> lidar =
      io::lidarPoses(io::readKittiPoses(dir() + "/poses.txt"), io::readKittiCalibTr(dir() + "/calib.txt"));
  std::ifstream in(dir() + "/loop_pairs.txt");
  std::string line;
  std::set<std::pair<int, int>> positives;
  int negatives = 0;
  while (std::getline(in, line)) {
    std::istringstream tokens(line);
    std::string q, c;
    int label = -1;
    ASSERT_TRUE(tokens >> q >> c >> label) << line;
    ASSERT_EQ(q.size(), 6u);
    ASSERT_EQ(c.size(), 6u);
    const int query = std::stoi(q), candidate = std::stoi(c);
    ASSERT_GE(query - candidate, 50);
    const double d = (lidar[query].topRightCorner<3, 1>() - lidar[candidate].topRightCorner<3, 1>()).norm();
    if (label == 1) {
      EXPECT_LE(d, 3.0);
      positives.insert({query, candidate});
    } else {
      ASSERT_EQ(label, 0);
      EXPECT_GT(d, 20.0);
      ++negatives;
    }
  }
  // Every frame pair within 3 m (and 50 frames apart) is listed.
  size_t expected = 0;
  for (int q = 0; q < 600; ++q) {
    for (int c = 0; c + 50 <= q; ++c) {
      if ((lidar[q].topRightCorner<3, 1>() - lidar[c].topRightCorner<3, 1>()).norm() <= 3.0) {
        ++expected;
        EXPECT_TRUE(positives.count({q, c})) << q << " " << c;
      }
    }
  }
  EXPECT_EQ(positives.size(), expected);
  EXPECT_GT(positives.size(), 20u) << "the small sequence should contain a revisit";
  EXPECT_EQ(stats_.positives, positives.size());
  EXPECT_EQ(stats_.negatives, static_cast<size_t>(negatives));
}

TEST_F(SimOutput, SameBytesAtAnyThreadCount) {
  WriteOptions o;
  o.dir = (root_ / "t2").string();
  o.threads = 2;
  writeSequence(Simulator(smallConfig()), o);
  size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir())) {
    if (!entry.is_regular_file()) continue;
    const fs::path other = fs::path(o.dir) / fs::relative(entry.path(), dir());
    ASSERT_TRUE(fs::exists(other)) << other;
    ASSERT_EQ(slurp(entry.path()), slurp(other)) << fs::relative(entry.path(), dir());
    ++files;
  }
  // .bin and .label per frame; calib, poses, odometry, times, loop pairs, simulation.txt and two previews.
  EXPECT_EQ(files, 2u * 600u + 8u);
}

TEST(SimWriter, AccumulatedFramesEqualFrameByFrame) {
  // The writer casts each raw scan once and merges it into every frame that accumulates it, across batch
  // boundaries (1 thread: batches of 4 frames, 6 scans per frame); every file must equal Simulator::frame(i).
  SimConfig c = smallConfig();
  c.frames = 15;
  c.accumulate = 6;
  const Simulator sim(c);
  const fs::path dir = fs::temp_directory_path() / ("sgtllc_sim_accumulate_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  WriteOptions o;
  o.dir = dir.string();
  o.threads = 1;
  o.previews = false;
  writeSequence(sim, o);
  const io::SequenceDir seq(o.dir);
  ASSERT_EQ(seq.size(), 15u);
  for (int i = 0; i < 15; ++i) {
    const SimFrame f = sim.frame(i);
    const LabeledCloud got = seq.load(static_cast<size_t>(i));
    ASSERT_EQ(got.points, f.points) << "frame " << i;
    ASSERT_EQ(got.labels, f.labels) << "frame " << i;
  }
  EXPECT_GT(sim.frame(14).points.size(), 5 * sim.frame(0).points.size());  // 6 scans against 1
  fs::remove_all(dir);
}

TEST_F(SimOutput, NeverOverwritesUnlessForced) {
  const fs::path target = root_ / "user";
  fs::create_directories(target);
  std::ofstream(target / "notes.txt") << "mine";
  EXPECT_THROW(prepareOutputDir(target.string(), false), Error);
  try {
    prepareOutputDir(target.string(), false);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not empty"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(prepareOutputDir(target.string(), true));
  EXPECT_EQ(slurp(target / "notes.txt"), "mine");
  EXPECT_TRUE(fs::is_directory(target / "velodyne"));
  EXPECT_THROW(prepareOutputDir((target / "notes.txt").string(), true), Error);  // a file, not a folder
  EXPECT_NO_THROW(prepareOutputDir((root_ / "fresh" / "deeper").string(), false));
}

TEST(SimConfigCheck, BadValuesAreNamed) {
  SimConfig c;
  c.frames = 0;
  EXPECT_THROW(c.validate(), Error);
  c.frames = 10;
  c.label_noise = 1.5;
  try {
    c.validate();
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("label noise"), std::string::npos);
  }
  EXPECT_THROW(parseSceneKind("downtown"), Error);
  EXPECT_THROW(parseSensorKind("vlp16"), Error);
}

}  // namespace
}  // namespace sgtllc::sim
