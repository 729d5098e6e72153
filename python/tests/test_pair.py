"""compare_pair / compare_nodes from Python against `sgtllc pair --json` on the bundled KITTI 00 pairs, and the
checks of bad arrays (shape, dtype, NaN, length, class range): ValueErrors naming the argument, never a crash."""
import numpy as np
import pytest

import sgtllc
from conftest import KITTI, MATCH_BIN, QUERY_BIN, cli_json


def scan(path):
    return sgtllc.read_kitti_bin(str(path)), sgtllc.read_labels(sgtllc.default_label_path(str(path)))


@pytest.fixture(scope="module")
def pair():
    (qp, ql), (mp, ml) = scan(QUERY_BIN), scan(MATCH_BIN)
    return qp, ql, mp, ml


@pytest.mark.parametrize("query,match", [("004501", "000052"), ("000850", "000088")])
def test_compare_pair_equals_cli_json(cli, query, match):
    q, m = KITTI / "velodyne" / f"{query}.bin", KITTI / "velodyne" / f"{match}.bin"
    expected = cli_json(cli, "pair", q, m)
    r = sgtllc.compare_pair(*scan(q), *scan(m))
    assert r.is_loop == expected["loop"]
    assert r.score == pytest.approx(expected["score"], abs=1e-12)
    # score_t: the old name of score in Python and in the JSON, kept one release.
    assert r.score_t == r.score == r.match.score_t and expected["score_t"] == expected["score"]
    assert r.score_c == pytest.approx(expected["score_c"], abs=1e-12)
    assert r.rejection.name.lower() == expected["rejection"]
    np.testing.assert_allclose(r.T_match_query, np.array(expected["T_match_query"]), rtol=0, atol=1e-6)
    assert len(r.query_nodes[0]) == expected["nodes_query"] and len(r.match_nodes[0]) == expected["nodes_match"]
    pairs = [(a["query_node"], a["match_node"]) for a in expected["matches"]]
    assert r.match.association_pairs.tolist() == [list(p) for p in pairs]
    inliers = [[a["query_node"], a["match_node"]] for a in expected["matches"] if a["inlier"]]
    assert r.match.inlier_pairs.tolist() == inliers
    # The footprint check ran where a pose was found (the true loop), with the CLI's figures.
    if expected["footprint"] is None:
        assert r.match.footprint.compared == 0
    else:
        assert r.match.footprint.compared == expected["footprint"]["compared_cells"] > 20
        assert r.match.footprint.share == pytest.approx(expected["footprint"]["share"], abs=1e-12)
        assert r.match.footprint.share > 0.9
        # The seen-through check is off by default: no sight, nothing judged.
        assert r.match.footprint.seen.judged == expected["footprint"]["sight_judged"] == 0


def test_seen_through_equals_cli_json(cli, tmp_path):
    # With the check on, the revisit 4501 -> 52: the same counts as the CLI, little of either scan seen through.
    yaml = tmp_path / "seen.yaml"
    yaml.write_text("verification:\n  max_seen_through: 0.5\n")
    expected = cli_json(cli, "pair", QUERY_BIN, MATCH_BIN, "--config", yaml)
    config = sgtllc.Config()
    config.verification.max_seen_through = 0.5
    r = sgtllc.compare_pair(*scan(QUERY_BIN), *scan(MATCH_BIN), config=config)
    assert r.is_loop and expected["loop"]
    seen = r.match.footprint.seen
    assert seen.judged == expected["footprint"]["sight_judged"] > 100
    assert seen.share == pytest.approx(expected["footprint"]["seen_through"], abs=1e-12)
    assert seen.share == seen.seen_through / seen.judged < 0.1


def test_true_loop_pose_matches_ground_truth(pair):
    # demo_pairs.txt: T_000052_004501 from the KITTI poses; the object-level fit is within decimetres.
    r = sgtllc.compare_pair(*pair)
    row = [l.split() for l in open(KITTI / "demo_pairs.txt") if l.startswith("000052 004501")][0]
    gt = np.vstack([np.array(row[4:16], float).reshape(3, 4), [0, 0, 0, 1]])
    assert r.is_loop
    err = sgtllc.pose_error(r.T_match_query, gt)
    assert err.translation_m < 0.5 and err.rotation_deg < 2.0
    assert r.T_match_query.shape == (4, 4) and r.T_match_query.dtype == np.float64


def test_compare_nodes_equals_compare_pair(pair):
    r = sgtllc.compare_pair(*pair)
    n = sgtllc.compare_nodes(*r.query_nodes, *r.match_nodes)
    assert n.score == r.score and n.is_loop == r.is_loop
    # Node sets have no points, so no refinement: their pose is the scans' object-level SVD pose, the seed.
    assert n.refinement is None and r.refinement is not None
    np.testing.assert_array_equal(n.T_match_query, r.refinement.T_match_query_seed)


def test_refinement_is_the_cli_refinement(cli, pair):
    expected = cli_json(cli, "pair", QUERY_BIN, MATCH_BIN)["refinement"]
    r = sgtllc.compare_pair(*pair)
    assert r.refinement.used and r.refinement.status == sgtllc.RefinementStatus.CONVERGED
    assert r.refinement.status.name.lower() == expected["status"] and r.refinement.iterations == expected["iterations"]
    assert r.refinement.fitness == pytest.approx(expected["fitness"], abs=1e-12)
    np.testing.assert_allclose(r.refinement.T_match_query_seed, np.array(expected["T_match_query_svd"]), rtol=0, atol=1e-6)
    np.testing.assert_array_equal(r.T_match_query, r.refinement.T_match_query)
    assert r.refinement.information.shape == (6, 6) and r.refinement.information[0, 0] > 0
    config = sgtllc.Config()
    config.registration.pair = False
    svd = sgtllc.compare_pair(*pair, config=config)
    assert svd.refinement is None
    np.testing.assert_array_equal(svd.T_match_query, r.refinement.T_match_query_seed)


