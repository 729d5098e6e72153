#!/usr/bin/env python3
"""Closes the loops of a KITTI-layout drive with its odometry and plots the corrected trajectory.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/close_loops.py SEQ_DIR --odometry ODOM.txt \
        [--calib calib.txt] [--config FILE] [--online] [--out-trajectory OUT.txt] [--plot trajectory.png]

SEQ_DIR holds velodyne/NNNNNN.bin and labels/NNNNNN.label (labels are not read with `labeller: {source:
geometric}` in --config); ODOM.txt one pose per scan, KITTI (with SEQ_DIR/calib.txt or --calib: cam0 poses, as
KITTI's poses.txt) or TUM. Each scan goes to sgtllc.LoopClosingPipeline with its odometry pose, as a SLAM system
would hand over its keyframes; the corrected poses are those of `sgtllc run SEQ_DIR --odometry ODOM.txt
--out-trajectory OUT.txt`. The plot needs matplotlib (Debian: python3-matplotlib).
"""
import argparse
import os

import numpy as np

import sgtllc


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sequence")
    parser.add_argument("--odometry", required=True, help="KITTI or TUM trajectory, one pose per scan")
    parser.add_argument("--calib", help="KITTI calib.txt of a cam0 odometry (default: SEQ_DIR/calib.txt if present)")
    parser.add_argument("--config", help="YAML configuration (see `sgtllc config`)")
    parser.add_argument("--online", action="store_true", help="re-solve the pose graph at every loop")
    parser.add_argument("--out-trajectory", help="write the corrected poses (KITTI layout, LiDAR frame)")
    parser.add_argument("--plot", help="PNG of the odometry and the corrected trajectory, seen from above")
    args = parser.parse_args()

    config = sgtllc.Config.from_yaml(args.config) if args.config else sgtllc.Config()
    geometric = config.labeller.source == sgtllc.LabelSource.GEOMETRIC
    seq = sgtllc.SequenceDir(args.sequence, read_labels=not geometric)
    calib = args.calib or os.path.join(args.sequence, "calib.txt")
    odometry = sgtllc.read_poses(args.odometry, calib if os.path.exists(calib) else None)
    if len(odometry) != len(seq):
        raise SystemExit(f"{args.odometry}: {len(odometry)} poses for {len(seq)} scans")

    pipeline = sgtllc.LoopClosingPipeline(config, online=args.online)
    for i in range(len(seq)):
        points, labels = seq.load(i)
        frame = pipeline.add_scan(points, None if geometric else labels, pose=odometry[i], name=seq.frame_name(i))
        if frame.loop is not None:
            print(f"loop {frame.loop.query} -> {frame.loop.match}  score {frame.loop.score:.3f}"
                  + (f"  (re-solved in {frame.solve_ms:.1f} ms)" if frame.solved else ""))
    closing = pipeline.finish()
    accepted = closing.result.num_accepted
    print(f"{len(seq)} frames, {len(pipeline.loops)} loops, {accepted} accepted")

    corrected = pipeline.poses
    if args.out_trajectory:
        np.savetxt(args.out_trajectory, corrected[:, :3, :].reshape(len(corrected), 12), fmt="%.17g")
    if args.plot:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("matplotlib is not installed: no plot")
            return
        fig, ax = plt.subplots(figsize=(6, 6))
        ax.plot(odometry[:, 0, 3], odometry[:, 1, 3], label="odometry", color="0.6")
        ax.plot(corrected[:, 0, 3], corrected[:, 1, 3], label="corrected")
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.legend()
        fig.savefig(args.plot, dpi=120)
        print(f"wrote {args.plot}")


if __name__ == "__main__":
    main()
