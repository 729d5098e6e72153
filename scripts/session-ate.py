#!/usr/bin/python3
"""Trajectory errors of merged sessions (docs/sessions.md) against the simulator's ground truth.

    scripts/session-ate.py S1 T1.txt [S2 T2.txt LOOPS2.csv RUN2.json]...

S1: the first session's folder (poses.txt, calib.txt) and T1 its corrected trajectory (`run --out-trajectory`); then
per later session its folder (poses.txt in S1's frame, cross_session.txt), its merged trajectory (`run --map
--out-trajectory`), its loops CSV (`run --map --out`) and the run's `--json` output (each loop's decision). All trajectories are KITTI cam0 files, as the simulator's
odometry. Prints every session's ATE after one rigid alignment of all sessions together onto the truth (and without
it: the map's frame is the truth's), the inter-session loops whose pose is more than 1 m or 5 degrees off the truth,
and the error by distance to the nearest first-session frame. A later session's frames are named FOLDER/NNNNNN (the
default session name: the folder's name), so a loop into an earlier session's frame is judged by that session's
truth.
"""
import csv
import json
import os
import sys

import numpy as np


def kitti_poses(path):
    rows = np.loadtxt(path, ndmin=2)
    poses = np.tile(np.eye(4), (len(rows), 1, 1))
    poses[:, :3, :] = rows.reshape(-1, 3, 4)
    return poses


def calib_tr(path):
    for line in open(path):
        if line.startswith("Tr:"):
            tr = np.eye(4)
            tr[:3, :] = np.array(line.split()[1:], dtype=float).reshape(3, 4)
            return tr
    raise SystemExit(path + ": no Tr line")


def rigid_alignment(estimate, truth):
    """R, t minimising |R e + t - truth| over the positions (Kabsch, no scale)."""
    mu_e, mu_t = estimate.mean(0), truth.mean(0)
    u, _, vt = np.linalg.svd((estimate - mu_e).T @ (truth - mu_t))
    d = np.eye(3)
    d[2, 2] = np.sign(np.linalg.det(vt.T @ u.T))
    r = vt.T @ d @ u.T
    return r, mu_t - r @ mu_e


def rms(v):
    return float(np.sqrt((np.linalg.norm(v, axis=1) ** 2).mean()))


def main(argv):
    if len(argv) < 2 or (len(argv) - 2) % 4:
        raise SystemExit(__doc__)
    tr = calib_tr(argv[0] + "/calib.txt")
    to_lidar = lambda poses: np.linalg.inv(tr) @ poses @ tr
    map_truth, map_est = to_lidar(kitti_poses(argv[0] + "/poses.txt")), to_lidar(kitti_poses(argv[1]))
    sessions = []
    for k in range(2, len(argv), 4):
        folder, trajectory, loops, run = argv[k:k + 4]
        decisions = [l["decision"] for l in json.load(open(run))["loop_list"]]
        sessions.append((folder, to_lidar(kitti_poses(folder + "/poses.txt")), to_lidar(kitti_poses(trajectory)), loops,
                         decisions))
    truth_of = {"%06d" % i: T for i, T in enumerate(map_truth)}
    for folder, s_truth, _, _, _ in sessions:
        name = os.path.basename(os.path.normpath(folder))
        truth_of.update({"%s/%06d" % (name, i): T for i, T in enumerate(s_truth)})
    estimate = np.vstack([map_est[:, :3, 3]] + [s[2][:, :3, 3] for s in sessions])
    truth = np.vstack([map_truth[:, :3, 3]] + [s[1][:, :3, 3] for s in sessions])
    r, t = rigid_alignment(estimate, truth)
    aligned = lambda p: p @ r.T + t
    print("%s: %d frames, ATE %.3f m (all sessions aligned together), %.3f m unaligned" %
          (argv[0], len(map_est), rms(aligned(map_est[:, :3, 3]) - map_truth[:, :3, 3]),
           rms(map_est[:, :3, 3] - map_truth[:, :3, 3])))
    for folder, s_truth, s_est, loops, decisions in sessions:
        error = aligned(s_est[:, :3, 3]) - s_truth[:, :3, 3]
        print("%s: %d frames, ATE %.3f m (aligned), %.3f m unaligned" %
              (folder, len(s_est), rms(error), rms(s_est[:, :3, 3] - s_truth[:, :3, 3])))
        inter = wrong = accepted = wrong_accepted = 0
        name = os.path.basename(os.path.normpath(folder))
        for k, row in enumerate(csv.DictReader(open(loops))):
            if row["match"].startswith(name + "/"):
                continue  # an intra-session loop
            query = int(row["query"].rsplit("/", 1)[1])
            loop = np.eye(4)
            loop[:3, :] = np.array([float(row[c]) for c in
                                    "r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz".split()]).reshape(3, 4)
            off = np.linalg.inv(np.linalg.inv(truth_of[row["match"]]) @ s_truth[query]) @ loop
            angle = np.degrees(np.arccos(np.clip((np.trace(off[:3, :3]) - 1) / 2, -1, 1)))
            bad = np.linalg.norm(off[:3, 3]) > 1.0 or angle > 5.0
            inter += 1
            wrong += bad
            accepted += decisions[k] == "accepted"
            wrong_accepted += bad and decisions[k] == "accepted"
        print("  inter-session loops found %d, accepted %d; pose off by > 1 m or 5 deg: %d, of them accepted %d" %
              (inter, accepted, wrong, wrong_accepted))
        nearest = np.loadtxt(folder + "/cross_session.txt", ndmin=2)[:, 2]
        for lo, hi in ((0, 3), (3, 20), (20, np.inf)):
            sel = (nearest >= lo) & (nearest < hi)
            if sel.any():
                e = np.linalg.norm(error[sel], axis=1)
                print("  frames %g-%g m from the first session: %d, error median %.3f m, p90 %.3f m, max %.3f m" %
                      (lo, hi, sel.sum(), np.median(e), np.percentile(e, 90), e.max()))


if __name__ == "__main__":
    main(sys.argv[1:])
