// The frame of a KITTI-format trajectory from its motion (trajectory_frame.h): KISS-ICP's cam0 odometry and
// SemanticKITTI's poses of KITTI 00 are cam0, the same converted through the calib are LiDAR, the simulator's
// odometry.txt (KITTI convention) is cam0; standing or short trajectories are undecided; and the rule's messages.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/io/trajectory_frame.h"
#include "sgtllc/sim/sequence_writer.h"
#include "sgtllc/sim/simulator.h"
#include "sgtllc/types.h"
#include "test_io_support.h"
#include "test_support.h"

namespace sgtllc::io {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using Verdict = FrameEvidence::Verdict;

const std::string kOdometry = test::dataPath("kitti/00/odometry/");
const std::string kCalib = test::dataPath("kitti/00/calib.txt");

std::vector<Eigen::Matrix4d> matrices(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Matrix4d> out;
  for (const Eigen::Isometry3d& T : poses) out.push_back(T.matrix());
  return out;
}

/// @p n poses @p step_m apart along the LiDAR's x axis (no rotation).
std::vector<Eigen::Matrix4d> straightLine(size_t n, double step_m) {
  std::vector<Eigen::Matrix4d> poses(n, Eigen::Matrix4d::Identity());
  for (size_t i = 0; i < n; ++i) poses[i](0, 3) = step_m * static_cast<double>(i);
  return poses;
}

class TrajectoryFrame : public test::TempDirTest {};

TEST_F(TrajectoryFrame, KissIcpKittiOdometryIsCam0AndThroughTheCalibLidar) {
  const std::vector<Eigen::Matrix4d> cam = readKittiPoses(kOdometry + "kissicp_first1000_kitti.txt");
  const FrameEvidence e = detectPoseFrame(cam);
  EXPECT_EQ(e.verdict, Verdict::kCam0) << e.reason;
  EXPECT_EQ(e.forward_axis, 2);
  EXPECT_EQ(e.up_axis, 1);
  EXPECT_GT(e.forward_share.z(), 0.9);
  EXPECT_GT(e.path_m, 500.0);  // the first 1000 frames of KITTI 00: ~10 m/s for 100 s, with stops
  EXPECT_GT(e.turn_deg, 180.0);

  // The same poses brought into the LiDAR frame, written out as a KITTI file and read back raw.
  const std::string lidar_file = path("lidar_kitti.txt");
  writeKittiPoses(lidar_file, lidarPoses(cam, readKittiCalibTr(kCalib)));
  const FrameEvidence l = detectPoseFrame(readKittiPoses(lidar_file));
  EXPECT_EQ(l.verdict, Verdict::kLidar) << l.reason;
  EXPECT_EQ(l.forward_axis, 0);
  EXPECT_EQ(l.up_axis, 2);
  EXPECT_GT(l.forward_share.x(), 0.9);
  EXPECT_NEAR(l.path_m, e.path_m, 1.0);  // a rigid change of axes keeps the path length
}

TEST_F(TrajectoryFrame, SemanticKittiPosesAreCam0AndKissIcpTumIsLidar) {
  EXPECT_EQ(detectPoseFrame(readKittiPoses(kOdometry + "semantickitti_poses_first1000.txt")).verdict, Verdict::kCam0);
  // The TUM file is the same estimate in the LiDAR frame (data/README.md): its motion says so too.
  const Trajectory tum = readTrajectory(kOdometry + "kissicp_first1000_tum.txt");
  EXPECT_EQ(detectPoseFrame(matrices(tum.poses)).verdict, Verdict::kLidar);
}

TEST_F(TrajectoryFrame, SimulatorOdometryIsWrittenInCam0) {
  sim::SimConfig c;
  c.frames = 80;
  c.seed = 5;
  c.sensor.rows = 8;
  c.sensor.columns = 64;
  const sim::Simulator simulator(c);
  sim::WriteOptions o;
  o.dir = path("sim");
  o.previews = false;
  o.node_stats_every = 0;
  sim::writeSequence(simulator, o);
  // odometry.txt follows poses.txt's KITTI convention (cam0, Tr in calib.txt).
  const FrameEvidence cam = detectPoseFrame(readKittiPoses(o.dir + "/odometry.txt"));
  EXPECT_EQ(cam.verdict, Verdict::kCam0) << cam.reason << "; " << evidenceText(cam);
  const FramedTrajectory read = readTrajectory(o.dir + "/odometry.txt", o.dir + "/calib.txt", PoseFrame::kAuto);
  EXPECT_TRUE(read.trajectory.calib_Tr);
  EXPECT_EQ(detectPoseFrame(matrices(read.trajectory.poses)).verdict, Verdict::kLidar);
  EXPECT_EQ(read.choice.note, "");  // a calib and cam0 motion agree: nothing to say
}

TEST_F(TrajectoryFrame, StandingOrShortTrajectoriesAreUndecided) {
  const FrameEvidence standing = detectPoseFrame(std::vector<Eigen::Matrix4d>(50, Eigen::Matrix4d::Identity()));
  EXPECT_EQ(standing.verdict, Verdict::kUndecided);
  EXPECT_EQ(standing.forward_axis, -1);
  EXPECT_THAT(standing.reason, HasSubstr("only 0 m of motion"));
  const FrameEvidence short_drive = detectPoseFrame(straightLine(10, 0.4));  // 3.6 m
  EXPECT_EQ(short_drive.verdict, Verdict::kUndecided);
  EXPECT_THAT(short_drive.reason, HasSubstr("only 4 m of motion, at least 5 needed"));
  EXPECT_EQ(detectPoseFrame(straightLine(10, 1.0)).verdict, Verdict::kLidar);  // 9 m straight along x
  EXPECT_EQ(detectPoseFrame({}).verdict, Verdict::kUndecided);
}

TEST_F(TrajectoryFrame, NoClearForwardAxisOrADisagreeingUpAxisIsUndecided) {
  // Diagonal motion in x–y: 50 % each.
  std::vector<Eigen::Matrix4d> diagonal = straightLine(20, 1.0);
  for (size_t i = 0; i < diagonal.size(); ++i) diagonal[i](1, 3) = diagonal[i](0, 3);
  const FrameEvidence d = detectPoseFrame(diagonal);
  EXPECT_EQ(d.verdict, Verdict::kUndecided);
  EXPECT_THAT(d.reason, HasSubstr("no axis carries 80 % of the motion: x 50 %, y 50 %, z 0 %"));
  // Forward x but turning about y (a LiDAR would turn about z): 20 steps of 1 m and 5°.
  std::vector<Eigen::Matrix4d> pitching(1, Eigen::Matrix4d::Identity());
  for (int i = 1; i < 20; ++i) {
    pitching.push_back(pitching.back() * test::rigid(0.0, 5.0, 0.0, Eigen::Vector3d(1.0, 0.0, 0.0)));
  }
  const FrameEvidence p = detectPoseFrame(pitching);
  EXPECT_EQ(p.verdict, Verdict::kUndecided);
  EXPECT_THAT(p.reason, HasSubstr("motion along x but turning about y, where LiDAR poses turn about z"));
}

TEST_F(TrajectoryFrame, TheRuleWithoutACalib) {
  const std::string cam0 = kOdometry + "kissicp_first1000_kitti.txt";
  const std::string message = test::errorOf([&] { readTrajectory(cam0, "", PoseFrame::kAuto); });
  EXPECT_THAT(message, AllOf(HasSubstr(cam0 + ": these KITTI poses move along their z axis, as KITTI's cam0 poses do"),
                             HasSubstr("give --calib CALIB.txt (its Tr brings them into the LiDAR frame), or "
                                       "--pose-frame lidar if they are LiDAR poses")));
  EXPECT_THAT(test::errorOf([&] { readTrajectory(cam0, "", PoseFrame::kCam0); }),
              HasSubstr(cam0 + ": --pose-frame cam0 needs --calib CALIB.txt"));
  // Explicitly LiDAR: taken as written, whatever the motion says.
  const FramedTrajectory as_lidar = readTrajectory(cam0, "", PoseFrame::kLidar);
  EXPECT_EQ(as_lidar.choice.note, "");
  EXPECT_FALSE(as_lidar.trajectory.calib_Tr);
  EXPECT_EQ(as_lidar.trajectory.poses[500].matrix(), readKittiPoses(cam0)[500]);

  const std::string lidar = path("lidar.txt");
  writeKittiPoses(lidar, lidarPoses(readKittiPoses(cam0), readKittiCalibTr(kCalib)));
  const FramedTrajectory auto_lidar = readTrajectory(lidar, "", PoseFrame::kAuto);
  EXPECT_FALSE(auto_lidar.choice.warning);
  EXPECT_THAT(auto_lidar.choice.note,
              AllOf(HasSubstr(lidar + ": KITTI poses read in the LiDAR frame (motion along x ("),
                    HasSubstr(", turning about z ("),
                    HasSubstr("); --pose-frame lidar to say so, --calib for cam0 poses")));

  const std::string standing = write("standing.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT(test::errorOf([&] { readTrajectory(standing, "", PoseFrame::kAuto); }),
              HasSubstr(standing + ": cannot tell the frame of these KITTI poses from their motion (only 0 m of "
                                   "motion, at least 5 needed); give --pose-frame lidar for LiDAR poses"));
}

TEST_F(TrajectoryFrame, TheRuleWithACalib) {
  const std::string cam0 = kOdometry + "kissicp_first1000_kitti.txt";
  const FramedTrajectory converted = readTrajectory(cam0, kCalib, PoseFrame::kAuto);
  ASSERT_TRUE(converted.trajectory.calib_Tr);
  EXPECT_EQ(converted.choice.note, "");
  // The same poses as the two-argument reader gives.
  EXPECT_EQ(converted.trajectory.poses[999].matrix(), readTrajectory(cam0, kCalib).poses[999].matrix());

  // A LiDAR-frame file with a calib: the calib is applied (the user said cam0), with a warning; explicit cam0 or
  // lidar have nothing to warn about.
  const std::string lidar = path("lidar.txt");
  writeKittiPoses(lidar, lidarPoses(readKittiPoses(cam0), readKittiCalibTr(kCalib)));
  const FramedTrajectory doubted = readTrajectory(lidar, kCalib, PoseFrame::kAuto);
  EXPECT_TRUE(doubted.trajectory.calib_Tr);
  EXPECT_TRUE(doubted.choice.warning);
  EXPECT_THAT(doubted.choice.note,
              AllOf(HasSubstr(lidar + ": these KITTI poses move as LiDAR poses do (motion along x ("),
                    HasSubstr("), yet the calib's Tr converts them as cam0 poses; --pose-frame lidar if they are "
                              "LiDAR poses, --pose-frame cam0 to say they are cam0")));
  const FramedTrajectory forced = readTrajectory(lidar, kCalib, PoseFrame::kCam0);
  EXPECT_TRUE(forced.trajectory.calib_Tr);
  EXPECT_EQ(forced.choice.note, "");
  const FramedTrajectory as_lidar = readTrajectory(lidar, kCalib, PoseFrame::kLidar);
  EXPECT_FALSE(as_lidar.trajectory.calib_Tr);
  EXPECT_EQ(as_lidar.choice.note, "");
  // A broken calib is an error even where it would not be applied by auto's verdict; lidar does not read it.
  const std::string no_tr = write("no_tr.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT(test::errorOf([&] { readTrajectory(lidar, no_tr, PoseFrame::kAuto); }), HasSubstr("no 'Tr:' line"));
  EXPECT_EQ(readTrajectory(lidar, no_tr, PoseFrame::kLidar).trajectory.poses.size(), 1000u);
  // Too short to tell: the calib decides (cam0).
  const std::string standing = write("standing.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_TRUE(readTrajectory(standing, kCalib, PoseFrame::kAuto).trajectory.calib_Tr);
}

TEST_F(TrajectoryFrame, TumFilesAreLidarPoses) {
  const std::string tum = kOdometry + "kissicp_first1000_tum.txt";
  const FramedTrajectory t = readTrajectory(tum, kCalib, PoseFrame::kAuto);
  EXPECT_EQ(t.trajectory.format, TrajectoryFormat::kTum);
  EXPECT_FALSE(t.trajectory.calib_Tr);
  EXPECT_EQ(t.choice.note, "");
  EXPECT_THAT(test::errorOf([&] { readTrajectory(tum, kCalib, PoseFrame::kCam0); }),
              HasSubstr(tum + ": a TUM file, read in the LiDAR frame as given; --pose-frame cam0 is for KITTI files"));
}

TEST(PoseFrameName, RoundTripsAndRefusesOthers) {
  for (PoseFrame f : {PoseFrame::kAuto, PoseFrame::kLidar, PoseFrame::kCam0}) {
    EXPECT_EQ(parsePoseFrame(poseFrameName(f)), f);
  }
  EXPECT_THAT(test::errorOf([] { parsePoseFrame("velodyne"); }),
              HasSubstr("pose frame 'velodyne' is not one of auto, lidar, cam0"));
}

}  // namespace
}  // namespace sgtllc::io
