"""Metrics against brute-force references computed here, and the pose and trajectory errors on analytic cases."""
import math

import numpy as np
import pytest

import sgtllc


def brute_force_curve(scores, positives):
    """Precision and recall at every distinct threshold, highest first (sklearn's convention, point (1, 0) last)."""
    points = []
    for t in sorted(set(scores), reverse=True):
        tp = sum(1 for s, p in zip(scores, positives) if s >= t and p)
        fp = sum(1 for s, p in zip(scores, positives) if s >= t and not p)
        points.append((tp / (tp + fp), tp / sum(positives)))
    return points


def test_pr_curve_f1_and_ep_equal_brute_force():
    rng = np.random.default_rng(7)
    scores = np.round(rng.random(200), 2)  # ties on purpose
    positives = rng.random(200) < scores  # higher scores are more often loops
    curve = sgtllc.precision_recall(scores, positives)
    reference = brute_force_curve(list(scores), list(positives))
    # One point per distinct threshold, highest first, down to full recall at the latest (sklearn).
    n = len(curve.thresholds)
    assert list(curve.thresholds) == sorted(set(scores), reverse=True)[:n]
    np.testing.assert_allclose(curve.precision[:n], [p for p, _ in reference][:n], rtol=0, atol=1e-12)
    np.testing.assert_allclose(curve.recall[:n], [r for _, r in reference][:n], rtol=0, atol=1e-12)
    assert curve.recall[n - 1] == 1.0
    f1 = max(2 * p * r / (p + r) for p, r in reference if p + r > 0)
    assert sgtllc.f1_max(curve) == pytest.approx(f1, abs=1e-12)
    r100 = max([r for p, r in reference if p == 1.0] + [0.0])
    assert sgtllc.recall_at_100_precision(curve) == pytest.approx(r100, abs=1e-12)
    p_rmin = 1.0 if positives[scores == scores.max()].any() else 0.0
    assert sgtllc.extended_precision(curve) == pytest.approx(0.5 * (p_rmin + r100), abs=1e-12)


def test_pr_input_checks():
    with pytest.raises(ValueError, match=r"positives: expected an \(N,\) bool array, N = 3"):
        sgtllc.precision_recall([0.1, 0.2, 0.3], [True, False])
    with pytest.raises(ValueError, match=r"scores\[1\] is not finite"):
        sgtllc.precision_recall([0.1, float("nan")], [True, False])


def rot_z(deg):
    a = math.radians(deg)
    T = np.eye(4)
    T[:2, :2] = [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]
    return T


def test_pose_error_analytic():
    est = rot_z(3.0)
    est[:3, 3] = [3.0, 4.0, 0.0]
    e = sgtllc.pose_error(est, np.eye(4))
    assert e.translation_m == pytest.approx(5.0) and e.rotation_deg == pytest.approx(3.0)
    assert not e.succeeds(2.0, 5.0) and e.succeeds(6.0, 5.0)
    s = sgtllc.summarise_poses([e, sgtllc.PoseError(1.0, 1.0)])
    assert (s.evaluated, s.successes, s.rte_mean) == (2, 1, 1.0)
    with pytest.raises(ValueError, match=r"estimate: expected a \(4, 4\) float array, got shape \(3, 4\)"):
        sgtllc.pose_error(np.eye(4)[:3], np.eye(4))


def test_trajectory_errors_of_a_shifted_trajectory():
    gt = np.stack([np.eye(4) for _ in range(20)])
    gt[:, 0, 3] = np.arange(20.0)
    est = gt.copy()
    est[:, 1, 3] += 0.5  # a constant offset: aligned ATE 0, unaligned 0.5, RPE 0
    ate = sgtllc.absolute_trajectory_error(gt, est)
    assert ate.aligned.rmse == pytest.approx(0, abs=1e-9) and ate.unaligned.rmse == pytest.approx(0.5)
    np.testing.assert_allclose(ate.T_gt_est[:3, 3], [0, -0.5, 0], atol=1e-9)
    rpe = sgtllc.relative_pose_error(gt, est, 2)
    assert rpe.translation_m.count == 18 and rpe.translation_m.max == pytest.approx(0, abs=1e-12)
    with pytest.raises(ValueError, match=r"expected an \(N, 4, 4\) float array"):
        sgtllc.absolute_trajectory_error(gt[:, :3], est)
    with pytest.raises(sgtllc.Error):
        sgtllc.absolute_trajectory_error(gt, est[:5])


def test_relocalization_metrics_on_a_hand_built_run():
    """Two map frames 10 m apart; a correct relocalization, a wrong frame, a rejected positive and a false one."""
    def pose(x, y):
        T = np.eye(4)
        T[0, 3], T[1, 3] = x, y
        return T

    map_poses = np.stack([pose(0, 0), pose(10, 0)])
    query_poses = np.stack([pose(1, 0), pose(9, 0), pose(0, 2), pose(0, 40)])
    truth = np.linalg.inv(map_poses[0]) @ query_poses[0]
    queries = [
        sgtllc.RelocalizationQuery(0, map_frame=0, accepted=True, T_mapframe_query=truth),  # correct, exact pose
        sgtllc.RelocalizationQuery(1, map_frame=0, accepted=True),  # 9 m from map frame 0: between 3 and 20 m
        sgtllc.RelocalizationQuery(2),  # positive, not accepted
        sgtllc.RelocalizationQuery(3, map_frame=1, accepted=True),  # 40 m from every map frame: false
    ]
    m = sgtllc.relocalization_metrics(queries, map_poses, query_poses)
    assert (m.queries, m.positives, m.negatives, m.accepted) == (4, 3, 1, 3)
    assert (m.accepted_near, m.accepted_between, m.accepted_far, m.accepted_negatives) == (1, 1, 1, 1)
    assert m.recall_at_1 == pytest.approx(1 / 3)
    assert m.precision == pytest.approx(1 / 3)
    assert m.precision_no_between == pytest.approx(1 / 2)
    assert m.pose_success == 1.0
    assert m.rte_mean_m == pytest.approx(0.0, abs=1e-12)
    assert m.false_rate == 1.0
    np.testing.assert_array_equal(queries[0].T_mapframe_query, truth)
    empty = sgtllc.relocalization_metrics([], map_poses, query_poses)
    assert empty.recall_at_1 is None and empty.precision is None and empty.false_rate is None
    with pytest.raises(sgtllc.Error, match="relocalization query 7: no ground-truth pose"):
        sgtllc.relocalization_metrics([sgtllc.RelocalizationQuery(7)], map_poses, query_poses)
