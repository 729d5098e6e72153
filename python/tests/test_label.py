"""The geometric labeller from Python: label_scan on a real KITTI scan and on bad input, and the config key."""
import numpy as np
import pytest

import sgtllc
from conftest import MATCH_BIN, QUERY_BIN, cli_json


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


def test_label_scan_ids_are_the_classes_as_semantickitti_ids():
    scan = sgtllc.read_kitti_bin(str(QUERY_BIN))
    classes, ground = sgtllc.label_scan(scan)
    expected = np.zeros(len(classes), dtype=np.uint32)
    kept = classes >= 0
    expected[kept] = np.array([50, 51, 70, 71, 72, 80, 81], dtype=np.uint32)[classes[kept]]
    expected[(~kept) & (ground == 1)] = 40
    ids = sgtllc.label_scan_ids(scan)
    assert ids.dtype == np.uint32
    np.testing.assert_array_equal(ids, expected)


def test_revisit_from_scans_alone_equals_the_cli(cli):
    # `sgtllc pair --labeller geometric` is label_scan_ids into compare_pair; guided
    # matching pairs 3 poles the descriptors confused, which makes 4501 -> 52 a loop (docs/algorithm.md §7.2).
    expected = cli_json(cli, "pair", QUERY_BIN, MATCH_BIN, "--labeller", "geometric")
    q, m = sgtllc.read_kitti_bin(str(QUERY_BIN)), sgtllc.read_kitti_bin(str(MATCH_BIN))
    r = sgtllc.compare_pair(q, sgtllc.label_scan_ids(q), m, sgtllc.label_scan_ids(m))
    assert r.is_loop and expected["loop"]
    assert r.score_t == pytest.approx(expected["score_t"], abs=1e-12)
    guided = [a for a in r.match.associations if a.guided]
    assert len(guided) == expected["guided_pairs"] > 0
    assert all(a.similarity == 0.0 for a in guided)
    assert sgtllc.Config().verification.guided_matching
    np.testing.assert_allclose(r.T_match_query, np.array(expected["T_match_query"]), rtol=0, atol=1e-6)
