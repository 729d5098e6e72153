"""The pose-graph optimiser from Python: a drifting square loop closed by one loop edge."""
import math

import numpy as np
import pytest

import sgtllc


def step(dx, yaw_deg):
    a = math.radians(yaw_deg)
    T = np.eye(4)
    T[:2, :2] = [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]
    T[0, 3] = dx
    return T


def test_loop_edge_removes_the_drift():
    # 40 steps of 1 m with a 90° turn every 10: a closed square. The odometry turns 0.5° too little per corner.
    truth, odometry = [np.eye(4)], []
    for i in range(40):
        yaw = 90.0 if i % 10 == 9 else 0.0
        truth.append(truth[-1] @ step(1.0, yaw))
        odometry.append(step(1.0, yaw - 0.5 if yaw else 0.0))
    optimizer = sgtllc.PoseGraphOptimizer()
    for T in odometry:
        optimizer.add_odometry(T)
    assert optimizer.num_frames == 41
    drifted = optimizer.poses
    loop = np.linalg.inv(truth[0]) @ truth[40]  # frame 40 is back at frame 0
    information = np.diag([1e4] * 3 + [1e5] * 3)
    optimizer.add_loop(sgtllc.Edge(0, 40, loop, information))
    result = optimizer.optimize()
    assert result.num_accepted == 1 and result.loops[0].decision == sgtllc.LoopDecision.ACCEPTED
    assert result.converged and result.poses.shape == (41, 4, 4)
    before = np.linalg.norm(drifted[40][:3, 3] - truth[40][:3, 3])
    after = np.linalg.norm(result.poses[40][:3, 3] - truth[40][:3, 3])
    assert before > 0.2 and after < 0.1 * before
    np.testing.assert_array_equal(optimizer.poses, result.poses)


def test_bad_edges_raise():
    optimizer = sgtllc.PoseGraphOptimizer()
    optimizer.add_odometry(step(1.0, 0.0))
    with pytest.raises(sgtllc.Error):
        optimizer.add_loop(sgtllc.Edge(0, 5, np.eye(4)))
    with pytest.raises(ValueError, match="last row must be 0 0 0 1"):
        sgtllc.Edge(0, 1, np.ones((4, 4)))
    with pytest.raises(ValueError, match=r"information: expected a \(6, 6\) float array"):
        optimizer.add_odometry(np.eye(4), np.eye(3))
    config = sgtllc.BackendConfig()
    config.loss_scale = -1.0
    with pytest.raises(sgtllc.Error, match="backend.loss_scale"):
        sgtllc.PoseGraphOptimizer(config)


def test_online_close_loop_is_bounded_by_the_path():
    # Out 60 m and back along the same line, 1 m a frame; on the way back every frame closes a loop to the frame it
    # passes. With one anchor per 5 m stretch the reduced graph stays at about 120 / 5 poses whatever the loop count;
    # with every loop endpoint an anchor it holds them all. The final optimize() is the batch solution either way.
    truth = [np.eye(4)]
    for i in range(120):
        truth.append(truth[-1] @ step(1.0, 180.0 if i == 59 else 0.0))
    rng = np.random.default_rng(3)
    odometry = []
    for a, b in zip(truth[:-1], truth[1:]):
        noise = step(0.01 * rng.standard_normal(), 0.05 * rng.standard_normal())
        odometry.append(np.linalg.inv(a) @ b @ noise)
    loops = [sgtllc.Edge(120 - q, q, np.linalg.inv(truth[120 - q]) @ truth[q], np.diag([1e3] * 3 + [1e4] * 3))
             for q in range(70, 121)]

    def run(spacing):
        config = sgtllc.BackendConfig()
        config.online.anchor_spacing_m = spacing
        optimizer = sgtllc.PoseGraphOptimizer(config)
        solved = []
        for q in range(1, 121):
            optimizer.add_odometry(odometry[q - 1])
            if q >= 70:
                result = optimizer.close_loop(loops[q - 70])
                assert result.reduced and result.num_accepted == q - 69
                solved.append(result.num_poses_solved)
        return solved, optimizer.optimize().poses

    bounded, bounded_final = run(5.0)
    exact, exact_final = run(0.0)
    assert exact[-1] >= 100          # every endpoint of 51 loops, frame 0 and the newest
    assert max(bounded) <= 120 // 5 + 4
    np.testing.assert_allclose(bounded_final, exact_final, atol=1e-6)
