// KITTI / TUM trajectory files: round trips, the cam0 ↔ LiDAR conversion, real KISS-ICP output, and bad input.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/types.h"
#include "test_io_support.h"
#include "test_support.h"
#include "test_trajectory_support.h"

namespace {

namespace fs = std::filesystem;
using sgtllc::Error;
using sgtllc::io::Trajectory;
using sgtllc::io::TrajectoryFormat;
using sgtllc::test::expectPosesNear;
using sgtllc::test::randomPoses;
using ::testing::AllOf;
using ::testing::HasSubstr;

class TrajectoryIo : public sgtllc::test::TempDirTest {
 protected:
  /// The message of the sgtllc::Error that reading @p text as a trajectory throws.
  std::string readError(const std::string& text, const std::string& calib = "") {
    const std::string file = write("traj.txt", text);
    return sgtllc::test::errorOf([&] { sgtllc::io::readTrajectory(file, calib); });
  }
  std::string calib() const {
    const std::string p = path("calib.txt");
    sgtllc::io::writeKittiCalib(p, sgtllc::io::kittiProjections(), sgtllc::io::kittiVelodyneToCam0());
    return p;
  }
  static std::string slurp(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

const std::string kIdentityKitti = "1 0 0 0 0 1 0 0 0 0 1 0\n";
const std::string kIdentityTum = "0 0 0 0 0 0 0 1\n";

TEST_F(TrajectoryIo, KittiRoundTripIsExact) {
  Trajectory t;
  t.poses = randomPoses(25, 7);
  sgtllc::io::writeTrajectory(path("out.txt"), t);
  const Trajectory back = sgtllc::io::readTrajectory(path("out.txt"));
  EXPECT_EQ(back.format, TrajectoryFormat::kKitti);
  EXPECT_FALSE(back.calib_Tr.has_value());
  EXPECT_TRUE(back.stamps.empty());
  expectPosesNear(back.poses, t.poses, 0.0);  // shortest round-trip numbers
}

TEST_F(TrajectoryIo, TumRoundTripKeepsStampsAndPoses) {
  Trajectory t;
  t.format = TrajectoryFormat::kTum;
  t.poses = randomPoses(25, 8);
  for (size_t i = 0; i < t.poses.size(); ++i) t.stamps.push_back(0.1 * static_cast<double>(i) + 1e9);
  sgtllc::io::writeTrajectory(path("out.txt"), t);
  const Trajectory back = sgtllc::io::readTrajectory(path("out.txt"));
  EXPECT_EQ(back.format, TrajectoryFormat::kTum);
  EXPECT_EQ(back.stamps, t.stamps);
  expectPosesNear(back.poses, t.poses, 1e-9);
}

TEST_F(TrajectoryIo, CalibConvertsCam0ToLidarAndTheWriterBack) {
  const std::vector<Eigen::Isometry3d> cam = randomPoses(10, 9);
  std::vector<Eigen::Matrix4d> cam_m;
  for (const auto& T : cam) cam_m.push_back(T.matrix());
  sgtllc::io::writeKittiPoses(path("cam.txt"), cam_m);

  const Trajectory lidar = sgtllc::io::readTrajectory(path("cam.txt"), calib());
  ASSERT_TRUE(lidar.calib_Tr.has_value());
  const Eigen::Matrix4d Tr = sgtllc::io::kittiVelodyneToCam0();
  EXPECT_EQ(*lidar.calib_Tr, Tr);
  for (size_t i = 0; i < cam.size(); ++i) {
    const Eigen::Matrix4d expected = Tr.inverse() * cam_m[i] * Tr;  // data/README.md: T_lidar = Tr⁻¹ · P · Tr
    EXPECT_LE((lidar.poses[i].matrix() - expected).cwiseAbs().maxCoeff(), 1e-12) << i;
  }
  // Written back in the input's frame: cam0 again, readable without the calib.
  sgtllc::io::writeTrajectory(path("back.txt"), lidar);
  const Trajectory back = sgtllc::io::readTrajectory(path("back.txt"));
  expectPosesNear(back.poses, cam, 1e-9);
}

TEST_F(TrajectoryIo, TumQuaternionIsNormalisedAndCommentsSkipped) {
  // Written to 7 digits, off unit length by up to 1e-3 (the tolerance): normalised.
  const std::string file =
      write("t.txt", "# timestamp tx ty tz qx qy qz qw\n5 1 2 3 0 0 0.7071068 0.7071068\n6 1 2 3 0 0 0 -1.0009\n");
  const Trajectory t = sgtllc::io::readTrajectory(file);
  ASSERT_EQ(t.poses.size(), 2u);
  EXPECT_EQ(t.stamps, (std::vector<double>{5, 6}));
  const Eigen::Matrix3d yaw90 = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LE((t.poses[0].linear() - yaw90).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(t.poses[0].translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_LE((t.poses[1].linear() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST_F(TrajectoryIo, CalibIsIgnoredForTum) {
  const Trajectory t = sgtllc::io::readTrajectory(write("t.txt", "0 1 2 3 0 0 0 1\n"), calib());
  EXPECT_FALSE(t.calib_Tr.has_value());
  EXPECT_EQ(t.poses[0].translation(), Eigen::Vector3d(1, 2, 3));
}

// KISS-ICP's estimate of KITTI 00 in both of its files (data/README.md): the KITTI one (cam0) through the calib and
// the TUM one (LiDAR frame) are the same trajectory, up to the 5e-9 of the KITTI file's printed precision.
TEST_F(TrajectoryIo, RealKissIcpKittiThroughCalibEqualsItsTumFile) {
  const std::string dir = sgtllc::test::dataPath("kitti/00/");
  const Trajectory kitti = sgtllc::io::readTrajectory(dir + "odometry/kissicp_first1000_kitti.txt", dir + "calib.txt");
  const Trajectory tum = sgtllc::io::readTrajectory(dir + "odometry/kissicp_first1000_tum.txt");
  ASSERT_EQ(kitti.poses.size(), 1000u);
  EXPECT_EQ(tum.format, TrajectoryFormat::kTum);
  EXPECT_NEAR(tum.stamps[1], 0.103736, 1e-12);  // line 2 of the file
  expectPosesNear(kitti.poses, tum.poses, 1e-7);
  // SemanticKITTI's poses are written with 6 significant digits: accepted as rotations.
  const Trajectory gt = sgtllc::io::readTrajectory(dir + "odometry/semantickitti_poses_first1000.txt");
  EXPECT_EQ(gt.poses.size(), 1000u);
  EXPECT_NEAR(gt.poses[1].translation().z(), 0.672716, 1e-12);
}

TEST_F(TrajectoryIo, PoseCountMustEqualFrames) {
  Trajectory t;
  t.poses = randomPoses(3, 1);
  EXPECT_NO_THROW(sgtllc::io::checkPoseCount("odo.txt", t, 3));
  for (size_t frames : {2u, 4u}) {
    EXPECT_THAT(sgtllc::test::errorOf([&] { sgtllc::io::checkPoseCount("odo.txt", t, frames); }),
                HasSubstr("odo.txt: 3 poses but the sequence has " + std::to_string(frames)));
  }
}

TEST_F(TrajectoryIo, MixedColumnCountsNameTheLine) {
  EXPECT_THAT(readError(kIdentityKitti + kIdentityKitti + kIdentityTum),
              AllOf(HasSubstr("traj.txt:3: 8 columns, but line 1 has 12"), HasSubstr("one format per file")));
  EXPECT_THAT(readError(kIdentityTum + "1 0 0 0 0 0 0 1 9\n"), HasSubstr("traj.txt:2: 9 columns; expected 12"));
}

TEST_F(TrajectoryIo, NonFiniteNumbersNameLineAndToken) {
  EXPECT_THAT(readError(kIdentityKitti + "1 0 0 nan 0 1 0 0 0 0 1 0\n"),
              AllOf(HasSubstr("traj.txt:2"), HasSubstr("'nan' is not a finite number")));
  EXPECT_THAT(readError(kIdentityTum + "1 0 inf 0 0 0 0 1\n"),
              AllOf(HasSubstr("traj.txt:2"), HasSubstr("'inf' is not a finite number")));
  EXPECT_THAT(readError("0 0 0 0 0 0 0 x\n"), HasSubstr("traj.txt:1: 'x' is not a finite number"));
}

TEST_F(TrajectoryIo, BadRotationsAreRejected) {
  EXPECT_THAT(readError(kIdentityTum + "1 0 0 0 0 0 0 0\n"),
              AllOf(HasSubstr("traj.txt:2: quaternion"), HasSubstr("has norm 0, not 1")));
  // Not a unit quaternion: refused rather than normalised (a scale or a wrong column would hide behind it).
  EXPECT_THAT(readError(kIdentityTum + "1 0 0 0 2 0 0 0\n"),
              HasSubstr("traj.txt:2: quaternion (2, 0, 0, 0) has norm 2, not 1"));
  EXPECT_THAT(readError(kIdentityTum + "1 0 0 0 0 0 0 1.0011\n"), HasSubstr("has norm 1.0011, not 1"));
  EXPECT_THAT(readError(kIdentityKitti + "2 0 0 0 0 1 0 0 0 0 1 0\n"),
              AllOf(HasSubstr("traj.txt:2: rotation is not orthonormal"), HasSubstr("= 3")));
  EXPECT_THAT(readError("-1 0 0 0 0 1 0 0 0 0 1 0\n"), HasSubstr("traj.txt:1: rotation has determinant -1"));
}

TEST_F(TrajectoryIo, LayoutErrors) {
  EXPECT_THAT(readError(""), HasSubstr("traj.txt: no poses"));
  EXPECT_THAT(readError(kIdentityKitti + "\n" + kIdentityKitti), HasSubstr("traj.txt:3: pose after blank line 2"));
  EXPECT_THAT(readError("# a comment\n" + kIdentityKitti), HasSubstr("comment lines in a KITTI pose file"));
  EXPECT_THAT(readError("2 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n"), HasSubstr("traj.txt:2: time stamp '1' is before"));
  // A token echoed in a message never reaches the terminal raw (io/quote.h).
  EXPECT_THAT(readError("0 0 0 0 0 0 0 1\n\x1b[2J 0 0 0 0 0 0 1\n"),
              HasSubstr("traj.txt:2: '\\x1b[2J' is not a finite number"));
  // Trailing blank lines are fine.
  EXPECT_EQ(sgtllc::io::readTrajectory(write("ok.txt", kIdentityKitti + "\n\n")).poses.size(), 1u);
}

TEST_F(TrajectoryIo, CalibWithoutTrIsAnError) {
  const std::string bad_calib = write("calib_no_tr.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT(readError(kIdentityKitti, bad_calib), HasSubstr("calib_no_tr.txt: no 'Tr:' line"));
  EXPECT_THAT(readError(kIdentityKitti, path("missing_calib.txt")), HasSubstr("cannot open"));
}

// Two Tr lines (a merged or concatenated calib) leave the transform ambiguous: refused, naming both lines.
TEST_F(TrajectoryIo, CalibWithTwoTrLinesIsAnError) {
  const std::string tr = "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  const std::string two = write("calib_two.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n" + tr + "\n" + tr);
  EXPECT_THAT(readError(kIdentityKitti, two), HasSubstr("calib_two.txt:4: a second Tr: line (line 2 has one)"));
  EXPECT_THAT(sgtllc::test::errorOf([&] { sgtllc::io::readKittiCalibTr(two); }),
              HasSubstr("calib_two.txt:4: a second Tr: line (line 2 has one)"));
}

// fuzz/regressions/trajectory/calib_overflow: an invertible Tr whose scales overflow Tr⁻¹ · P · Tr for a rotation
// about z (entry (1, 0) becomes 1e300 · 1 · 1e300); readTrajectory returned an infinite pose.
TEST_F(TrajectoryIo, CalibThatOverflowsThePosesIsAnError) {
  const std::string bad_calib = write("calib_scaled.txt", "Tr: 1e300 0 0 0 0 1e-300 0 0 0 0 1 0\n");
  EXPECT_THAT(readError("0 -1 0 0 1 0 0 0 0 0 1 0\n", bad_calib),
              AllOf(HasSubstr("calib_scaled.txt: its Tr turns the pose of"), HasSubstr("traj.txt:1 into non-finite")));
  // The same Tr leaves the identity pose finite (Tr⁻¹ · I · Tr = I): it is the overflow that is rejected.
  const Trajectory t = sgtllc::io::readTrajectory(write("id.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n"), bad_calib);
  ASSERT_EQ(t.poses.size(), 1u);
  EXPECT_TRUE(t.poses[0].matrix().allFinite());
}

TEST_F(TrajectoryIo, FailedWriteLeavesTheOldFile) {
  const std::string file = write("keep.txt", "old");
  Trajectory t;
  t.format = TrajectoryFormat::kTum;
  t.poses = randomPoses(2, 3);  // no stamps
  EXPECT_THROW(sgtllc::io::writeTrajectory(file, t), Error);
  EXPECT_EQ(slurp(file), "old");
  EXPECT_THAT([&] { sgtllc::io::writeTrajectory(path("no/such/dir/t.txt"), Trajectory{}); },
              ::testing::ThrowsMessage<Error>(HasSubstr("cannot write " + path("no/such/dir/t.txt"))));
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

TEST_F(TrajectoryIo, WithPosesKeepsFormatAndChecksCount) {
  Trajectory t;
  t.format = TrajectoryFormat::kTum;
  t.stamps = {1, 2};
  t.poses = randomPoses(2, 4);
  const Trajectory c = sgtllc::io::withPoses(t, randomPoses(2, 5));
  EXPECT_EQ(c.format, TrajectoryFormat::kTum);
  EXPECT_EQ(c.stamps, t.stamps);
  EXPECT_THROW(sgtllc::io::withPoses(t, randomPoses(3, 5)), Error);
}

}  // namespace
