"""pagor.register against the pagor tool: the same clouds and configuration give the same report
(pose, levels, verdict, diagnosis; schema pagor.register/1), on the dev KITTI pairs and the
generated scene; and the module's own inputs (dtypes, strides) do not change the result."""
import json

import numpy as np
import pytest

import pagor
from conftest import KITTI_DIR, kitti_frame

# What differs between two runs of one registration: wall-clock times, and the inputs' names
# (the report's top-level "source" and "target").
VOLATILE = {"timings_ms", "clique_time_ms", "time_ms"}

DEV_PAIRS = [tuple(int(f) for f in line.split()) for line in
             (KITTI_DIR / "pairs_00_dev.txt").read_text().splitlines()
             if line.strip()] if (KITTI_DIR / "pairs_00_dev.txt").exists() else []


def stable(report, top=True):
    if top and isinstance(report, dict):
        report = {k: v for k, v in report.items() if k not in ("source", "target")}
    if isinstance(report, dict):
        return {k: stable(v, False) for k, v in report.items() if k not in VOLATILE}
    if isinstance(report, list):
        return [stable(v, False) for v in report]
    return report


def assert_same_as_cli(result, expected):
    assert result.to_dict()["schema"] == "pagor.register/1"
    assert result.T_target_source is not None
    np.testing.assert_array_equal(result.T_target_source, np.array(expected["T_target_source"]))
    assert stable(json.loads(result.to_json())) == stable(expected)
    assert result.selected_level == expected["selected_level"]
    assert result.accepted == expected["acceptance"]["accepted"]
    assert stable(result.diagnosis) == stable(expected["diagnosis"])
    assert set(result.timings_ms) == set(expected["timings_ms"])


@pytest.mark.parametrize("pair", DEV_PAIRS, ids=lambda p: f"{p[0]}-{p[1]}")
def test_kitti_dev_pair_equals_the_cli(pair, kitti_dir, cli, tmp_path):
    s, t = pair
    expected = cli(["register", "--kitti-root", str(kitti_dir), "--sequence", "00", "--pair",
                    str(s), str(t), "--threads", "2"], tmp_path / "cli.json")
    source, source_labels = pagor.read_cloud(*kitti_frame(s))
    target, target_labels = pagor.read_cloud(*kitti_frame(t))
    truth = np.array(expected["ground_truth"]["T_target_source"])
    result = pagor.register(source, target, source_labels, target_labels,
                            ground_truth=truth, threads=2)
    assert_same_as_cli(result, expected)
    assert [lv.epsilon for lv in result.levels] == [lv["epsilon"] for lv in expected["levels"]]


def test_generated_scene_equals_the_cli_and_finds_the_truth(cli, tmp_path):
    expected = cli(["register", "--synthetic", "7"], tmp_path / "cli.json")
    scene = pagor.synthetic_scene(seed=7)
    result = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                            scene["target_labels"], ground_truth=scene["T_target_source"])
    assert_same_as_cli(result, expected)
    assert result.accepted
    assert result.diagnosis["verdict"] == "success"
    np.testing.assert_allclose(result.T_target_source, scene["T_target_source"], atol=0.2)


@pytest.fixture(scope="module")
def scene():
    return pagor.synthetic_scene(seed=7)


def pose(source, target, scene):
    return pagor.register(source, target, scene["source_labels"], scene["target_labels"],
                          config={"refinement": {"enabled": False}}).T_target_source


def test_float64_strided_and_fortran_inputs_give_the_same_pose(scene):
    src, tgt = scene["source"], scene["target"]
    reference = pose(src, tgt, scene)
    assert reference is not None
    # float64 holds every float32 exactly; a column slice of an N x 4 array is a strided view;
    # a Fortran-ordered copy has the other strides. All read in place.
    wide = np.hstack([src, np.ones((len(src), 1), np.float32)])
    variants = [src.astype(np.float64), wide[:, :3], np.asfortranarray(src)]
    assert not wide[:, :3].flags.c_contiguous
    for variant in variants:
        np.testing.assert_array_equal(pose(variant, tgt, scene), reference)


def test_labels_of_any_integer_type_in_range_are_accepted(scene):
    reference = pose(scene["source"], scene["target"], scene)
    labels64 = {k: scene[k].astype(np.int64) for k in ("source_labels", "target_labels")}
    np.testing.assert_array_equal(pose(scene["source"], scene["target"], labels64), reference)


def test_result_attributes_mirror_the_report(scene):
    result = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                            scene["target_labels"], config={"preset": "paper",
                                                            "label_scheme": "semantickitti-train"})
    report = result.to_dict()
    assert report["config"]["graph"]["thresholds"] == [0.02, 0.04, 0.08, 0.16]
    assert result.config == report["config"]
    assert result.T_target_source.shape == (4, 4) and result.T_target_source.dtype == np.float64
    assert len(result.levels) == len(report["levels"]) == 4
    for level, expected in zip(result.levels, report["levels"]):
        assert level.epsilon == expected["epsilon"]
        assert level.clique_size == expected["clique_size"] == len(level.clique)
        assert level.inliers == expected["inliers"]
        assert level.score_D == expected["score_D"]
        assert level.success is None  # no ground truth
        assert level.to_dict() == expected
    assert result.diagnosis is None
    assert result.timings_ms["total"] > 0
    assert json.loads(result.to_json(indent=-1)) == report
    assert "pagor.Result" in repr(result) and "pagor.Level" in repr(result.levels[0])


def test_a_registration_without_labels_uses_class_agnostic_keypoints(scene):
    result = pagor.register(scene["source"], scene["target"])
    landmarks = result.to_dict()["landmarks"]["source"]
    assert landmarks.get("structure", 0) > 0
