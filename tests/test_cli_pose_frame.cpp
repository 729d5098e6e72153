// `--pose-frame` and the frame rule of KITTI-format odometry in `optimize` and `run` (io/trajectory_frame.h): the
// same drive written as LiDAR-frame and as cam0 KITTI poses closes the same way when each is read in its frame;
// a cam0 file without --calib is refused with a message naming --calib; LiDAR motion is read as such with a note.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/eval/trajectory_error.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "test_cli_backend_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using test::CliRun;
using test::run;

std::vector<Eigen::Matrix4d> matrices(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Matrix4d> out;
  for (const Eigen::Isometry3d& T : poses) out.push_back(T.matrix());
  return out;
}

class PoseFrameCli : public test::CliBackend {
 protected:
  void SetUp() override {
    CliBackend::SetUp();
    truth_ = test::circleDrive();
    const std::vector<Eigen::Matrix4d> odometry = matrices(test::driftedOdometry(truth_));
    const Eigen::Matrix4d Tr = io::kittiVelodyneToCam0();
    std::vector<Eigen::Matrix4d> cam0;
    for (const Eigen::Matrix4d& T : odometry) cam0.push_back(Tr * T * Tr.inverse());
    io::writeKittiPoses(path("lidar.txt"), odometry);
    io::writeKittiPoses(path("cam0.txt"), cam0);
    io::writeKittiCalib(path("calib.txt"), io::kittiProjections(), Tr);
    write("loops.csv", io::loopsCsvText(test::exactLoops(truth_)));
  }
  CliRun optimize(const std::string& odometry, const std::string& extra) const {
    return run("optimize --odometry " + path(odometry) + " --loops " + path("loops.csv") + " --out-trajectory " +
               path("corrected.txt") + " --force " + extra);
  }
  /// ATE (aligned RMSE) of the corrected trajectory, read in the LiDAR frame (through the calib for cam0).
  double correctedAte(const std::string& calib) const {
    return eval::absoluteTrajectoryError(truth_, io::readTrajectory(path("corrected.txt"), calib).poses).aligned.rmse;
  }
  std::vector<Eigen::Isometry3d> truth_;
};

TEST_F(PoseFrameCli, Cam0WithoutCalibIsRefusedNamingCalib) {
  const CliRun r = optimize("cam0.txt", "");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr(path("cam0.txt") + ": these KITTI poses move along their z axis, as KITTI's cam0 "
                                                  "poses do"));
  EXPECT_THAT(r.out, HasSubstr("give --calib CALIB.txt (its Tr brings them into the LiDAR frame), or --pose-frame "
                               "lidar if they are LiDAR poses"));
  const CliRun explicit_cam0 = optimize("cam0.txt", "--pose-frame cam0");
  EXPECT_EQ(explicit_cam0.status, 1);
  EXPECT_THAT(explicit_cam0.out, HasSubstr("--pose-frame cam0 needs --calib CALIB.txt"));
}

TEST_F(PoseFrameCli, BothFramesCloseTheLoopWhenReadInTheirOwn) {
  const CliRun lidar = optimize("lidar.txt", "--pose-frame lidar");
  ASSERT_EQ(lidar.status, 0) << lidar.out;
  EXPECT_THAT(lidar.out, HasSubstr("back end: 10 loops, 10 accepted, 0 rejected"));
  EXPECT_THAT(lidar.out, Not(HasSubstr("note:")));  // said explicitly: nothing to report
  const double ate_lidar = correctedAte("");
  EXPECT_LT(ate_lidar, 0.05);

  const CliRun cam0 = optimize("cam0.txt", "--calib " + path("calib.txt"));
  ASSERT_EQ(cam0.status, 0) << cam0.out;
  EXPECT_THAT(cam0.out, HasSubstr("back end: 10 loops, 10 accepted, 0 rejected"));
  EXPECT_NEAR(correctedAte(path("calib.txt")), ate_lidar, 1e-6);  // written back in cam0, read through the calib
}

TEST_F(PoseFrameCli, LidarMotionWithoutCalibIsReadWithANote) {
  const CliRun r = optimize("lidar.txt", "");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("note: " + path("lidar.txt") + ": KITTI poses read in the LiDAR frame (motion along x"));
  EXPECT_THAT(r.out, HasSubstr("; --pose-frame lidar to say so, --calib for cam0 poses\n"));
  EXPECT_THAT(r.out, HasSubstr("10 accepted"));
  // With a calib, the calib is applied (the user said cam0), but the clear LiDAR motion is worth a warning.
  const CliRun with_calib = optimize("lidar.txt", "--calib " + path("calib.txt"));
  ASSERT_EQ(with_calib.status, 0) << with_calib.out;
  EXPECT_THAT(with_calib.out, HasSubstr("warning: " + path("lidar.txt") + ": these KITTI poses move as LiDAR poses "
                                                                          "do (motion along x"));
  EXPECT_THAT(with_calib.out, HasSubstr("--pose-frame lidar if they are LiDAR poses"));
}

TEST_F(PoseFrameCli, ContradictoryOrUnknownOptionsAreRefused) {
  const CliRun both = optimize("lidar.txt", "--pose-frame lidar --calib " + path("calib.txt"));
  EXPECT_NE(both.status, 0);
  EXPECT_THAT(both.out, HasSubstr("--calib converts cam0 poses, --pose-frame lidar says they are LiDAR poses"));
  const CliRun unknown = optimize("lidar.txt", "--pose-frame velodyne");
  EXPECT_NE(unknown.status, 0);
  EXPECT_THAT(unknown.out, HasSubstr("--pose-frame"));
}

TEST_F(PoseFrameCli, KissIcpCam0OdometryOfKitti00IsRefusedWithoutCalib) {
  // The real file of the README's KITTI 00 run (data/README.md): KITTI format, cam0 frame.
  const std::string odometry = test::dataPath("kitti/00/odometry/kissicp_first1000_kitti.txt");
  write("none.csv", io::loopsCsvText({}));
  const CliRun r = run("optimize --odometry " + odometry + " --loops " + path("none.csv"));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.out, HasSubstr(odometry + ": these KITTI poses move along their z axis"));
  EXPECT_THAT(r.out, HasSubstr("give --calib CALIB.txt"));
  const CliRun ok = run("optimize --odometry " + odometry + " --loops " + path("none.csv") + " --calib " +
                        test::dataPath("kitti/00/calib.txt"));
  EXPECT_EQ(ok.status, 0) << ok.out;
  EXPECT_THAT(ok.out, HasSubstr("frames 1000, loops read 0"));
}

}  // namespace
}  // namespace sgtllc
