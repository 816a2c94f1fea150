"""read_cloud for every format the pagor tool reads, the configuration as dicts, the examples."""
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import pagor
from conftest import SHARED_DATA, SOURCE_DIR, kitti_frame


def test_read_cloud_reads_a_kitti_scan_and_its_labels(kitti_dir):
    scan, labels_path = kitti_frame(20)
    points, labels = pagor.read_cloud(scan, labels_path)
    raw = np.fromfile(scan, np.float32).reshape(-1, 4)
    assert points.dtype == np.float32 and points.shape == (len(raw), 3)
    np.testing.assert_array_equal(points, raw[:, :3])
    np.testing.assert_array_equal(labels, np.fromfile(labels_path, np.uint32))
    assert pagor.read_cloud(str(scan))[1] is None  # no labels without a .label file


def test_read_cloud_reads_pcd_with_labels():
    path = SHARED_DATA / "semreg-dev" / "03" / "source.pcd"
    if not path.exists():
        pytest.skip(f"no {path}")
    points, labels = pagor.read_cloud(path)
    assert points.shape[1] == 3 and len(points) > 10000
    assert labels.dtype == np.uint32 and len(labels) == len(points)
    assert set(np.unique(labels)) <= set(range(20))  # the learning map


def test_read_cloud_reads_ply_and_drops_non_finite_points_with_a_warning(tmp_path):
    rows = [(0.5, 1.0, 2.0, 10), (float("nan"), 0.0, 0.0, 11), (3.0, -4.0, 5.25, 12)]
    path = tmp_path / "cloud.ply"
    path.write_text("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                    "property float y\nproperty float z\nproperty uint label\nend_header\n"
                    + "".join(f"{x} {y} {z} {label}\n" for x, y, z, label in rows))
    with pytest.warns(UserWarning, match="cloud.ply"):
        points, labels = pagor.read_cloud(path)
    np.testing.assert_array_equal(points, np.array([[0.5, 1.0, 2.0], [3.0, -4.0, 5.25]],
                                                   np.float32))
    np.testing.assert_array_equal(labels, [10, 12])


def test_returned_arrays_own_their_data():
    scene = pagor.synthetic_scene(seed=7)
    points = scene["source"]
    assert points.flags.c_contiguous and points.dtype == np.float32 and points.shape[1] == 3
    assert not points.flags.owndata and points.base is not None  # the core's vector, not a copy
    del scene
    assert np.isfinite(points).all()  # still valid after the dict is gone


def cli_json(args):
    return json.loads(subprocess.run([os.environ["PAGOR_CLI"], *args], check=True,
                                     capture_output=True, text=True).stdout)


def test_default_config_and_presets_are_the_cli_documents():
    if "PAGOR_CLI" not in os.environ:
        pytest.skip("PAGOR_CLI is not set (ctest sets it)")
    assert pagor.default_config() == cli_json(["config", "--print-default"])
    assert set(pagor.preset_names()) >= {"default", "paper", "indoor"}
    for name in pagor.preset_names():
        assert pagor.preset_config(name) == cli_json(["config", "--preset", name])


def test_check_config_fills_absent_keys_from_the_preset():
    config = pagor.check_config({"preset": "paper", "verification": {"mu": 0.5}})
    paper = pagor.preset_config("paper")
    assert config["verification"]["mu"] == 0.5
    assert config["graph"] == paper["graph"]
    assert pagor.check_config({}) == pagor.default_config()
    assert pagor.__version__.count(".") == 2


def run_example(name, *args):
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python" / name), *args],
                          check=True, capture_output=True, text=True, env=env).stdout


def test_the_readme_example_registers_a_kitti_pair(kitti_dir):
    (source, source_labels), (target, target_labels) = kitti_frame(20), kitti_frame(30)
    out = run_example("register_clouds.py", str(source), str(target), "--source-labels",
                      str(source_labels), "--target-labels", str(target_labels))
    assert "accepted: True" in out
    assert out.count("epsilon") == len(pagor.default_config()["graph"]["thresholds"])


def snippet(path):
    """The part of an example between its README marker and "end of snippet"."""
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if 'README: "Use it as a library"' in line)
    end = next(i for i, line in enumerate(lines) if "end of snippet" in line)
    return "\n".join(lines[start + 1:end]).strip("\n")


def test_the_readme_snippets_are_the_tested_examples():
    readme = (SOURCE_DIR / "README.md").read_text()
    blocks = re.findall(r"<!-- snippet: (\S+) -->\n```\w*\n(.*?)\n```", readme, re.S)
    assert sorted(path for path, _ in blocks) == ["examples/cpp/register_clouds.cpp",
                                                  "examples/python/register_clouds.py"]
    for path, block in blocks:
        assert block == snippet(SOURCE_DIR / path), f"the README's {path} differs from the file"


def test_the_open3d_example_aligns_two_open3d_clouds(tmp_path):
    pytest.importorskip("open3d")
    pair = SHARED_DATA / "semreg-dev" / "03"
    if not pair.exists():
        pytest.skip(f"no {pair}")
    aligned = tmp_path / "aligned.ply"
    out = run_example("open3d_register.py", str(pair / "source.pcd"), str(pair / "target.pcd"),
                      "--config", str(SOURCE_DIR / "bench" / "manifests" / "semreg-dev.json"),
                      "--save", str(aligned), "--no-window")
    lines = out.splitlines()
    start = lines.index("T_target_source:") + 1
    T = np.array([[float(v) for v in line.split()] for line in lines[start:start + 4]])
    truth = np.loadtxt(pair / "T_target_source.txt")
    assert np.linalg.norm(T[:3, 3] - truth[:3, 3]) < 2.0
    assert aligned.stat().st_size > 0


def test_the_readme_is_a_quickstart_and_every_link_of_the_docs_resolves():
    readme = SOURCE_DIR / "README.md"
    assert len(readme.read_text().splitlines()) <= 250, "the README is a quickstart: the rest in docs/"
    pages = [readme, *sorted((SOURCE_DIR / "docs").glob("*.md"))]
    for page in pages:
        text = page.read_text()
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text):
            if re.match(r"[a-z]+:", target):
                continue  # another site
            assert (page.parent / target).exists(), f"{page.name} links to {target}, which is not there"
        for path, block in re.findall(r"<!-- snippet: (\S+) -->\n```\w*\n(.*?)\n```", text, re.S):
            assert block == snippet(SOURCE_DIR / path), f"{page.name}'s {path} differs from the file"
