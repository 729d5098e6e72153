#!/usr/bin/env python3
"""Consecutive keyframes of KITTI-layout scenes through `sgtllc pair --json`: how many pairs verify, and how many
of those have a pose within 1 m / 5 deg of the scenes' own poses (LiDAR poses, poses.txt). The nuScenes figures
of BENCHMARKS.md ("Node repeatability on real scans") come from it.

  scripts/pair-consecutive.py SGTLLC SCENE_DIR... [-- PAIR_ARGS...]
  e.g. scripts/pair-consecutive.py build/apps/sgtllc/sgtllc nuscenes/0001 nuscenes/0005 -- --config configs/nuscenes.yaml
"""
import glob
import json
import os
import subprocess
import sys

import numpy as np


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    sgtllc, rest = argv[1], argv[2:]
    scenes, extra = (rest[:rest.index("--")], rest[rest.index("--") + 1:]) if "--" in rest else (rest, [])
    geometric = "geometric" in extra
    pairs = loops = good = 0
    nodes = []
    for scene in scenes:
        rows = np.loadtxt(os.path.join(scene, "poses.txt")).reshape(-1, 3, 4)
        poses = np.tile(np.eye(4), (len(rows), 1, 1))
        poses[:, :3, :] = rows
        bins = sorted(glob.glob(os.path.join(scene, "velodyne", "*.bin")))
        for a, b in zip(bins[:-1], bins[1:]):
            ia, ib = (int(os.path.basename(p)[:-4]) for p in (a, b))
            labels = [] if geometric else [
                "--labels-query", os.path.join(scene, "labels", f"{ib:06d}.label"),
                "--labels-match", os.path.join(scene, "labels", f"{ia:06d}.label")]
            out = subprocess.run([sgtllc, "pair", b, a, "--json"] + labels + extra, capture_output=True, text=True)
            if out.returncode != 0:
                sys.exit(out.stderr)
            r = json.loads(out.stdout)
            pairs += 1
            nodes.append(r["nodes_query"])
            if not r["loop"]:
                continue
            loops += 1
            error = np.linalg.inv(np.linalg.inv(poses[ia]) @ poses[ib]) @ np.array(r["T_match_query"])
            angle = np.degrees(np.arccos(np.clip((np.trace(error[:3, :3]) - 1) / 2, -1, 1)))
            good += np.linalg.norm(error[:3, 3]) <= 1.0 and angle <= 5.0
    print(f"pairs {pairs}, median nodes {np.median(nodes):g}, loops {loops}, within 1 m / 5 deg {good}")


if __name__ == "__main__":
    main(sys.argv)
