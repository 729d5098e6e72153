"""Maps from Python (docs/map-format.md): a detector's frames saved and loaded back exactly, a second session
relocalized in them with its true pose, a resumed detector equal to one run, and clean refusals."""
import numpy as np
import pytest

import sgtllc
from conftest import KITTI

RNG = np.random.default_rng(7)
WORLD = np.column_stack([RNG.uniform(-110, 110, 400), RNG.uniform(-110, 110, 400), RNG.uniform(0, 6, 400)])
CLASSES = RNG.integers(0, 7, 400)


def pose(i, offset=0.0, phase=0.0):
    """Frame i of a circular route, 100 frames a lap (frame 100 + k revisits frame k)."""
    a = phase + 2 * np.pi * i / 100
    T = np.eye(4)
    c, s = np.cos(a + np.pi / 2), np.sin(a + np.pi / 2)
    T[:3, :3] = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    T[:3, 3] = [(60 + offset) * np.cos(a), (60 + offset) * np.sin(a), 1.7]
    return T


def frame(T, rng):
    seen = np.linalg.norm(WORLD[:, :2] - T[:2, 3], axis=1) <= 35
    inv = np.linalg.inv(T)
    centres = WORLD[seen] @ inv[:3, :3].T + inv[:3, 3] + rng.normal(0, 0.03, (seen.sum(), 3))
    return centres, CLASSES[seen]


def config():
    c = sgtllc.Config()
    c.retrieval.exclude_recent = 20
    return c


def session(n, offset=0.0, phase=0.0, seed=1):
    rng = np.random.default_rng(seed)
    poses = [pose(i, offset, phase) for i in range(n)]
    return poses, [frame(T, rng) for T in poses]


def test_save_load_localize(tmp_path):
    poses, frames = session(100)
    detector = sgtllc.LoopDetector(config())
    for centres, classes in frames:
        detector.process_nodes(centres, classes)
    names = [f"{i:06d}" for i in range(100)]
    m = detector.to_map(names, np.array(poses))
    path = tmp_path / "m.sgtmap"
    m.save(str(path))
    with pytest.raises(sgtllc.Error, match="file exists"):
        m.save(str(path))
    loaded = sgtllc.load_map(str(path), config())
    assert loaded.num_frames == 100 and loaded.names == names and loaded.has_poses
    np.testing.assert_array_equal(loaded.poses, np.array(poses))
    for f in (0, 57, 99):
        for a, b in zip(loaded.nodes(f), detector.nodes(f)):
            np.testing.assert_array_equal(a, b)

    second_poses, second = session(20, offset=3.0, phase=0.9, seed=99)
    in_memory, from_file = sgtllc.Relocalizer(m, config()), sgtllc.Relocalizer(loaded, config())
    localized = 0
    for T, (centres, classes) in zip(second_poses, second):
        a, b = in_memory.localize_nodes(centres, classes), from_file.localize_nodes(centres, classes)
        assert (a.map_frame, a.score, a.localized) == (b.map_frame, b.score, b.localized)
        np.testing.assert_array_equal(a.T_mapframe_query, b.T_mapframe_query)
        if a.localized:
            localized += 1
            assert np.linalg.norm(a.T_world_query[:3, 3] - T[:3, 3]) < 0.3
    assert localized >= 18


