"""examples/python/run_sequence.py runs on the four bundled KITTI 00 scans and finds the one true loop."""
import os
import subprocess
import sys

from conftest import KITTI, SOURCE


def test_run_sequence_example(tmp_path):
    config = tmp_path / "config.yaml"
    config.write_text("retrieval:\n  exclude_recent: 1\n")
    out = subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "run_sequence.py"), str(KITTI),
                          "--config", str(config), "--plot", str(tmp_path / "pr.png")],
                         check=True, capture_output=True, text=True, env=dict(os.environ)).stdout
    assert "loop 004501 -> 000052" in out
    assert "4 frames, 1 with a revisit: F1max 1.000, EP 1.000" in out


def test_run_sequence_plots_precision_against_ascending_recall():
    import importlib.util

    import numpy as np
    import sgtllc

    spec = importlib.util.spec_from_file_location("run_sequence", SOURCE / "examples" / "python" / "run_sequence.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    # Scores 0.9 (true), 0.8 (false), 0.7 (true) with 4 revisits: thresholds give recall 1/4, 1/4, 2/4 at
    # precision 1, 1/2, 2/3; the appended (0, 1) comes first and nothing returns to recall 0.
    curve = sgtllc.precision_recall([0.9, 0.8, 0.7], [True, False, True], positives_override=4)
    recall, precision = example.plot_points(curve)
    np.testing.assert_allclose(recall, [0.0, 0.25, 0.25, 0.5])
    np.testing.assert_allclose(precision, [1.0, 1.0, 0.5, 2.0 / 3.0])
