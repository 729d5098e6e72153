"""The geometric labeller from Python: label_scan on a real KITTI scan and on bad input, and the config key."""
from pathlib import Path

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
    assert r.score == pytest.approx(expected["score"], abs=1e-12)
    guided = [a for a in r.match.associations if a.guided]
    assert len(guided) == expected["guided_pairs"] > 0
    assert all(a.similarity == 0.0 for a in guided)
    assert sgtllc.Config().verification.guided_matching
    np.testing.assert_allclose(r.T_match_query, np.array(expected["T_match_query"]), rtol=0, atol=1e-6)


def test_poles_must_be_seen_whole():
    # A thin upright segment cut off at a side by nearer points is a strip seen through a gap, not a pole
    # (docs/labeller.md §4, "Seen whole"). On the real scan 4501 the rule takes away pole points that the
    # ground truth calls building or vegetation, and keeps its trunks.
    scan = sgtllc.read_kitti_bin(str(QUERY_BIN))
    truth = np.fromfile(str(QUERY_BIN).replace("velodyne", "labels").replace(".bin", ".label"), dtype=np.uint32)
    truth &= 0xFFFF
    config = sgtllc.LabellerConfig()
    assert config.segments.pole_max_occluded == 0.75
    seen_whole, _ = sgtllc.label_scan(scan, config)
    config.segments.pole_max_occluded = 1.0  # the rule off
    every_pole, _ = sgtllc.label_scan(scan, config)
    wrong = np.isin(truth, [50, 70])  # building, vegetation
    trunk = truth == 71
    assert np.count_nonzero((seen_whole == 5) & wrong) < 0.5 * np.count_nonzero((every_pole == 5) & wrong)
    assert np.count_nonzero((seen_whole == 5) & trunk) == np.count_nonzero((every_pole == 5) & trunk)
    # A pole seen whole was a pole before as well: the rule only takes poles away.
    assert np.all(every_pole[seen_whole == 5] == 5)


def test_reuse_freed_memory_keeps_results():
    # Process-wide and glibc-only (memory_reuse.h): the labels are the same with freed memory kept or handed back.
    import platform
    scan = sgtllc.read_kitti_bin(str(QUERY_BIN))
    before = sgtllc.label_scan_ids(scan)
    assert sgtllc.reuse_freed_memory() is (platform.libc_ver()[0] == "glibc")
    np.testing.assert_array_equal(sgtllc.label_scan_ids(scan), before)
    with pytest.raises(TypeError):
        sgtllc.reuse_freed_memory(-1)


def test_huge_page_heap_keeps_results():
    # Process-wide (memory_reuse.h): true wherever glibc's heap grew into a region marked for huge pages, which
    # a kernel offering them (madvise or always mode) always lets it do.
    import platform
    scan = sgtllc.read_kitti_bin(str(QUERY_BIN))
    before = sgtllc.label_scan_ids(scan)
    sgtllc.reuse_freed_memory()
    marked = sgtllc.huge_page_heap()
    mode = Path("/sys/kernel/mm/transparent_hugepage/enabled")
    offered = mode.exists() and ("[always]" in mode.read_text() or "[madvise]" in mode.read_text())
    assert marked is True or not (platform.libc_ver()[0] == "glibc" and offered)
    np.testing.assert_array_equal(sgtllc.label_scan_ids(scan), before)
    assert sgtllc.huge_page_heap(1 << 20) is False  # under two huge pages: nothing to mark
