#!/usr/bin/env python3
"""How much the geometric labeller's classes and nodes depend on the heading a scan is taken at.

A spinning LiDAR at one spot sees the same scene whatever the car's heading: a scan yawed about the sensor's
vertical axis is what that sensor would give there facing another way (less the seam and the car's own shadow). A
labeller whose classes repeat from any heading gives the yawed scan the same classes and nodes; one that does not
fails at every revisit with a turn (docs/labeller.md §4, "Cut by the view's top"). For each real scan and each yaw
this prints the per-class IoU of the two labellings (the points are the same, in the same order), the share of
nodes repeated within 0.5 m (nodes of the yawed scan turned back) and whether `compare_pair` of the scan against
its yawed self is a loop, with its inliers.

    scripts/yaw-stability.py [--yaw 1,5,62,175] [--config C.yaml] SCAN.bin ...

Needs numpy and the sgtllc module (build/python on PYTHONPATH, or installed).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "python"))
import sgtllc  # noqa: E402

NAMES = {0: "building", 1: "fence", 2: "vegetation", 5: "pole"}


def yawed(points, deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    out = points.copy()
    out[:, 0] = c * points[:, 0] - s * points[:, 1]
    out[:, 1] = s * points[:, 0] + c * points[:, 1]
    return out


def yaw_matrix(deg):
    a = math.radians(deg)
    T = np.eye(4)
    T[:2, :2] = [[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]
    return T


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scans", nargs="+")
    ap.add_argument("--yaw", default="1,5,62,175", help="yaws in degrees, comma-separated")
    ap.add_argument("--config", help="YAML configuration (labeller.* and the detector's settings)")
    ap.add_argument("--per-scan", action="store_true", help="a line per scan and yaw")
    args = ap.parse_args()
    yaws = [float(y) for y in args.yaw.split(",")]
    config = sgtllc.Config.from_yaml(args.config) if args.config else sgtllc.Config()
    config.labeller.source = sgtllc.LabelSource.GEOMETRIC
    inter = {y: {c: 0 for c in NAMES} for y in yaws}
    union = {y: {c: 0 for c in NAMES} for y in yaws}
    rep = {y: [0, 0] for y in yaws}
    rep_class = {y: {c: [0, 0] for c in NAMES} for y in yaws}
    loops = {y: [0, 0, []] for y in yaws}

    for path in args.scans:
        points = sgtllc.read_kitti_bin(path)[:, :3].copy()
        dummy = np.zeros(len(points), dtype=np.uint32)
        c0, _ = sgtllc.label_scan(points, config.labeller)
        for y in yaws:
            q = yawed(points, y)
            c1, _ = sgtllc.label_scan(q, config.labeller)
            for c in NAMES:
                a, b = c0 == c, c1 == c
                inter[y][c] += int((a & b).sum())
                union[y][c] += int((a | b).sum())
            pair = sgtllc.compare_pair(q, sgtllc.apply_labeller(q, dummy, config), points,
                                       sgtllc.apply_labeller(points, dummy, config), config)
            (ca, ka), (cb, kb) = pair.query_nodes, pair.match_nodes
            r = sgtllc.node_repeatability(ca, ka, cb, kb, np.linalg.inv(yaw_matrix(y)))
            for c in NAMES:
                rep_class[y][c][0] += int(r.repeated[c])
                rep_class[y][c][1] += int(r.nodes[c])
            rep[y][0] += int(np.sum(r.repeated))
            rep[y][1] += int(np.sum(r.nodes))
            loops[y][0] += int(pair.is_loop)
            loops[y][1] += 1
            loops[y][2].append(len(pair.match.inliers))
            if args.per_scan:
                print(f"{os.path.basename(path)} yaw {y:g}: repeated {int(np.sum(r.repeated))} of "
                      f"{int(np.sum(r.nodes))}, loop {pair.is_loop}, inliers {len(pair.match.inliers)}")
    print("yaw | " + " | ".join(f"IoU {n}" for n in NAMES.values()) + " | nodes repeated | loops | median inliers"
          " | nodes repeated by class")
    for y in yaws:
        ious = [inter[y][c] / union[y][c] if union[y][c] else float("nan") for c in NAMES]
        print(f"{y:g} | " + " | ".join(f"{v:.3f}" for v in ious) +
              f" | {rep[y][0] / max(1, rep[y][1]):.3f} ({rep[y][0]} of {rep[y][1]}) | {loops[y][0]} of {loops[y][1]}"
              f" | {float(np.median(loops[y][2])):.0f} | " +
              ", ".join(f"{NAMES[c]} {rep_class[y][c][0]}/{rep_class[y][c][1]}" for c in NAMES))


if __name__ == "__main__":
    main()
