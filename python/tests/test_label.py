"""The geometric labeller from Python: label_scan on a real KITTI scan and on bad input, and the config key."""
import numpy as np
import pytest

import sgtllc
from conftest import QUERY_BIN


def test_label_scan_real_scan():
    scan = sgtllc.read_kitti_bin(str(QUERY_BIN))
    classes, ground = sgtllc.label_scan(scan)
    assert classes.shape == (scan.shape[0],) and classes.dtype == np.int8
    assert ground.shape == (scan.shape[0],) and ground.dtype == np.uint8
    assert not np.any(classes == 3)  # trunk is merged into pole
    assert np.count_nonzero(classes == 0) > 20000  # buildings
    assert 0.3 < ground.mean() < 0.7
    # (N, 3) and (N, 4) give the same: intensity is not used; and the same on every call.
    again, _ = sgtllc.label_scan(scan[:, :3].copy())
    np.testing.assert_array_equal(classes, again)
    # Points labelled ground are never given a class.
    assert np.all(classes[ground == 1] == -1)


def test_label_scan_bad_input():
    classes, ground = sgtllc.label_scan(np.full((100, 3), 2.0, dtype=np.float32))
    assert np.all(classes == -1)
    pts = np.array([[np.nan, 0, 0], [np.inf, 1, 1], [1, 2, 3]], dtype=np.float32)
    classes, ground = sgtllc.label_scan(pts)
    assert list(classes) == [-1, -1, -1] and ground[0] == 0 and ground[1] == 0
    with pytest.raises(Exception):
        sgtllc.label_scan(np.zeros((10, 2), dtype=np.float32))


def test_labeller_config_key():
    c = sgtllc.Config()
    assert c.labeller.source == sgtllc.LabelSource.FILE
    c.labeller.source = sgtllc.LabelSource.GEOMETRIC
    c.labeller.ground.tolerance = 0.0
    with pytest.raises(sgtllc.ConfigError):
        c.validate()
