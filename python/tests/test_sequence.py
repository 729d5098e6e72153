"""A sequence run from Python (SequenceDir + LoopDetector + loop_edge) equals `sgtllc run --out`'s loops CSV:
on the four bundled KITTI 00 scans, and on a short simulated sequence with several loops."""
import csv

import numpy as np
import pytest

import sgtllc
from conftest import KITTI, run_cli


def python_loops(sequence, config):
    """The rows `sgtllc run` writes, computed from Python: names, scores, pose and information (None if none)."""
    seq = sgtllc.SequenceDir(str(sequence))
    detector = sgtllc.LoopDetector(config)
    rows = []
    for i in range(len(seq)):
        r = detector.process(*seq.load(i))
        assert r.frame == i
        if r.is_loop:
            c = r.loop
            try:
                info = sgtllc.loop_edge(c.frame, i, c.match, detector.nodes(i), detector.nodes(c.frame),
                                        config.backend.loops).information
            except sgtllc.Error:
                info = None  # collinear inlier centres: `run` writes empty information columns
            rows.append((seq.frame_name(i), seq.frame_name(c.frame), c.match.score, c.match.score_c,
                         c.match.T_match_query, info))
    return rows


def cli_loops(cli, sequence, config, tmp_path):
    cfg, out = tmp_path / "config.yaml", tmp_path / "loops.csv"
    cfg.write_text(config.to_yaml())
    run_cli(cli, "run", sequence, "--config", cfg, "--out", out, "--threads", 2)
    with open(out) as f:
        return list(csv.DictReader(f))


def assert_same(py_rows, cli_rows):
    assert len(py_rows) == len(cli_rows)
    for (query, match, score, score_c, T, info), row in zip(py_rows, cli_rows):
        assert (query, match) == (row["query"], row["match"])
        assert "%.6f" % score == row["score"] and "%.6f" % score_c == row["score_c"]
        names = ["r11", "r12", "r13", "tx", "r21", "r22", "r23", "ty", "r31", "r32", "r33", "tz"]
        assert ["%.6f" % v for v in T[:3, :].ravel()] == [row[n] for n in names]
        upper = [row["i%d%d" % (a, b)] for a in range(1, 7) for b in range(a, 7)]
        if info is None:
            assert upper == [""] * 21
        else:
            assert [float(v) for v in upper] == [info[a, b] for a in range(6) for b in range(a, 6)]


def test_bundled_kitti_scans_as_a_sequence(cli, tmp_path):
    config = sgtllc.Config()
    config.retrieval.exclude_recent = 1  # frames 52, 88, 850, 4501: every older frame is a candidate
    rows = python_loops(KITTI, config)
    assert [(q, m) for q, m, *_ in rows] == [("004501", "000052")]
    assert_same(rows, cli_loops(cli, KITTI, config, tmp_path))


@pytest.fixture(scope="module")
def simulated(cli, tmp_path_factory):
    out = tmp_path_factory.mktemp("sim") / "seq"
    run_cli(cli, "simulate", "--out", out, "--frames", 60, "--seed", 3, "--revisits", 1, "--no-preview",
            "--threads", 2)
    return out


def test_simulated_sequence_equals_cli_csv(cli, simulated, tmp_path):
    config = sgtllc.Config()
    config.retrieval.exclude_recent = 10
    rows = python_loops(simulated, config)
    assert len(rows) >= 3  # a run that finds no loop would compare nothing
    assert_same(rows, cli_loops(cli, simulated, config, tmp_path))


def test_threads_do_not_change_results(simulated):
    one, two = sgtllc.Config(), sgtllc.Config()
    one.retrieval.exclude_recent = two.retrieval.exclude_recent = 10
    two.threads = 2
    a, b = python_loops(simulated, one), python_loops(simulated, two)
    assert [r[:4] for r in a] == [r[:4] for r in b]
    for x, y in zip(a, b):
        np.testing.assert_array_equal(x[4], y[4])


def test_process_nodes_equals_process(simulated):
    config = sgtllc.Config()
    config.retrieval.exclude_recent = 10
    # Nodes carry no footprint (algorithm §7.7): with the check off the two paths verify alike.
    config.verification.min_footprint_overlap = 0.0
    seq = sgtllc.SequenceDir(str(simulated))
    points_detector, nodes_detector = sgtllc.LoopDetector(config), sgtllc.LoopDetector(config)
    for i in range(len(seq)):
        a = points_detector.process(*seq.load(i))
        b = nodes_detector.process_nodes(*points_detector.nodes(i))
        assert (a.is_loop, a.match_frame, a.score) == (b.is_loop, b.match_frame, b.score)
        assert [c.frame for c in a.candidates] == [c.frame for c in b.candidates]
    assert nodes_detector.num_frames == len(seq)
