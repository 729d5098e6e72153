"""sgtllc.SessionPipeline (docs/sessions.md) on the bundled KITTI 00 scans: a map of frames 52, 88 and 850 at their
ground-truth poses, and frame 4501 (a revisit of 52) as a new session whose odometry starts at the identity; the
merge places it at its ground-truth pose."""
import numpy as np
import pytest

import sgtllc
from conftest import KITTI

MAP_FRAMES = ["000052", "000088", "000850"]


def config(min_inter_loops=1, keep_distance_m=3.0):
    c = sgtllc.Config()
    c.retrieval.exclude_recent = 1
    c.backend.sessions.min_inter_loops = min_inter_loops  # one frame: one inter-session loop at most
    c.backend.sessions.keep_distance_m = keep_distance_m
    return c


def truth():
    return sgtllc.read_poses(str(KITTI / "poses.txt"), str(KITTI / "calib.txt"))


def kitti_map(c):
    seq = sgtllc.SequenceDir(str(KITTI))
    pipeline = sgtllc.LoopClosingPipeline(c)
    for i in range(len(seq)):
        if seq.frame_name(i) in MAP_FRAMES:
            pipeline.add_scan(*seq.load(i), name=seq.frame_name(i))
    poses = truth()[[int(f) for f in MAP_FRAMES]]
    return pipeline.to_map(poses), seq


@pytest.mark.parametrize("keep_distance_m", [0.0, 3.0])
def test_a_session_of_one_revisit_is_placed_at_its_true_pose(keep_distance_m):
    c = config(keep_distance_m=keep_distance_m)
    m, seq = kitti_map(c)
    session = sgtllc.SessionPipeline(m, c, name="later", map_session="first")
    i = [seq.frame_name(k) for k in range(len(seq))].index("004501")
    frame = session.add_scan(*seq.load(i), pose=np.eye(4), name="004501")
    assert frame.in_map.localized and frame.loop is None
    assert (frame.inter.query, frame.inter.match, frame.inter.edge.from_, frame.inter.edge.to) == ("later/004501", "000052", 0, 3)
    np.testing.assert_array_equal(session.poses, np.eye(4)[None])  # before the merge: the odometry
    closing = session.finish()
    assert closing.merge.placed and closing.merge.inter_accepted == 1
    error = np.linalg.inv(truth()[4501]) @ session.poses[0]
    assert np.linalg.norm(error[:3, 3]) < 0.3
    assert np.degrees(np.arccos(np.clip((np.trace(error[:3, :3]) - 1) / 2, -1, 1))) < 2.0
    merged = session.merged_map()
    if keep_distance_m == 0.0:  # every frame joins
        assert merged.num_frames == 4 and merged.names[3] == "later/004501"
        assert merged.sessions == [("first", 0, 3), ("later", 3, 1)]
        np.testing.assert_array_equal(merged.poses[3], session.poses[0])
    else:  # the map recognised 4501 and has 52 2.96 m away facing its way: the map already has the place
        assert merged.num_frames == 3
        assert merged.sessions == [("first", 0, 3), ("later", 3, 0)]


def test_too_few_inter_session_loops_leave_the_session_out(tmp_path):
    c = config(min_inter_loops=2)
    m, seq = kitti_map(c)
    session = sgtllc.SessionPipeline(m, c, name="later")
    i = [seq.frame_name(k) for k in range(len(seq))].index("004501")
    session.add_scan(*seq.load(i), pose=np.eye(4))
    assert not session.finish().merge.placed
    with pytest.raises(sgtllc.Error, match="not placed"):
        session.merged_map()
    with pytest.raises(sgtllc.Error, match="already has a session"):
        sgtllc.SessionPipeline(m, c, name="map")
    m.save(str(tmp_path / "m.sgtmap"))
    assert sgtllc.load_map(str(tmp_path / "m.sgtmap")).sessions == []


def test_a_loop_from_elsewhere_is_merged_with_the_detected_ones():
    c = config()
    m, seq = kitti_map(c)
    session = sgtllc.SessionPipeline(m, c, name="later")
    i = [seq.frame_name(k) for k in range(len(seq))].index("004501")
    frame = session.add_scan(*seq.load(i), pose=np.eye(4))
    # The same tie again, as another place recognition would give it; then two false ones, a map frame far away.
    e = frame.inter.edge
    session.add_loop(sgtllc.Edge(e.from_, e.to, e.T_from_to, e.information), "later/004501", "000052")
    with pytest.raises(sgtllc.Error, match="two map frames"):
        session.add_loop(sgtllc.Edge(0, 1, np.eye(4)))
    with pytest.raises(sgtllc.Error, match="of 0..2 \\(the map's\\) and 3..3"):
        session.add_loop(sgtllc.Edge(0, 4, np.eye(4)))  # session frame 1 was not added
    for t in ([7.0, -3.0, 0.0], [-20.0, 5.0, 0.0]):  # two that disagree with each other too
        far = np.eye(4)
        far[:3, 3] = t
        session.add_loop(sgtllc.Edge(2, 3, far, e.information), "later/004501", "000850", injected=True)
    assert [l.injected for l in session.loops] == [False, False, True, True]
    closing = session.finish()
    assert closing.merge.placed and closing.merge.inter_accepted == 2
    decisions = [d.decision for d in closing.merge.result.loops]
    assert decisions == [sgtllc.LoopDecision.ACCEPTED] * 2 + [sgtllc.LoopDecision.INCONSISTENT] * 2
    with pytest.raises(sgtllc.Error, match="after finish"):
        session.add_loop(sgtllc.Edge(0, 3, np.eye(4)))
