"""Shared fixtures of the Python module's tests. ctest sets the environment (tests/CMakeLists.txt):
PYTHONPATH (the module in the build tree), PAGOR_CLI (the pagor tool), PAGOR_KITTI_DIR,
PAGOR_SHARED_DATA and PAGOR_SOURCE_DIR."""
import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("PAGOR_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SHARED_DATA = Path(os.environ.get("PAGOR_SHARED_DATA", SOURCE_DIR.parent / "shared" / "data"))
KITTI_DIR = Path(os.environ.get("PAGOR_KITTI_DIR", SHARED_DATA / "kitti"))


def have_kitti():
    return (KITTI_DIR / "sequences" / "00" / "velodyne" / "000000.bin").exists()


@pytest.fixture(scope="session")
def cli():
    """Runs the pagor tool with arguments; returns its --json output as a dict."""
    path = os.environ.get("PAGOR_CLI")
    if not path:
        pytest.skip("PAGOR_CLI is not set (ctest sets it)")

    def run(args, json_path):
        subprocess.run([path, *args, "--json", str(json_path)], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        return json.loads(Path(json_path).read_text())

    return run


@pytest.fixture(scope="session")
def kitti_dir():
    if not have_kitti():
        pytest.skip(f"no KITTI data at {KITTI_DIR}")
    return KITTI_DIR


def kitti_frame(frame):
    """Paths of a KITTI frame's scan and labels."""
    seq = KITTI_DIR / "sequences" / "00"
    return seq / "velodyne" / f"{frame:06d}.bin", seq / "labels" / f"{frame:06d}.label"


@pytest.fixture(scope="module")
def manifest(tmp_path_factory):
    """A pairs manifest of four semreg-dev pairs (bench_rows.NAMES)."""
    from bench_rows import write_manifest
    return write_manifest(tmp_path_factory.mktemp("pairs") / "pairs.txt")


@pytest.fixture(scope="module")
def reference(manifest, tmp_path_factory):
    """The CLI's lines for the manifest's pairs (pagor bench --out)."""
    from bench_rows import cli_rows
    if not os.environ.get("PAGOR_CLI"):
        pytest.skip("PAGOR_CLI is not set (ctest sets it)")
    return cli_rows(manifest, tmp_path_factory.mktemp("cli") / "cli.jsonl")
