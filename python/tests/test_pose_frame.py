"""read_poses follows the command line's pose-frame rule (include/sgtllc/io/trajectory_frame.h): a calib means cam0,
pose_frame="lidar" takes KITTI poses as LiDAR poses, and "auto" without a calib lets the motion decide, printing
(warning) the choice, or refuses with the message that names --calib."""
import warnings

import numpy as np
import pytest

import sgtllc
from conftest import KITTI

CAM0 = KITTI / "odometry" / "kissicp_first1000_kitti.txt"
TUM = KITTI / "odometry" / "kissicp_first1000_tum.txt"
CALIB = KITTI / "calib.txt"


def raw_kitti(path):
    rows = np.loadtxt(path).reshape(-1, 3, 4)
    poses = np.tile(np.eye(4), (len(rows), 1, 1))
    poses[:, :3, :] = rows
    return poses


def write_kitti(path, poses):
    np.savetxt(path, poses[:, :3, :].reshape(len(poses), 12), fmt="%.17g")


def test_cam0_file_through_the_calib_equals_lidar_poses():
    Tr = sgtllc.read_calib(str(CALIB))
    expected = np.linalg.inv(Tr) @ raw_kitti(CAM0) @ Tr
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a calib and cam0 motion agree: no warning
        poses = sgtllc.read_poses(str(CAM0), str(CALIB))
    np.testing.assert_allclose(poses, expected, atol=1e-9)
    np.testing.assert_array_equal(sgtllc.read_poses(str(CAM0), str(CALIB), "cam0"), poses)


def test_cam0_file_without_a_calib_names_calib():
    with pytest.raises(sgtllc.Error, match=r"kissicp_first1000_kitti\.txt: these KITTI poses move along their z axis, "
                                           r"as KITTI's cam0 poses do .*give --calib CALIB\.txt"):
        sgtllc.read_poses(str(CAM0))
    with pytest.raises(sgtllc.Error, match=r"--pose-frame cam0 needs --calib CALIB\.txt"):
        sgtllc.read_poses(str(CAM0), pose_frame="cam0")
    # Said explicitly: taken as written.
    np.testing.assert_array_equal(sgtllc.read_poses(str(CAM0), pose_frame="lidar"), raw_kitti(CAM0))
    with pytest.raises(sgtllc.Error, match=r"calib converts cam0 poses, pose_frame='lidar' says they are LiDAR"):
        sgtllc.read_poses(str(CAM0), str(CALIB), pose_frame="lidar")


def test_lidar_file_is_detected_and_said(tmp_path):
    Tr = sgtllc.read_calib(str(CALIB))
    lidar = np.linalg.inv(Tr) @ raw_kitti(CAM0) @ Tr
    path = tmp_path / "lidar.txt"
    write_kitti(path, lidar)
    with pytest.warns(UserWarning, match=r"lidar\.txt: KITTI poses read in the LiDAR frame \(motion along x .*"
                                         r"turning about z .*--pose-frame lidar to say so, --calib for cam0 poses"):
        poses = sgtllc.read_poses(str(path))
    np.testing.assert_array_equal(poses, lidar)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        np.testing.assert_array_equal(sgtllc.read_poses(str(path), pose_frame="lidar"), lidar)
    # With a calib the calib is applied (the user said cam0), with a warning that the motion doubts it.
    Tr = sgtllc.read_calib(str(CALIB))
    with pytest.warns(UserWarning, match=r"these KITTI poses move as LiDAR poses do .*yet the calib's Tr converts "
                                         r"them as cam0 poses; --pose-frame lidar if they are LiDAR poses"):
        np.testing.assert_allclose(sgtllc.read_poses(str(path), str(CALIB)), np.linalg.inv(Tr) @ lidar @ Tr,
                                   atol=1e-9)


def test_standing_trajectory_is_undecided(tmp_path):
    path = tmp_path / "standing.txt"
    write_kitti(path, np.tile(np.eye(4), (20, 1, 1)))
    with pytest.raises(sgtllc.Error, match=r"cannot tell the frame of these KITTI poses from their motion \(only 0 m "
                                           r"of motion, at least 5 needed\); give --pose-frame lidar"):
        sgtllc.read_poses(str(path))


def test_tum_is_lidar_and_a_bad_frame_name_is_refused():
    poses = sgtllc.read_poses(str(TUM))
    rows = np.loadtxt(TUM)
    np.testing.assert_allclose(poses[:, :3, 3], rows[:, 1:4])
    assert poses.shape == (len(rows), 4, 4)
    with pytest.raises(sgtllc.Error, match=r"a TUM file, read in the LiDAR frame as given"):
        sgtllc.read_poses(str(TUM), pose_frame="cam0")
    with pytest.raises(sgtllc.Error, match=r"pose frame 'velodyne' is not one of auto, lidar, cam0"):
        sgtllc.read_poses(str(TUM), pose_frame="velodyne")