def test_shortlist_and_tracker():
    poses, frames = session(100)
    detector = sgtllc.LoopDetector(config())
    for centres, classes in frames:
        detector.process_nodes(centres, classes)
    m = detector.to_map([f"{i:06d}" for i in range(100)], np.array(poses))
    second_poses, second = session(10, offset=3.0, phase=0.9, seed=99)
    wide, own = sgtllc.Relocalizer(m, config()), sgtllc.Relocalizer(m, config(), num_candidates=0)

    def retrieved(r):  # the top-1's map neighbours added by verification.neighbour_frames are not counted
        return sum(c.retrieved for c in r.localize_nodes(*second[0]).search.candidates)
    assert retrieved(wide) == 50
    assert retrieved(own) == config().retrieval.num_candidates
    # The rotation check: 0 turns it off, 90 degrees or more is refused.
    unchecked = sgtllc.Relocalizer(m, config(), max_rotation_uncertainty_deg=0.0)
    assert unchecked.localize_nodes(*second[0]).localized >= wide.localize_nodes(*second[0]).localized
    with pytest.raises(sgtllc.Error, match="max_rotation_uncertainty_deg"):
        sgtllc.Relocalizer(m, config(), max_rotation_uncertainty_deg=90.0)
    tracker = sgtllc.RelocalizationTracker(wide, window=5)
    for T, (centres, classes) in zip(second_poses, second):
        r, alone = tracker.localize_nodes(centres, classes), wide.localize_nodes(centres, classes)
        if alone.localized:  # an answer above sigma_4 is the same in the stream
            assert not r.tracked and r.map_frame == alone.map_frame
        if r.localized:
            assert np.linalg.norm(r.T_world_query[:3, 3] - T[:3, 3]) < 0.3
    tracker.reset()
    with pytest.raises(sgtllc.Error, match="gate_m"):
        sgtllc.RelocalizationTracker(wide, gate_m=0.0)


def test_resume_equals_one_run():
    _, frames = session(130)
    one = sgtllc.LoopDetector(config())
    whole = [one.process_nodes(c, k) for c, k in frames]
    head = sgtllc.LoopDetector(config())
    for c, k in frames[:70]:
        head.process_nodes(c, k)
    resumed = sgtllc.LoopDetector(head.to_map(), config())
    assert resumed.num_frames == 70
    for i, (c, k) in enumerate(frames[70:], start=70):
        r = resumed.process_nodes(c, k)
        assert (r.frame, r.is_loop, r.match_frame, r.score) == (whole[i].frame, whole[i].is_loop,
                                                                 whole[i].match_frame, whole[i].score)


def test_bad_maps_are_refused(tmp_path):
    _, frames = session(3)
    detector = sgtllc.LoopDetector(config())
    for c, k in frames:
        detector.process_nodes(c, k)
    with pytest.raises(sgtllc.Error, match="used twice"):
        detector.to_map(["a", "b", "a"])
    path = tmp_path / "m.sgtmap"
    detector.to_map().save(str(path))
    data = path.read_bytes()
    (tmp_path / "cut.sgtmap").write_bytes(data[: len(data) // 2])
    with pytest.raises(sgtllc.Error, match="cut.sgtmap: truncated map file"):
        sgtllc.load_map(str(tmp_path / "cut.sgtmap"))
    other = config()
    other.retrieval.histogram_bins = 12
    with pytest.raises(sgtllc.Error, match="retrieval.histogram_bins: the map was built with 30"):
        sgtllc.load_map(str(path), other)
    with pytest.raises(FileNotFoundError):
        sgtllc.load_map(str(tmp_path / "none.sgtmap"))


def test_scans_keep_their_footprints_in_the_map(tmp_path):
    # KITTI 00 frames 52 and 88 as scans: the map keeps their footprints, through a file too, and relocalizing
    # scan 4501 checks its structure against frame 52's (share above 0.9); a map of nodes has none.
    def scan(name):
        path = KITTI / "velodyne" / f"{name}.bin"
        return sgtllc.read_kitti_bin(str(path)), sgtllc.read_labels(sgtllc.default_label_path(str(path)))

    detector = sgtllc.LoopDetector()
    for name in ("000052", "000088"):
        detector.process(*scan(name))
    m = detector.to_map(["000052", "000088"])
    assert m.has_footprints
    path = tmp_path / "scans.sgtmap"
    m.save(str(path))
    loaded = sgtllc.load_map(str(path))
    assert loaded.has_footprints
    r = sgtllc.Relocalizer(loaded).localize(*scan("004501"))
    assert r.localized and r.map_frame == 0
    best = r.search.candidates[r.search.best]
    assert best.match.footprint.compared > 200 and best.match.footprint.share > 0.9
    assert not sgtllc.LoopDetector().to_map([]).has_footprints
