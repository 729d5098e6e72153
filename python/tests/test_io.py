"""The readers against plain numpy parsing of the same files, and their errors (missing file, malformed file)."""
import numpy as np
import pytest

import sgtllc
from conftest import KITTI, MATCH_BIN, SOURCE


def test_kitti_bin_and_labels_equal_numpy():
    points = sgtllc.read_kitti_bin(str(MATCH_BIN))
    np.testing.assert_array_equal(points, np.fromfile(MATCH_BIN, np.float32).reshape(-1, 4))
    labels = sgtllc.read_labels(str(KITTI / "labels" / "000052.label"))
    np.testing.assert_array_equal(labels, np.fromfile(KITTI / "labels" / "000052.label", np.uint32))
    assert labels.dtype == np.uint32 and points.dtype == np.float32 and len(labels) == len(points)
    xyz, lab = sgtllc.read_labeled_scan(str(MATCH_BIN))
    np.testing.assert_array_equal(xyz, points[:, :3])
    np.testing.assert_array_equal(lab, labels)


def test_pcd_formats_agree():
    clouds = [sgtllc.read_pcd(str(SOURCE / "data" / "pcd" / f"000052_every100th_{k}.pcd"))
              for k in ("ascii", "binary", "binary_compressed")]
    np.testing.assert_array_equal(clouds[1][0], clouds[2][0])  # binary and compressed: the same floats
    for points, labels in clouds[1:]:
        np.testing.assert_allclose(points, clouds[0][0], rtol=1e-6, atol=1e-5)  # ascii: 7 significant digits
        np.testing.assert_array_equal(labels, clouds[0][1])
    assert clouds[0][0].shape[1] == 3 and len(clouds[0][0]) > 100
    for k, (points, _) in zip(("ascii", "binary", "binary_compressed"), clouds):
        only = sgtllc.read_pcd_points(str(SOURCE / "data" / "pcd" / f"000052_every100th_{k}.pcd"))
        np.testing.assert_array_equal(only, points)


def test_pcd_without_a_label_field(tmp_path):
    # x y z intensity records are a KITTI .bin's layout: header + the .bin bytes is a binary PCD without labels.
    scan = sgtllc.read_kitti_bin(str(MATCH_BIN))
    n = len(scan)
    path = tmp_path / "raw.pcd"
    path.write_bytes(("VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
                      f"WIDTH {n}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA binary\n").encode()
                     + scan.astype(np.float32).tobytes())
    np.testing.assert_array_equal(sgtllc.read_pcd_points(str(path)), scan[:, :3])
    with pytest.raises(sgtllc.Error, match="no field 'label'"):
        sgtllc.read_pcd(str(path))


def test_poses_and_calib_equal_numpy():
    # KITTI's poses.txt is in cam0: as written with pose_frame="lidar", in the LiDAR frame through the calib.
    poses = sgtllc.read_poses(str(KITTI / "poses.txt"), pose_frame="lidar")
    rows = np.loadtxt(KITTI / "poses.txt").reshape(-1, 3, 4)
    np.testing.assert_array_equal(poses[:, :3, :], rows)
    np.testing.assert_array_equal(poses[:, 3, :], np.tile([0, 0, 0, 1.0], (len(rows), 1)))
    Tr = sgtllc.read_calib(str(KITTI / "calib.txt"))
    line = [l for l in open(KITTI / "calib.txt") if l.startswith("Tr:")][0]
    np.testing.assert_array_equal(Tr[:3], np.array(line.split()[1:], float).reshape(3, 4))
    lidar = sgtllc.lidar_poses(poses[:3], Tr)
    np.testing.assert_allclose(lidar[2], np.linalg.inv(Tr) @ poses[2] @ Tr, atol=1e-12)
    np.testing.assert_allclose(sgtllc.read_poses(str(KITTI / "poses.txt"), str(KITTI / "calib.txt"))[:3], lidar,
                               atol=1e-12)


def test_node_files_round_trip(tmp_path):
    centres = np.array([[1.5, -2.25, 0.1], [10.0, 3.0, 1e-7]])
    classes = np.array([0, 5], np.int32)
    path = tmp_path / "nodes.txt"
    sgtllc.write_nodes(str(path), centres, classes)
    c, k = sgtllc.read_nodes(str(path))
    np.testing.assert_array_equal(c, centres)
    np.testing.assert_array_equal(k, classes)
    with pytest.raises(sgtllc.Error, match="exists"):
        sgtllc.write_nodes(str(path), centres, classes)
    sgtllc.write_nodes(str(path), centres[:1], classes[:1], overwrite=True)
    assert len(sgtllc.read_nodes(str(path))[0]) == 1


def test_sequence_dir():
    seq = sgtllc.SequenceDir(str(KITTI))
    assert len(seq) == 4 and seq.frame_name(0) == "000052" and seq.bin_path(3).endswith("004501.bin")
    with pytest.raises(IndexError):
        seq.load(4)


def test_missing_file_is_file_not_found(tmp_path):
    for read in (sgtllc.read_kitti_bin, sgtllc.read_labels, sgtllc.read_pcd, sgtllc.read_pcd_points,
                 sgtllc.read_poses, sgtllc.read_calib,
                 sgtllc.read_nodes, sgtllc.Config.from_yaml):
        with pytest.raises((FileNotFoundError, sgtllc.Error), match="nope"):
            read(str(tmp_path / "nope"))
    with pytest.raises(FileNotFoundError):
        sgtllc.read_kitti_bin(str(tmp_path / "nope.bin"))
    with pytest.raises(sgtllc.Error, match="velodyne"):
        sgtllc.SequenceDir(str(tmp_path))


def test_malformed_files_name_file_and_problem(tmp_path):
    bad_bin = tmp_path / "bad.bin"
    bad_bin.write_bytes(b"\0" * 17)
    with pytest.raises(sgtllc.Error, match=r"bad\.bin.*17 bytes is not a multiple of 16"):
        sgtllc.read_kitti_bin(str(bad_bin))
    bad_poses = tmp_path / "poses.txt"
    bad_poses.write_text("1 0 0 0 0 1 0 0 0 0 1\n")
    with pytest.raises(sgtllc.Error, match=r"poses\.txt:1: 11 columns; expected 12"):
        sgtllc.read_poses(str(bad_poses))
    bad_nodes = tmp_path / "n.txt"
    bad_nodes.write_text("1 2 3\n")
    with pytest.raises(sgtllc.Error, match=r"n\.txt:1"):
        sgtllc.read_nodes(str(bad_nodes))


def test_scan_pair_lists_read_as_the_cli_reads_them(tmp_path):
    lists = tmp_path / "lists"
    lists.mkdir()
    (lists / "pairs.txt").write_text('query,match\n# the demo pair\na.bin,../b.bin\n/abs/c.bin,"d,e.bin"\n')
    assert sgtllc.read_scan_pairs(str(lists / "pairs.txt")) == [
        (str(lists / "a.bin"), str(lists / "../b.bin")), ("/abs/c.bin", str(lists / "d,e.bin"))]
    (lists / "bad.txt").write_text("/only.bin\n")
    with pytest.raises(ValueError, match=r"bad.txt:1: 1 fields, expected two"):
        sgtllc.read_scan_pairs(str(lists / "bad.txt"))
