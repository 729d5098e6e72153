"""ScanAccumulator: merges by hand-computed transforms, labels with their points, at most N scans."""
import numpy as np
import pytest

import sgtllc


def pose(yaw_deg, t):
    c, s = np.cos(np.radians(yaw_deg)), np.sin(np.radians(yaw_deg))
    T = np.eye(4)
    T[:2, :2] = [[c, -s], [s, c]]
    T[:3, 3] = t
    return T


def test_merges_into_the_newest_frame():
    a = sgtllc.ScanAccumulator(3)
    a.add([[1.0, 0, 0], [0, 0, 3]], [10, 11], pose(0, [1, 0, 0]))
    a.add([[1.0, 1, 0]], np.array([20], np.uint32), pose(90, [0, 2, 0]))
    points, labels = a.add(np.array([[5, -4, 2, 0.7]], np.float32), [30], pose(180, [0, 2, 1]))
    # World -> frame 2: (-wx, -(wy - 2), wz - 1); see tests/test_accumulate.cpp for the same numbers.
    np.testing.assert_allclose(points, [[-2, 2, -1], [-1, 2, 2], [1, -1, -1], [5, -4, 2]], atol=1e-5)
    assert points.dtype == np.float32 and labels.dtype == np.uint32
    assert labels.tolist() == [10, 11, 20, 30]
    assert len(a) == 3 and a.capacity == 3 and a.points == 4 and a.bytes == 64


def test_holds_at_most_n_scans():
    a = sgtllc.ScanAccumulator(2)
    for k in range(5):
        points, labels = a.add(np.zeros((k + 1, 3)), np.full(k + 1, k), pose(0, [k, 0, 0]))
        assert len(a) == min(k + 1, 2)
        assert len(points) == (k + 1) + (k if k else 0)
        assert sorted(set(labels.tolist())) == sorted({k, max(k - 1, 0)})
    a.clear()
    assert len(a) == 0


def test_bad_input():
    with pytest.raises(sgtllc.Error, match="must be 1..1000"):
        sgtllc.ScanAccumulator(0)
    a = sgtllc.ScanAccumulator(2)
    with pytest.raises(ValueError, match="labels"):
        a.add(np.zeros((3, 3)), [1, 2], np.eye(4))
    with pytest.raises(ValueError, match="T_world_scan"):
        a.add(np.zeros((1, 3)), [1], np.eye(3))
    assert len(a) == 0
