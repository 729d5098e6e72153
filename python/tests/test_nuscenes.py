"""One-byte label files and the nuScenes preset on the real nuScenes-lidarseg frames in data/nuscenes."""
import numpy as np
import pytest

import sgtllc
from conftest import SOURCE

SCENE = SOURCE / "data" / "nuscenes" / "0001"
BIN = SCENE / "velodyne" / "000000.bin"
LABEL = SCENE / "labels" / "000000.label"


def test_one_byte_labels_equal_numpy():
    want = np.fromfile(LABEL, np.uint8).astype(np.uint32)
    points, labels = sgtllc.read_labeled_scan(str(BIN))  # format AUTO: 34,720 bytes for 34,720 points
    np.testing.assert_array_equal(labels, want)
    assert len(points) == 34720
    np.testing.assert_array_equal(sgtllc.read_labels(str(LABEL), point_count=34720), want)
    np.testing.assert_array_equal(sgtllc.read_labels(str(LABEL), format=sgtllc.LabelFormat.UINT8), want)
    with pytest.raises(sgtllc.Error, match="has 34720 bytes, not 138880 .uint32"):
        sgtllc.read_labeled_scan(str(BIN), format=sgtllc.LabelFormat.UINT32)


def test_nuscenes_preset_in_the_config():
    config = sgtllc.Config.from_yaml(str(SOURCE / "configs" / "nuscenes.yaml"))
    assert config.labels.preset == sgtllc.LabelPreset.NUSCENES
    assert config.labels.format == sgtllc.LabelFormat.UINT8
    assert config.labeller.source == sgtllc.LabelSource.HYBRID
    assert sgtllc.Config().labels.format == sgtllc.LabelFormat.AUTO


def test_label_free_pair_verifies_by_consistency():
    # Keyframes 1 and 0 from the scans alone: 5 nodes each, RANSAC on the descriptors' pairs fails, the consistency
    # path (docs/algorithm.md §7.8) verifies 3 nodes whose distances agree; ICP then refines the pose.
    def scan(i):
        points = sgtllc.read_kitti_bin(str(SCENE / "velodyne" / f"{i:06d}.bin"))
        return points, sgtllc.label_scan_ids(points)

    rows = np.loadtxt(SCENE / "poses.txt").reshape(-1, 3, 4)
    poses = [np.vstack([r, [0, 0, 0, 1]]) for r in rows]
    reference = np.linalg.inv(poses[0]) @ poses[1]
    r = sgtllc.compare_pair(*scan(1), *scan(0))
    assert r.is_loop and r.match.by_consistency
    assert len(r.match.inliers) >= 3
    err = sgtllc.pose_error(r.T_match_query, reference)
    assert err.translation_m < 0.3 and err.rotation_deg < 2.0
    off = sgtllc.Config()
    off.verification.consistency_pairs = 0
    paper = sgtllc.compare_pair(*scan(1), *scan(0), off)
    assert not paper.is_loop and not paper.match.by_consistency
    assert paper.rejection == sgtllc.Rejection.RANSAC_FAILED


def test_footprint_search_moves_a_pose_short_along_the_street():
    # Scene 0006, keyframe 2 against 0, 9.7 m apart along a straight street, the dataset's labels: the nodes'
    # inliers are fences and ground centred on what each scan sees, their pose 0.5 m long; the footprint search
    # (docs/algorithm.md §7.9) moves it 10 m, where the structure beside the street agrees.
    scene = SOURCE / "data" / "nuscenes" / "0006"
    config = sgtllc.Config.from_yaml(str(SOURCE / "configs" / "nuscenes.yaml"))
    config.labeller.source = sgtllc.LabelSource.FILE

    def scan(i):
        return sgtllc.read_labeled_scan(str(scene / "velodyne" / f"{i:06d}.bin"))

    rows = np.loadtxt(scene / "poses.txt").reshape(-1, 3, 4)
    poses = [np.vstack([r, [0, 0, 0, 1]]) for r in rows]
    reference = np.linalg.inv(poses[0]) @ poses[2]
    r = sgtllc.compare_pair(*scan(2), *scan(0), config)
    assert r.is_loop
    search = r.match.footprint_search
    assert search.shift == pytest.approx((0.0, 10.0))
    assert search.share > search.unshifted_share + config.verification.footprint_search_gain
    assert np.linalg.norm(r.T_match_query[:2, 3] - reference[:2, 3]) < 0.3
    config.verification.footprint_search = 0.0
    before = sgtllc.compare_pair(*scan(2), *scan(0), config)
    assert before.is_loop and before.match.footprint_search.compared == 0
    assert np.linalg.norm(before.T_match_query[:2, 3] - reference[:2, 3]) > 8.0


def test_covisible_score_counts_only_what_the_other_scan_could_see():
    # The same pair: the match scan has 11 nodes, the query 9. Counting only the nodes the pose puts within the other
    # scan's reach (configs/nuscenes.yaml; docs/algorithm.md §7.3) leaves out match nodes beyond the query's
    # farthest one, and the 4 inliers are divided by 9 instead of 11.
    scene = SOURCE / "data" / "nuscenes" / "0006"
    config = sgtllc.Config.from_yaml(str(SOURCE / "configs" / "nuscenes.yaml"))
    config.labeller.source = sgtllc.LabelSource.FILE
    assert config.verification.score_covisible and not sgtllc.Config().verification.score_covisible

    def scan(i):
        return sgtllc.read_labeled_scan(str(scene / "velodyne" / f"{i:06d}.bin"))

    covisible = sgtllc.compare_pair(*scan(2), *scan(0), config)
    config.verification.score_covisible = False
    every = sgtllc.compare_pair(*scan(2), *scan(0), config)
    assert [len(covisible.query_nodes[1]), len(covisible.match_nodes[1])] == [9, 11]
    assert len(covisible.match.inliers) == len(every.match.inliers) == 4
    assert covisible.match.score == pytest.approx(4 / 9)
    assert every.match.score == pytest.approx(4 / 11)
