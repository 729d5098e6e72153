"""Shared fixtures: the repository's data/ samples and the command-line tool (set by ctest, see python/CMakeLists.txt)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("SGTLLC_SOURCE_DIR", Path(__file__).resolve().parents[2]))
KITTI = SOURCE / "data" / "kitti" / "00"
QUERY_BIN = KITTI / "velodyne" / "004501.bin"
MATCH_BIN = KITTI / "velodyne" / "000052.bin"


@pytest.fixture(scope="session")
def cli():
    """Path of the `sgtllc` tool; the CLI comparisons need it (ctest passes it unless the tool is not built)."""
    path = os.environ.get("SGTLLC_CLI")
    if not path:
        pytest.skip("SGTLLC_CLI is not set (the command-line tool is not built)")
    return path


def run_cli(cli, *args):
    out = subprocess.run([cli, *map(str, args)], check=True, capture_output=True, text=True)
    return out.stdout


def cli_json(cli, *args):
    return json.loads(run_cli(cli, *args, "--json"))
