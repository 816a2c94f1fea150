"""pagor.register_correspondences: the same result as `pagor register --correspondences` on a
correspondences file, and the known transform of a generated problem."""
import json

import numpy as np
import pytest

import pagor
from conftest import SHARED_DATA, SOURCE_DIR

DATA = SOURCE_DIR / "tests" / "data"


def stable(report):
    """The report without wall-clock times and what only a file gives (its name, inlier flags)."""
    if isinstance(report, dict):
        return {k: stable(v) for k, v in report.items()
                if k not in ("clique_time_ms", "timings_ms", "correspondences", "precision",
                             "recall", "true_inliers", "source", "target")}
    if isinstance(report, list):
        return [stable(v) for v in report]
    return report


def test_a_correspondences_file_gives_what_the_cli_gives(cli, tmp_path):
    problem = DATA / "association_m100.txt"
    config_path = DATA / "association_config.json"
    expected = cli(["register", "--correspondences", str(problem), "--config", str(config_path)],
                   tmp_path / "cli.json")
    columns = np.loadtxt(problem, comments="#")
    result = pagor.register_correspondences(columns[:, 0:3], columns[:, 3:6], columns[:, 6],
                                            config=json.loads(config_path.read_text()))
    report = result.to_dict()
    assert report["schema"] == expected["schema"] == "pagor.register/1"
    np.testing.assert_array_equal(result.T_target_source, np.array(expected["T_target_source"]))
    assert stable(report) == stable(expected)
    assert report["correspondences"]["count"] == expected["correspondences"]["count"]
    assert result.accepted is False  # no clouds to verify on, and the verdict says so
    assert report["acceptance"]["verified"] is False
    # every level's clique is the ten flagged inliers (as the CLI test checks)
    inliers = set(np.flatnonzero(columns[:, 7]))
    assert all(set(level.clique) == inliers for level in result.levels)


@pytest.mark.parametrize("model", ["se3", "four_dof"])
def test_a_generated_problem_gives_its_transform(model):
    rng = np.random.default_rng(11)
    yaw = np.radians(30.0)
    T = np.eye(4)
    T[:3, :3] = [[np.cos(yaw), -np.sin(yaw), 0], [np.sin(yaw), np.cos(yaw), 0], [0, 0, 1]]
    T[:3, 3] = [8.0, -3.0, 0.5]
    p = rng.uniform(-40, 40, (400, 3))
    q = p @ T[:3, :3].T + T[:3, 3] + rng.normal(0, 0.02, p.shape)
    outliers = rng.random(len(p)) < 0.8  # 80 % wrong matches
    q[outliers] = rng.uniform(-40, 40, (outliers.sum(), 3))
    result = pagor.register_correspondences(p, q, config={"gnc": {"model": model}})
    np.testing.assert_allclose(result.T_target_source, T, atol=0.05)
    best = result.levels[result.selected_level]
    assert set(best.clique) <= set(np.flatnonzero(~outliers))
    assert best.inliers >= 0.9 * (~outliers).sum()


def test_a_gedi_problem_of_the_shared_data():
    path = SHARED_DATA / "gedi-dev" / "03.txt"
    if not path.exists():
        pytest.skip(f"no {path}")
    columns = np.loadtxt(path)
    T = np.loadtxt(SHARED_DATA / "gedi-dev" / "03.T.txt")
    result = pagor.register_correspondences(columns[:, 0:3], columns[:, 3:6],
                                            config={"graph": {"trim": "difference"}})
    assert result.T_target_source is not None
    assert np.linalg.norm(result.T_target_source[:3, 3] - T[:3, 3]) < 2.0


def test_clouds_to_verify_on_and_a_ground_truth():
    scene = pagor.synthetic_scene(7)
    source, target = scene["source"], scene["target"]
    T = scene["T_target_source"]
    rng = np.random.default_rng(5)
    p = source[rng.choice(len(source), 300, replace=False)].astype(np.float64)
    q = p @ T[:3, :3].T + T[:3, 3]
    q[100:] = target[rng.choice(len(target), 200, replace=False)]  # two thirds wrong
    result = pagor.register_correspondences(p, q, source=source, target=target, ground_truth=T)
    report = result.to_dict()
    assert report["selected_by"] == "score_D"
    assert report["acceptance"]["verified"] is True
    assert report["ground_truth"]["success"] is True
    with pytest.raises(ValueError, match="source and target"):
        pagor.register_correspondences(p, q, source=source)
