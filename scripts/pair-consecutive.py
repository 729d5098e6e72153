#!/usr/bin/env python3
"""Pairs of real keyframes of KITTI-layout scenes through `sgtllc pair --list --json`: how many pairs are loops, and how
many of those have a pose within 1 m / 5 deg and within 0.3 m / 2 deg of the scenes' own poses (LiDAR poses,
poses.txt). The nuScenes figures of BENCHMARKS.md ("Node repeatability on real scans", "Consistency path") come
from it.

  scripts/pair-consecutive.py SGTLLC SCENE_DIR... [--gap G] [--far | --cross] [-- PAIR_ARGS...]

  --gap G   each keyframe B against the keyframe A = B - G of its scene (default 1)
  --far     instead, pairs of one scene more than 20 m apart (every third A, every second B > A): none is a loop
  --cross   instead, pairs of keyframes of two different scenes (frames 0, 13, 26, 38 against 0, 19, 38)

  e.g. scripts/pair-consecutive.py build/apps/sgtllc/sgtllc nuscenes/0001 nuscenes/0005 -- --config configs/nuscenes.yaml
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

import numpy as np


def poses(scene):
    rows = np.loadtxt(os.path.join(scene, "poses.txt")).reshape(-1, 3, 4)
    out = np.tile(np.eye(4), (len(rows), 1, 1))
    out[:, :3, :] = rows
    return out


def frame(scene, kind, i):
    return os.path.join(scene, kind, f"{i:06d}.{'bin' if kind == 'velodyne' else 'label'}")


def pairs_of(scenes, mode, gap):
    """(query scene, query frame, match scene, match frame, reference T_match_query or None)."""
    out = []
    if mode == "cross":
        for k, a in enumerate(scenes):
            for b in scenes[k + 1:]:
                out += [(a, i, b, j, None) for i in (0, 13, 26, 38) for j in (0, 19, 38)]
        return out
    for scene in scenes:
        p = poses(scene)
        if mode == "far":
            out += [(scene, b, scene, a, None) for a in range(0, len(p), 3) for b in range(a + 1, len(p), 2)
                    if np.linalg.norm(p[a][:3, 3] - p[b][:3, 3]) > 20.0]
        else:
            out += [(scene, b, scene, b - gap, np.linalg.inv(p[b - gap]) @ p[b]) for b in range(gap, len(p))]
    return out


def main(argv):
    args, extra = (argv[1:argv.index("--")], argv[argv.index("--") + 1:]) if "--" in argv else (argv[1:], [])
    mode, gap = "gap", 1
    if "--gap" in args:
        k = args.index("--gap")
        gap = int(args[k + 1])
        args = args[:k] + args[k + 2:]
    for flag in ("--far", "--cross"):
        if flag in args:
            mode = flag[2:]
            args.remove(flag)
    if len(args) < 2:
        sys.exit(__doc__)
    sgtllc, scenes = args[0], args[1:]

    jobs = pairs_of(scenes, mode, gap)
    with tempfile.TemporaryDirectory() as tmp:
        lst = os.path.join(tmp, "pairs.csv")
        with open(lst, "w", newline="") as f:
            rows = csv.writer(f, lineterminator="\n")  # quotes a path that holds a comma or a quote
            for qs, qi, ms, mi, _ in jobs:
                rows.writerow([os.path.abspath(frame(qs, "velodyne", qi)), os.path.abspath(frame(ms, "velodyne", mi))])
        # One process, two pairs at once: one JSON object a line, in the list's order.
        out = subprocess.run([sgtllc, "pair", "--list", lst, "--json", "--threads", "2"] + extra, capture_output=True,
                             text=True)
    if out.returncode != 0:
        sys.exit(out.stderr)
    results = [json.loads(line) for line in out.stdout.splitlines()]
    loops = within_1m = within_03m = by_consistency = 0
    for job, r in zip(jobs, results):
        if not r["loop"]:
            continue
        loops += 1
        by_consistency += r["path"] == "consistency"
        if job[4] is None:
            print(f"loop: {frame(job[0], 'velodyne', job[1])} -> {frame(job[2], 'velodyne', job[3])}")
            continue
        error = np.linalg.inv(job[4]) @ np.array(r["T_match_query"])
        angle = np.degrees(np.arccos(np.clip((np.trace(error[:3, :3]) - 1) / 2, -1, 1)))
        distance = np.linalg.norm(error[:3, 3])
        within_1m += distance <= 1.0 and angle <= 5.0
        within_03m += distance <= 0.3 and angle <= 2.0
    nodes = np.median([r["nodes_query"] for r in results])
    print(f"pairs {len(jobs)}, median nodes {nodes:g}, loops {loops} ({by_consistency} by the consistency path), "
          f"within 1 m / 5 deg {within_1m}, within 0.3 m / 2 deg {within_03m}")


if __name__ == "__main__":
    main(sys.argv)