def test_dtypes_and_layouts_give_the_same_result(pair):
    qp, ql, mp, ml = pair
    base = sgtllc.compare_pair(qp, ql, mp, ml)
    variants = [
        (np.ascontiguousarray(qp[:, :3]), ql.astype(np.int64)),  # (N, 3) float32, int64 labels
        (qp.astype(np.float64), ql.astype(np.uint64)),  # float64 points
        (np.asfortranarray(qp[:, :3]), ql),  # Fortran order
        (qp[:, :3], ql.astype(np.int32)),  # a strided view
    ]
    for points, labels in variants:
        r = sgtllc.compare_pair(points, labels, mp, ml)
        assert r.score == base.score
        np.testing.assert_array_equal(r.T_match_query, base.T_match_query)


def test_nan_points_raise_unless_dropped(pair):
    qp, ql, mp, ml = pair
    bad = np.vstack([qp, [[np.nan, 0, 0, 0]]]).astype(np.float32)
    labels = np.append(ql, np.uint32(50))
    with pytest.raises(ValueError, match=r"query_points\[%d\] is not finite" % len(qp)):
        sgtllc.compare_pair(bad, labels, mp, ml)
    r = sgtllc.compare_pair(bad, labels, mp, ml, drop_nonfinite=True)
    assert r.extraction_query.nonfinite_points == 1
    assert r.score == sgtllc.compare_pair(qp, ql, mp, ml).score


@pytest.mark.parametrize(
    "points,labels,message",
    [
        (np.zeros((5, 2), np.float32), np.zeros(5, np.uint32), r"expected an \(N, 3\) or \(N, 4\) float array, got shape \(5, 2\)"),
        (np.zeros(12, np.float32), np.zeros(4, np.uint32), r"expected an \(N, 3\) or \(N, 4\).*got shape \(12,\)"),
        (np.zeros((5, 3), np.int32), np.zeros(5, np.uint32), r"got dtype int32"),
        (np.zeros((5, 3), np.float32), np.zeros(4, np.uint32), r"labels: expected an \(N,\) integer array .*N = 5, got shape \(4,\)"),
        (np.zeros((5, 3), np.float32), np.zeros(5, np.float32), r"labels: .*got dtype float32"),
        (np.zeros((5, 3), np.float32), np.full(5, -1), r"labels\[0\] = -1 is not a raw id"),
        (np.zeros((5, 3), np.float32), np.full(5, 2**33), r"labels\[0\] = 8589934592 is not a raw id"),
        ([[0.0, 0.0]], [0], r"got shape \(1, 2\)"),
    ],
)
def test_bad_arrays_raise_value_error(pair, points, labels, message):
    _, _, mp, ml = pair
    with pytest.raises(ValueError, match=message):
        sgtllc.compare_pair(points, labels, mp, ml)
    with pytest.raises(ValueError, match=message.replace("labels", "labels")):
        sgtllc.LoopDetector().process(points, labels)


def test_bad_nodes_raise_value_error():
    c = np.zeros((3, 3))
    with pytest.raises(ValueError, match=r"query_classes\[1\] = 7 is not a class index 0..6"):
        sgtllc.compare_nodes(c, [0, 7, 1], c, [0, 1, 2])
    with pytest.raises(ValueError, match=r"query_centres: expected an \(N, 3\) float array, got shape \(3, 4\)"):
        sgtllc.compare_nodes(np.zeros((3, 4)), [0, 1, 2], c, [0, 1, 2])
    with pytest.raises(ValueError, match=r"match_centres\[2\] is not finite"):
        sgtllc.compare_nodes(c, [0, 1, 2], np.array([[0, 0, 0], [1, 0, 0], [np.inf, 0, 0]], float), [0, 1, 2])
    config = sgtllc.Config()
    config.graph.max_nodes = 2
    with pytest.raises(sgtllc.Error, match="max_nodes"):
        sgtllc.compare_nodes(c, [0, 1, 2], c, [0, 1, 2], config)


def test_empty_scans_are_no_loop():
    e = np.zeros((0, 3), np.float32)
    r = sgtllc.compare_pair(e, np.zeros(0, np.uint32), e, np.zeros(0, np.uint32))
    assert not r.is_loop and r.score == 0.0 and r.rejection == sgtllc.Rejection.FEW_ASSOCIATIONS
    np.testing.assert_array_equal(r.T_match_query, np.eye(4))


def test_config_is_used(pair):
    config = sgtllc.Config()
    config.verification.sigma_4 = 0.99
    r = sgtllc.compare_pair(*pair, config=config)
    assert not r.is_loop and r.score == sgtllc.compare_pair(*pair).score


def test_threads_share_the_module(pair):
    # The GIL is released inside the calls: concurrent calls must give the serial result, and two threads on one
    # detector are serialised by its lock (frames get distinct indices, nothing is lost).
    from concurrent.futures import ThreadPoolExecutor

    expected = sgtllc.compare_pair(*pair)
    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda _: sgtllc.compare_pair(*pair), range(4)))
    for r in results:
        assert r.score == expected.score
        np.testing.assert_array_equal(r.T_match_query, expected.T_match_query)
    detector = sgtllc.LoopDetector()
    qp, ql, _, _ = pair
    with ThreadPoolExecutor(2) as pool:
        frames = sorted(pool.map(lambda _: detector.process(qp, ql).frame, range(4)))
    assert frames == [0, 1, 2, 3] and detector.num_frames == 4
