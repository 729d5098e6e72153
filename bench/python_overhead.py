#!/usr/bin/env python3
"""Python call overhead of compare_pair on the bundled KITTI 00 pair (004501 vs 000052): the wall time of the
Python call against the library's own stage times of the same call (StageTimes: extraction, description,
verification), i.e. what the binding adds (array checks, the copy into the library's LabeledCloud, the result).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [REPEATS]

Reports the median over REPEATS calls (default 30) of each (and the least overhead seen), for (N, 4) float32 input straight from
read_kitti_bin and for (N, 3) float64 input (a converting copy), and LoopDetector.process on the same scans.
"""
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import sgtllc

ROOT = Path(__file__).resolve().parents[1]
VELODYNE = ROOT / "data" / "kitti" / "00" / "velodyne"


def scan(name):
    path = str(VELODYNE / f"{name}.bin")
    return sgtllc.read_kitti_bin(path), sgtllc.read_labels(sgtllc.default_label_path(path))


def measure(call, repeats, prepare=lambda: None):
    walls, inner = [], []
    for _ in range(repeats):
        state = prepare()
        start = time.perf_counter()
        result = call(state)
        walls.append((time.perf_counter() - start) * 1e3)
        inner.append(result.timing.total_ms)
    overhead = np.subtract(walls, inner)
    return statistics.median(walls), statistics.median(inner), statistics.median(overhead), overhead.min()


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    (qp, ql), (mp, ml) = scan("004501"), scan("000052")
    q64, m64 = qp[:, :3].astype(np.float64), mp[:, :3].astype(np.float64)
    detector_config = sgtllc.Config()
    detector_config.retrieval.exclude_recent = 1

    def detector_with_match():  # not timed: a detector that holds the match frame
        d = sgtllc.LoopDetector(detector_config)
        d.process(mp, ml)
        return d

    none = lambda: None
    cases = [
        ("compare_pair, (N, 4) float32", lambda _: sgtllc.compare_pair(qp, ql, mp, ml), none),
        ("compare_pair, (N, 3) float64", lambda _: sgtllc.compare_pair(q64, ql, m64, ml), none),
        ("LoopDetector.process (query)", lambda d: d.process(qp, ql), detector_with_match),
    ]
    print(f"{len(qp)} + {len(mp)} points, median of {repeats} calls")
    for name, call, prepare in cases:
        call(prepare())  # warm-up
        wall, inner, overhead, least = measure(call, repeats, prepare)
        print(f"{name:30s} wall {wall:7.2f} ms  library {inner:7.2f} ms  overhead {overhead:5.2f} ms "
              f"({100 * overhead / inner:4.1f} %, least {least:5.2f} ms)")


if __name__ == "__main__":
    main()
