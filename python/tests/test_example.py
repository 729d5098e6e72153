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
