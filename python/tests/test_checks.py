"""Python refuses what the command line refuses, with the same messages (non-rigid poses, a second Tr line, a
quaternion that is not a unit one), and its own errors say what was expected (None for an array, a frame out of
range, a wrong attribute type)."""
import subprocess

import numpy as np
import pytest

import sgtllc
from conftest import KITTI

IDENTITY = "1 0 0 0 0 1 0 0 0 0 1 0\n"


def test_read_poses_refuses_a_non_rigid_rotation(tmp_path):
    path = tmp_path / "scaled.txt"
    path.write_text(IDENTITY + "2 0 0 0 0 2 0 0 0 0 2 0\n")
    for frame in ("auto", "lidar"):
        with pytest.raises(sgtllc.Error, match=r"scaled\.txt:2: rotation is not orthonormal \(\|RᵀR − I\| = 3, "
                                               r"at most 0\.001\)"):
            sgtllc.read_poses(str(path), pose_frame=frame)


def test_python_and_the_command_line_say_the_same(tmp_path, cli):
    bad = {"scaled.txt": IDENTITY + "2 0 0 0 0 2 0 0 0 0 2 0\n", "quat.txt": "0 0 0 0 2 0 0 0\n",
           "cam0.txt": (KITTI / "odometry" / "kissicp_first1000_kitti.txt").read_text()}
    for name, text in bad.items():
        path = tmp_path / name
        path.write_text(text)
        with pytest.raises(sgtllc.Error) as python:
            sgtllc.read_poses(str(path))
        out = subprocess.run([cli, "optimize", "--odometry", str(path), "--loops", str(tmp_path / "none.csv")],
                             capture_output=True, text=True)
        assert out.returncode == 1 and str(python.value) in out.stderr, (name, out.stderr)


def test_tum_quaternion_must_be_a_unit_one(tmp_path):
    path = tmp_path / "t.txt"
    path.write_text("0 0 0 0 0 0 0 1\n0.1 1 0 0 2 0 0 0\n")
    with pytest.raises(sgtllc.Error, match=r"t\.txt:2: quaternion \(2, 0, 0, 0\) has norm 2, not 1"):
        sgtllc.read_poses(str(path))
    path.write_text("0 0 0 0 0 0 0 1.0004\n")  # six written digits are far closer than 1e-3
    assert sgtllc.read_poses(str(path)).shape == (1, 4, 4)


def test_a_calib_with_two_tr_lines_is_refused(tmp_path):
    lines = open(KITTI / "calib.txt").read().splitlines()
    tr = [l for l in lines if l.startswith("Tr:")][0]
    path = tmp_path / "calib.txt"
    path.write_text("\n".join(lines + [tr]) + "\n")
    message = rf"calib\.txt:{len(lines) + 1}: a second Tr: line \(line {lines.index(tr) + 1} has one\)"
    with pytest.raises(sgtllc.Error, match=message):
        sgtllc.read_calib(str(path))
    with pytest.raises(sgtllc.Error, match=message):
        sgtllc.read_poses(str(KITTI / "odometry" / "kissicp_first1000_kitti.txt"), str(path))


def detector_with_one_frame():
    detector = sgtllc.LoopDetector(sgtllc.Config())
    detector.process_nodes(np.array([[0.0, 0, 0], [5, 0, 0], [0, 5, 0]]), np.array([0, 1, 2]))
    return detector


def test_to_map_refuses_non_rigid_poses():
    detector = detector_with_one_frame()
    with pytest.raises(sgtllc.Error, match=r"poses\[0\]: rotation is not orthonormal \(\|RᵀR − I\| = 1, at most "
                                           r"0\.001\)"):
        detector.to_map(poses=np.zeros((1, 4, 4)))
    bad_row = np.eye(4)[None].copy()
    bad_row[0, 3, 0] = 1.0
    with pytest.raises(sgtllc.Error, match=r"poses\[0\]: the last row must be 0 0 0 1"):
        detector.to_map(poses=bad_row)
    assert detector.to_map(poses=np.eye(4)[None]).has_poses


def test_none_for_an_array_says_none():
    with pytest.raises(ValueError, match=r"query_centres: expected an \(N, 3\) float array, got None"):
        sgtllc.compare_nodes(None, [0], [[0.0, 0, 0]], [0])
    with pytest.raises(ValueError, match=r"points: expected an \(N, 3\) or \(N, 4\) float array, got None"):
        sgtllc.LoopDetector(sgtllc.Config()).process(None, [0])


def test_frame_out_of_range():
    seq = sgtllc.SequenceDir(str(KITTI))
    for call in (seq.load, seq.bin_path, seq.label_path, seq.frame_name):
        with pytest.raises(IndexError, match=r"frame 99 is out of range: the sequence has 4 frames \(0\.\.3\)"):
            call(99)
    with pytest.raises(IndexError, match=r"frame -1 is out of range"):
        seq.load(-1)
    with pytest.raises(IndexError, match=r"frame -1: the detector holds no frames"):
        sgtllc.LoopDetector(sgtllc.Config()).nodes(-1)
    with pytest.raises(IndexError, match=r"frame 1 is not in 0\.\.0"):
        detector_with_one_frame().nodes(1)


def test_wrong_attribute_type_names_attribute_and_type():
    c = sgtllc.Config()
    cases = [
        (lambda: setattr(c.graph, "max_nodes", 2.5), r"GraphConfig\.max_nodes: expected int, got float 2\.5"),
        (lambda: setattr(c.graph, "sigma_d", "a"), r"GraphConfig\.sigma_d: expected float, got str 'a'"),
        (lambda: setattr(c.descriptor, "global_mode", 3),
         r"DescriptorConfig\.global_mode: expected sgtllc\.GlobalMode, got int 3"),
        (lambda: setattr(c, "graph", 1), r"Config\.graph: expected sgtllc\.GraphConfig, got int 1"),
        (lambda: setattr(c.backend.solver, "max_iterations", None),
         r"SolverSettings\.max_iterations: expected int, got NoneType None"),
    ]
    for assign, message in cases:
        with pytest.raises(TypeError, match=message):
            assign()
    # Right types still work, and the value is set.
    c.graph.sigma_d = 7
    c.descriptor.global_mode = sgtllc.GlobalMode.G1
    assert c.graph.sigma_d == 7.0 and c.descriptor.global_mode == sgtllc.GlobalMode.G1
