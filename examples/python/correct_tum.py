#!/usr/bin/env python3
"""Corrects another SLAM system's trajectory with sgtllc's loop closures, frame by frame.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/correct_tum.py NODE_DIR POSES.tum OUT.tum \
        [--config FILE] [--online]

POSES.tum is a TUM file (`stamp x y z qx qy qz qw`, one LiDAR pose per line) as KISS-ICP, FAST-LIO or LIO-SAM
write it; NODE_DIR holds one node file NAME.txt (`x y z label` rows) per line of it, in name order, e.g. the
objects of an instance segmentation (scans work the same way with add_scan). Each pose is handed to
sgtllc.LoopClosingPipeline as it arrives, with online=True re-solved at every loop as a running system would;
OUT.tum gets the corrected poses with the same stamps: what `sgtllc run --nodes NODE_DIR --odometry POSES.tum
--out-trajectory OUT.tum` writes.
"""
import argparse
import os

import numpy as np

import sgtllc


def pose_from_tum(row):
    """(4, 4) pose of a TUM row's x y z qx qy qz qw."""
    x, y, z, qx, qy, qz, qw = row
    n = np.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    qx, qy, qz, qw = qx / n, qy / n, qz / n, qw / n
    T = np.eye(4)
    T[:3, :3] = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                 [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                 [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
    T[:3, 3] = [x, y, z]
    return T


def tum_from_pose(T):
    """x y z qx qy qz qw of a (4, 4) pose (quaternion with qw >= 0)."""
    R = T[:3, :3]
    # The largest of 4w², 4x², 4y², 4z² gives the best-conditioned formula.
    w2, x2, y2, z2 = 1 + np.trace(R), 1 + R[0, 0] - R[1, 1] - R[2, 2], 1 - R[0, 0] + R[1, 1] - R[2, 2], \
        1 - R[0, 0] - R[1, 1] + R[2, 2]
    k = int(np.argmax([w2, x2, y2, z2]))
    s = 2 * np.sqrt([w2, x2, y2, z2][k])
    if k == 0:
        q = [(R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s, s / 4]
    elif k == 1:
        q = [s / 4, (R[0, 1] + R[1, 0]) / s, (R[0, 2] + R[2, 0]) / s, (R[2, 1] - R[1, 2]) / s]
    elif k == 2:
        q = [(R[0, 1] + R[1, 0]) / s, s / 4, (R[1, 2] + R[2, 1]) / s, (R[0, 2] - R[2, 0]) / s]
    else:
        q = [(R[0, 2] + R[2, 0]) / s, (R[1, 2] + R[2, 1]) / s, s / 4, (R[1, 0] - R[0, 1]) / s]
    if q[3] < 0:
        q = [-c for c in q]
    return [*T[:3, 3], *q]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("nodes", help="folder of node files NAME.txt, one per pose")
    parser.add_argument("poses", help="TUM trajectory: stamp x y z qx qy qz qw")
    parser.add_argument("out", help="corrected TUM trajectory to write")
    parser.add_argument("--config", help="YAML configuration (see `sgtllc config`)")
    parser.add_argument("--online", action="store_true", help="re-solve at every loop, as a running system")
    args = parser.parse_args()

    config = sgtllc.Config.from_yaml(args.config) if args.config else sgtllc.Config()
    names = sorted(f[:-4] for f in os.listdir(args.nodes) if f.endswith(".txt"))
    rows = np.loadtxt(args.poses, comments="#", ndmin=2)
    if rows.shape != (len(names), 8):
        raise SystemExit(f"{args.poses}: {rows.shape[0]} rows of {rows.shape[1]} columns; expected "
                         f"{len(names)} rows (one per node file) of 8")

    pipeline = sgtllc.LoopClosingPipeline(config, online=args.online)
    for name, row in zip(names, rows):  # as the poses arrive
        centres, classes = sgtllc.read_nodes(os.path.join(args.nodes, name + ".txt"), config)
        frame = pipeline.add_nodes(centres, classes, pose=pose_from_tum(row[1:]), name=name)
        if frame.solved:
            print(f"loop {frame.loop.query} -> {frame.loop.match}: re-solved, {frame.update.num_accepted} loops "
                  f"accepted so far")
    closing = pipeline.finish()
    with open(args.out, "w") as out:
        for stamp, T in zip(rows[:, 0], closing.poses):
            out.write(" ".join(repr(float(v)) for v in [stamp, *tum_from_pose(T)]) + "\n")
    print(f"{len(names)} frames, {len(pipeline.loops)} loops, {closing.result.num_accepted} accepted; wrote {args.out}")


if __name__ == "__main__":
    main()
