#!/usr/bin/env python3
"""Runs the online loop detector over a SemanticKITTI-layout sequence and plots its precision-recall curve.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/run_sequence.py SEQ_DIR [--config FILE] [--plot pr.png]

SEQ_DIR holds velodyne/NNNNNN.bin, labels/NNNNNN.label and poses.txt (+ calib.txt), e.g. a sequence written by
`sgtllc simulate --out SEQ_DIR --frames 600 --seed 1` (one revisit, 1.5 GB; 300 frames are too short for any).
A detected loop is a true positive if the two frames are within --max-distance metres in the ground truth (the
protocol of `sgtllc eval`, top-1 per query). The plot needs matplotlib (Debian: python3-matplotlib); without it
the curve's summary is printed only.
"""
import argparse
import os

import numpy as np

import sgtllc


def plot_points(curve):
    """The curve's (recall, precision) in plotting order: recall ascending from the point (0, 1).

    precision_recall lists its points highest threshold first (recall ascending) and appends (recall 0,
    precision 1) last, as sklearn does; drawn in that order the appended point closes the curve into a box.
    """
    recall = np.concatenate(([0.0], np.asarray(curve.recall)[:-1]))
    precision = np.concatenate(([1.0], np.asarray(curve.precision)[:-1]))
    return recall, precision


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sequence")
    parser.add_argument("--config", help="YAML configuration (see `sgtllc config`)")
    parser.add_argument("--max-distance", type=float, default=4.0, help="true loop: frames this close (m)")
    parser.add_argument("--plot", default="pr_curve.png", help="PNG to write the PR curve to")
    args = parser.parse_args()

    config = sgtllc.Config.from_yaml(args.config) if args.config else sgtllc.Config()
    seq = sgtllc.SequenceDir(args.sequence)
    # KITTI's poses.txt is in cam0: calib.txt's Tr brings it into the LiDAR frame (without one, the motion decides).
    calib = os.path.join(args.sequence, "calib.txt")
    poses = sgtllc.read_poses(os.path.join(args.sequence, "poses.txt"), calib if os.path.exists(calib) else None)
    # Frame i of the folder is line int(NAME) of poses.txt (a folder may hold a subset, as data/kitti/00 does).
    positions = poses[[int(seq.frame_name(i)) for i in range(len(seq))], :3, 3]

    detector = sgtllc.LoopDetector(config)
    scores, correct, has_revisit = [], [], 0
    for i in range(len(seq)):
        result = detector.process(*seq.load(i))
        # Ground truth: any frame old enough to be searched within max_distance is a revisit.
        old = positions[: max(0, i - config.retrieval.exclude_recent + 1)]
        revisit = len(old) > 0 and np.linalg.norm(old - positions[i], axis=1).min() < args.max_distance
        has_revisit += bool(revisit)
        if result.match_frame >= 0:
            scores.append(result.score)
            correct.append(np.linalg.norm(positions[result.match_frame] - positions[i]) < args.max_distance)
        if result.is_loop:
            t = result.T_match_query[:3, 3]
            print(f"loop {seq.frame_name(i)} -> {seq.frame_name(result.match_frame)}  score {result.score:.3f}"
                  f"  t = ({t[0]:.2f}, {t[1]:.2f}, {t[2]:.2f}) m")

    if not scores or has_revisit == 0:
        print(f"{len(seq)} frames: no queries with a ground-truth revisit, nothing to score")
        return
    curve = sgtllc.precision_recall(scores, correct, positives_override=has_revisit)
    print(f"{len(seq)} frames, {has_revisit} with a revisit: F1max {sgtllc.f1_max(curve):.3f}, "
          f"EP {sgtllc.extended_precision(curve):.3f}, R@100%P {sgtllc.recall_at_100_precision(curve):.3f}")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (Debian: python3-matplotlib): no plot")
        return
    recall, precision = plot_points(curve)
    fig, ax = plt.subplots(figsize=(5, 4))
    # As sklearn's PrecisionRecallDisplay: between two recalls, the precision of the point at the higher one.
    ax.plot(recall, precision, drawstyle="steps-pre")
    ax.set(xlabel="recall", ylabel="precision", xlim=(0, 1.02), ylim=(0, 1.02), title=os.path.basename(args.sequence))
    fig.tight_layout()
    fig.savefig(args.plot, dpi=120)
    print(f"wrote {args.plot}")


if __name__ == "__main__":
    main()
