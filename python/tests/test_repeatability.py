"""Node repeatability and label agreement from Python, against a brute-force numpy reference and the CLI."""
import numpy as np
import pytest

import sgtllc
from conftest import KITTI, MATCH_BIN, QUERY_BIN, cli_json


def brute_force_share(a, ca, b, cb, T_b_a, radius):
    moved_a = a @ T_b_a[:3, :3].T + T_b_a[:3, 3]
    T_a_b = np.linalg.inv(T_b_a)
    moved_b = b @ T_a_b[:3, :3].T + T_a_b[:3, 3]
    hits = 0
    for p, c, others, oc in ((moved_a, ca, b, cb), (moved_b, cb, a, ca)):
        for x, k in zip(p, c):
            d = np.linalg.norm(others - x, axis=1)
            hits += bool(np.any((d <= radius) & (oc == k)))
    return hits / (len(a) + len(b))


def test_node_repeatability_matches_brute_force():
    rng = np.random.default_rng(3)
    a = rng.uniform(-20, 20, size=(60, 3))
    ca = rng.integers(0, 7, size=60)
    angle = 0.4
    T = np.eye(4)
    T[:2, :2] = [[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]
    T[:3, 3] = [2.0, -1.0, 0.1]
    b = a @ T[:3, :3].T + T[:3, 3] + rng.normal(0, 0.3, size=(60, 3))
    cb = ca.copy()
    cb[:10] = (cb[:10] + 1) % 7
    r = sgtllc.node_repeatability(a, ca, b, cb, T, radius=0.5, range=0.0)
    assert r.share() == pytest.approx(brute_force_share(a, ca, b, cb, T, 0.5), abs=1e-12)
    assert r.nodes.sum() == 120
    assert r.repeated.sum() == round(r.share() * 120)
    with pytest.raises(ValueError):
        sgtllc.node_repeatability(a, ca, b, cb, T, radius=0.0)


def test_label_agreement_matches_cli(cli):
    seq = str(KITTI)
    out = cli_json(cli, "repeatability", seq, "--pair", "004501:000052", "--poses", f"{seq}/poses_semantickitti.txt")
    tp = fp = fn = 0
    for scan in (QUERY_BIN, MATCH_BIN):
        points = sgtllc.read_kitti_bin(str(scan))
        classes, _ = sgtllc.label_scan(points)
        k = sgtllc.label_agreement(classes, sgtllc.read_labels(str(KITTI / "labels" / (scan.stem + ".label"))))
        tp, fp, fn = tp + k.tp, fp + k.fp, fn + k.fn
    building = out["label_agreement"]["classes"]["building"]
    assert building["iou"] == pytest.approx(tp[0] / (tp[0] + fp[0] + fn[0]), abs=1e-12)
    assert building["reference_points"] == tp[0] + fn[0]
    with pytest.raises(ValueError):
        sgtllc.label_agreement(np.array([7.5]), np.array([50]))


def test_apply_labeller_sources():
    points = sgtllc.read_kitti_bin(str(QUERY_BIN))
    labels = sgtllc.read_labels(str(KITTI / "labels" / "004501.label"))
    config = sgtllc.Config()
    np.testing.assert_array_equal(sgtllc.apply_labeller(points, labels, config), labels)
    config.labeller.source = sgtllc.LabelSource.GEOMETRIC
    np.testing.assert_array_equal(sgtllc.apply_labeller(points, labels, config), sgtllc.label_scan_ids(points))
    # A label set without pole and trunk classes (as nuScenes'): hybrid splits them off its building and vegetation.
    config.labeller.source = sgtllc.LabelSource.HYBRID
    config.labels.preset = sgtllc.LabelPreset.CUSTOM
    semantic = labels & 0xFFFF
    for raw in np.unique(semantic):
        config.labels.custom_map[int(raw)] = -1
    for raw, cls in {50: 0, 80: 0, 81: 0, 70: 2, 71: 2}.items():
        config.labels.custom_map[raw] = cls
    out = sgtllc.apply_labeller(points, labels, config)
    assert set(np.unique(out[np.isin(semantic, [50, 80, 81])])) <= {50, 80}
    assert set(np.unique(out[np.isin(semantic, [70, 71])])) <= {70, 71}
    thin = np.isin(out, [71, 80])
    assert thin.sum() > 1000
    assert np.isin(semantic[thin], [71, 80]).mean() > 0.76  # mostly the scan's true trunks and poles
