"""sgtllc.LoopClosingPipeline and its two examples: the examples' corrected poses are `sgtllc run`'s to 1e-9 m."""
import os
import subprocess
import sys
import tarfile

import numpy as np
import pytest

import sgtllc
from conftest import KITTI, SOURCE, run_cli

FRAMES = ["000052", "000088", "000850", "004501"]


def short_config():
    config = sgtllc.Config()
    config.retrieval.exclude_recent = 1  # four scans: every older one is a candidate
    return config


def kiss_poses():
    return sgtllc.read_poses(str(KITTI / "kissicp_00_kitti.txt"), str(KITTI / "calib.txt"))


def test_pipeline_closes_the_bundled_revisit():
    seq = sgtllc.SequenceDir(str(KITTI))
    odometry = kiss_poses()[[int(f) for f in FRAMES]]
    pipeline = sgtllc.LoopClosingPipeline(short_config(), online=True)
    frames = [pipeline.add_scan(*seq.load(i), pose=odometry[i], name=seq.frame_name(i)) for i in range(len(seq))]
    assert [f.loop is not None for f in frames] == [False, False, False, True]
    loop = frames[3].loop
    assert (loop.query, loop.match, loop.edge.from_, loop.edge.to) == ("004501", "000052", 0, 3)
    assert loop.score == pytest.approx(0.64)
    assert frames[3].solved and frames[3].update.num_accepted == 1
    # KISS-ICP drifted 4501 to 12.4 m from 52; the ground truth has them 2.96 m apart.
    assert np.linalg.norm(odometry[3, :3, 3] - odometry[0, :3, 3]) > 12.0
    closing = pipeline.finish()
    assert np.linalg.norm(closing.poses[3, :3, 3] - closing.poses[0, :3, 3]) == pytest.approx(2.96, abs=0.05)
    np.testing.assert_array_equal(pipeline.poses, closing.poses)
    assert pipeline.names == FRAMES
    assert pipeline.to_map().num_frames == 4
    with pytest.raises(sgtllc.Error, match="finish"):
        pipeline.add_scan(*seq.load(0), pose=odometry[0])


def test_pipeline_refuses_what_it_cannot_use():
    seq = sgtllc.SequenceDir(str(KITTI))
    points, labels = seq.load(0)
    pipeline = sgtllc.LoopClosingPipeline(short_config())
    with pytest.raises(sgtllc.Error, match="labeller.source is geometric"):
        pipeline.add_scan(points)
    pipeline.add_scan(points, labels)
    with pytest.raises(sgtllc.Error, match="the frames before had none"):
        pipeline.add_scan(points, labels, pose=np.eye(4))
    with pytest.raises(sgtllc.Error, match="odometry poses"):
        pipeline.finish()
    assert pipeline.num_frames == 1
    with pytest.raises(sgtllc.Error, match="online solving needs"):
        sgtllc.LoopClosingPipeline(short_config(), online=True).add_scan(points, labels)
    geometric = short_config()
    geometric.labeller.source = sgtllc.LabelSource.GEOMETRIC
    assert sgtllc.LoopClosingPipeline(geometric).add_scan(points).detection.num_nodes > 5


def run_example(name, *args):
    return subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / name), *map(str, args)],
                          check=True, capture_output=True, text=True, env=dict(os.environ)).stdout


def test_close_loops_example_gives_the_poses_of_run(cli, tmp_path):
    config = tmp_path / "config.yaml"
    config.write_text("retrieval:\n  exclude_recent: 1\n")
    # The four bundled scans' lines of the KISS-ICP odometry (cam0, through data/kitti/00/calib.txt).
    rows = np.loadtxt(KITTI / "kissicp_00_kitti.txt")[[int(f) for f in FRAMES]]
    odometry = tmp_path / "odometry.txt"
    np.savetxt(odometry, rows, fmt="%.17g")
    out = run_example("close_loops.py", KITTI, "--odometry", odometry, "--config", config, "--out-trajectory",
                      tmp_path / "example.txt")
    assert "loop 004501 -> 000052" in out
    assert "4 frames, 1 loops, 1 accepted" in out
    run_cli(cli, "run", KITTI, "--odometry", odometry, "--config", config, "--out-trajectory", tmp_path / "run.txt")
    from_run = sgtllc.read_poses(str(tmp_path / "run.txt"), str(KITTI / "calib.txt"))
    from_example = np.loadtxt(tmp_path / "example.txt").reshape(-1, 3, 4)
    np.testing.assert_allclose(from_example, from_run[:, :3, :], rtol=0, atol=1e-9)


def test_correct_tum_example_gives_the_poses_of_run(cli, tmp_path):
    # KITTI 00's first 2,000 object frames (163 loops) and its KISS-ICP odometry as a TUM file of LiDAR poses.
    frames = 2000
    with tarfile.open(KITTI / "objects.tar.xz") as archive:
        members = sorted((m for m in archive.getmembers() if m.name.endswith(".txt")), key=lambda m: m.name)
        archive.extractall(tmp_path, members=members[:frames])
    nodes = tmp_path / "objects"
    poses = kiss_poses()[:frames]
    tum = tmp_path / "odometry.tum"
    with open(tum, "w") as f:
        for i, T in enumerate(poses):
            f.write(" ".join(repr(float(v)) for v in [0.1 * i, *T[:3, 3], *rotation_to_quaternion(T[:3, :3])]) + "\n")
    config = SOURCE / "configs" / "kitti00-objects.yaml"
    out = run_example("correct_tum.py", nodes, tum, tmp_path / "example.tum", "--config", config, "--online")
    assert "re-solved" in out
    run_cli(cli, "run", "--nodes", nodes, "--odometry", tum, "--config", config, "--online", "--quiet",
            "--out-trajectory", tmp_path / "run.tum")
    from_run = sgtllc.read_poses(str(tmp_path / "run.tum"))
    from_example = sgtllc.read_poses(str(tmp_path / "example.tum"))
    assert len(from_example) == frames
    np.testing.assert_allclose(from_example, from_run, rtol=0, atol=1e-9)
    stamps = np.loadtxt(tmp_path / "example.tum")[:, 0]
    np.testing.assert_array_equal(stamps, 0.1 * np.arange(frames))
    # The loops moved the trajectory: the corrected poses are not the odometry.
    assert np.abs(from_example[:, :3, 3] - poses[:, :3, 3]).max() > 1.0


def rotation_to_quaternion(R):
    """qx qy qz qw of a rotation matrix, via the example's own conversion."""
    sys.path.insert(0, str(SOURCE / "examples" / "python"))
    try:
        import correct_tum
    finally:
        sys.path.pop(0)
    T = np.eye(4)
    T[:3, :3] = R
    return correct_tum.tum_from_pose(T)[3:]
