#!/usr/bin/env python3
"""Correct top-1 loops among a sequence's revisit queries, split by the direction of travel: the opposite-direction
revisits of BENCHMARKS.md ("Reverse revisits without labels") come from it.

A query is frame i with an earlier frame j <= i - GAP (the protocol's exclusion, 50) within 3 m; it is an
opposite-direction query when the travel directions at i and j (central differences of poses.txt) point apart
(negative dot product), else a same-direction one. A query is answered correctly when `frames.csv` of
`sgtllc eval SEQ --report DIR` has a loop at it whose match lies within 3 m.

  scripts/reverse-revisits.py SEQ_DIR REPORT_DIR... [--gap 50]
"""
import csv
import sys

import numpy as np


def queries(poses_path, gap):
    rows = np.loadtxt(poses_path).reshape(-1, 3, 4)
    pos = rows[:, :, 3]
    heading = np.zeros_like(pos)
    heading[1:-1] = pos[2:] - pos[:-2]
    heading[0], heading[-1] = pos[1] - pos[0], pos[-1] - pos[-2]
    heading /= np.linalg.norm(heading, axis=1, keepdims=True) + 1e-12
    opposite, same = [], []
    for i in range(gap, len(pos)):
        dist = np.linalg.norm(pos[: i - gap + 1] - pos[i], axis=1)
        j = int(np.argmin(dist))
        if dist[j] < 3.0:
            (opposite if heading[i] @ heading[j] < 0 else same).append(i)
    return opposite, same


def main(argv):
    gap = 50
    if "--gap" in argv:
        k = argv.index("--gap")
        gap = int(argv[k + 1])
        argv = argv[:k] + argv[k + 2:]
    if len(argv) < 3:
        sys.exit(__doc__)
    opposite, same = queries(argv[1] + "/poses.txt", gap)
    print(f"revisit queries within 3 m: {len(opposite)} opposite-direction, {len(same)} same-direction")
    for report in argv[2:]:
        frames = {int(f["frame"]): f for f in csv.DictReader(open(report + "/frames.csv"))}

        def correct(ids):
            return sum(1 for i in ids if frames[i]["loop"] == "1" and float(frames[i]["match_distance_m"]) < 3.0)

        print(f"{report}: correct top-1 {correct(opposite)} opposite-direction, {correct(same)} same-direction")


if __name__ == "__main__":
    main(sys.argv)
