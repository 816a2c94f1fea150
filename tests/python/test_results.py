"""Results as numpy arrays (landmarks, correspondences, each level's clique), picklable, with
to_dict() / to_json() equal to `pagor register --json`; clouds given as Open3D point clouds or
as file paths."""
import json
import os
import pickle
import re
import subprocess

import numpy as np
import pytest

import pagor


@pytest.fixture(scope="module")
def scene():
    return pagor.synthetic_scene(seed=7)


@pytest.fixture(scope="module")
def result(scene):
    return pagor.register(scene["source"], scene["target"], scene["source_labels"],
                          scene["target_labels"], ground_truth=scene["T_target_source"])


def test_each_level_clique_is_an_int_array_of_the_report(result):
    report = result.to_dict()
    for level, expected in zip(result.levels, report["levels"]):
        assert isinstance(level.clique, np.ndarray) and level.clique.dtype == np.int64
        np.testing.assert_array_equal(level.clique, expected["clique"])
        assert len(level.clique) == level.clique_size


def test_correspondences_are_arrays_the_cliques_index(result, scene):
    c = result.correspondences
    n = result.to_dict()["correspondences"]["count"]
    assert len(c) == n and c.p.shape == c.q.shape == (n, 3) and c.p.dtype == np.float64
    assert c.class_index.dtype == np.int32 and set(c.origin) == {"landmark"}
    # each correspondence joins a source landmark and a target landmark of its class
    source, target = result.landmarks["source"], result.landmarks["target"]
    np.testing.assert_array_equal(c.p, source.positions[c.source])
    np.testing.assert_array_equal(c.q, target.positions[c.target])
    np.testing.assert_array_equal(c.class_index, source.class_index[c.source])
    np.testing.assert_array_equal(c.class_index, target.class_index[c.target])
    assert set(c.class_name) <= set(source.class_names)
    # the selected clique's members agree with the true pose (within the noise bound)
    T = scene["T_target_source"]
    clique = result.levels[result.selected_level].clique
    moved = c.p[clique] @ T[:3, :3].T + T[:3, 3]
    assert np.linalg.norm(moved - c.q[clique], axis=1).max() < 1.0


def test_landmarks_per_cloud_match_the_report_counts(result):
    report = result.to_dict()["landmarks"]
    for side in ("source", "target"):
        landmarks = result.landmarks[side]
        assert landmarks.positions.shape == (len(landmarks), 3)
        counts = {}
        for name in landmarks.class_name:
            counts[name] = counts.get(name, 0) + 1
        assert counts == {k: v for k, v in report[side].items() if v > 0}


def test_a_result_pickles_and_comes_back_equal(result):
    copy = pickle.loads(pickle.dumps(result))
    assert copy == result and copy.to_json() == result.to_json()
    np.testing.assert_array_equal(copy.T_target_source, result.T_target_source)
    np.testing.assert_array_equal(copy.correspondences.p, result.correspondences.p)
    np.testing.assert_array_equal(copy.landmarks["target"].positions,
                                  result.landmarks["target"].positions)
    np.testing.assert_array_equal(copy.levels[1].clique, result.levels[1].clique)
    assert repr(copy) == repr(result)


VOLATILE_LINE = re.compile(r'^\s*"(\w+)": ("[^"]*"|[-+0-9.eE]+),?$')
VOLATILE_KEYS = {"source", "target", "clique_time_ms", "time_ms", "landmarks", "correspondences",
                 "graph", "clique", "gnc", "verification", "refinement", "acceptance",
                 "evaluation", "diagnosis", "total"}


def test_to_json_is_the_text_the_cli_writes(result, cli, tmp_path):
    """Line by line, but for the wall-clock times and the inputs' names."""
    cli(["register", "--synthetic", "7"], tmp_path / "cli.json")
    expected = (tmp_path / "cli.json").read_text().splitlines()
    ours = result.to_json().splitlines()  # the same scene, with its ground truth as the CLI has
    assert len(ours) == len(expected)
    for mine, theirs in zip(ours, expected):
        if mine != theirs:
            a, b = VOLATILE_LINE.match(mine), VOLATILE_LINE.match(theirs)
            assert a and b and a.group(1) == b.group(1) and a.group(1) in VOLATILE_KEYS, \
                (mine, theirs)


def test_to_json_indents_as_asked_up_to_16_spaces(result):
    one_line = result.to_json(indent=-1)
    assert "\n" not in one_line and json.loads(one_line) == result.to_dict()
    assert result.to_json(None) == one_line
    assert result.to_json(4).splitlines()[1].startswith('    "')
    assert result.to_json(16) == result.to_json(100000) == result.to_json(2**31 - 1) == \
        result.to_json(2**80)
    assert result.to_json(-5) == one_line
    with pytest.raises(TypeError, match="indent: expected an int or None, got str"):
        result.to_json("2")


def test_without_clouds_accepted_is_false_and_repr_says_not_verified():
    rng = np.random.default_rng(2)
    p = rng.uniform(-30, 30, (150, 3))
    q = p + [4.0, -2.0, 0.5]
    r = pagor.register_correspondences(p, q)
    np.testing.assert_allclose(r.T_target_source[:3, 3], [4.0, -2.0, 0.5], atol=1e-6)
    assert r.accepted is False and r.verified is False
    assert "not verified" in repr(r) and "rejected" not in repr(r)
    assert r.acceptance["reason"].startswith("nothing to verify on")
    # the correspondences are the ones given, in order, a matcher's, without class
    np.testing.assert_array_equal(r.correspondences.p, p)
    np.testing.assert_array_equal(r.correspondences.q, q)
    assert set(r.correspondences.origin) == {"matcher"}
    assert (r.correspondences.class_index == -1).all() and set(r.correspondences.class_name) == {""}
    assert len(r.landmarks["source"]) == 0 and r.landmarks["source"].positions.shape == (0, 3)


class DuckCloud:
    """What pagor reads of an Open3D PointCloud: `.points`, a buffer of N x 3 float64."""

    def __init__(self, points):
        self.points = points


def test_an_object_with_points_is_read_as_an_open3d_cloud(scene):
    reference = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                               scene["target_labels"])
    duck = pagor.register(DuckCloud(scene["source"].astype(np.float64)),
                          DuckCloud(scene["target"].astype(np.float64)),
                          scene["source_labels"], scene["target_labels"])
    np.testing.assert_array_equal(duck.T_target_source, reference.T_target_source)


def test_an_open3d_point_cloud_is_accepted_directly(scene):
    o3d = pytest.importorskip("open3d")
    source = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(scene["source"].astype(float)))
    target = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(scene["target"].astype(float)))
    r = pagor.register(source, target, scene["source_labels"], scene["target_labels"])
    reference = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                               scene["target_labels"])
    np.testing.assert_array_equal(r.T_target_source, reference.T_target_source)
    r = pagor.register_correspondences(reference.correspondences.p, reference.correspondences.q,
                                       source=source, target=target)
    assert r.verified and r.to_dict()["selected_by"] == "score_D"


def test_file_paths_are_read_as_read_cloud_reads_them(scene, tmp_path):
    paths = {}
    for side in ("source", "target"):
        rows = np.hstack([scene[side], np.zeros((len(scene[side]), 1), np.float32)])
        paths[side] = tmp_path / f"{side}.bin"
        rows.astype(np.float32).tofile(paths[side])
    from_files = pagor.register(paths["source"], str(paths["target"]), scene["source_labels"],
                                scene["target_labels"])
    reference = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                               scene["target_labels"])
    np.testing.assert_array_equal(from_files.T_target_source, reference.T_target_source)
    assert from_files.to_dict()["source"] == str(paths["source"])


def test_a_missing_file_is_file_not_found_naming_the_argument(tmp_path):
    with pytest.raises(FileNotFoundError, match="source: no such file.*nowhere.bin"):
        pagor.register(tmp_path / "nowhere.bin", np.zeros((10, 3)))
    with pytest.raises(FileNotFoundError, match="target: no such file"):
        pagor.register(np.zeros((10, 3)), str(tmp_path / "nowhere.pcd"))
    with pytest.raises(FileNotFoundError, match="labels_path: no such file"):
        scan = tmp_path / "scan.bin"
        np.zeros((10, 4), np.float32).tofile(scan)
        pagor.read_cloud(scan, tmp_path / "scan.label")


def test_fused_correspondences_carry_their_origin_and_class(scene):
    landmarks_only = pagor.register(scene["source"], scene["target"])  # class-agnostic keypoints
    c = landmarks_only.correspondences
    assert set(c.class_name) == {"structure"} and set(c.origin) == {"landmark"}
    fused = pagor.register_correspondences(c.p, c.q, source=scene["source"],
                                           target=scene["target"],
                                           config={"correspondences": {"fuse_matches": True}})
    f = fused.correspondences
    origin = fused.to_dict()["correspondences"]["origin"]
    for name in ("landmark", "matcher"):
        assert (f.origin == name).sum() == origin[name]["count"] == len(c)
        clique = fused.levels[fused.selected_level].clique
        assert (f.origin[clique] == name).sum() == origin[name]["selected_clique"]
    assert set(f.class_name[f.origin == "matcher"]) == {""}
    assert (f.class_index[f.origin == "matcher"] == -1).all()


def test_every_acceptance_test_is_shown_with_its_value_and_threshold(result):
    tests = {t["name"]: t for t in result.acceptance_tests}
    assert {"overlap", "inliers", "sharpness", "margin", "ambiguity"} <= set(tests)
    accept = pagor.default_config()["acceptance"]
    assert tests["overlap"]["threshold"] == accept["min_overlap"]
    assert tests["overlap"]["comparison"] == ">="
    assert tests["ambiguity"]["threshold"] == accept["max_ambiguity"]
    assert tests["ambiguity"]["comparison"] == "<="
    assert tests["overlap"]["value"] == pytest.approx(result.acceptance["overlap"])
    assert all(t["passed"] for t in tests.values() if t["applies"])  # the scene is accepted
    assert result.accepted and not result.wrong_pose_accepted


def test_the_verdict_says_whether_it_adopted_an_alternative(result):
    # The generated scene's selected pose is accepted as it is: nothing adopted, and the best
    # alternative (if any) names the points behind its ratio.
    assert "adopted" in result.acceptance and result.acceptance["adopted"] is None
    assert pagor.default_config()["acceptance"]["adopt_alternative"] is True
    alt = result.alternative
    assert alt is not None  # the generated scene has a distinct rival, clearly weaker
    assert alt["only_selected"] > alt["only_alternative"] >= 0
    assert alt["ratio"] <= pagor.default_config()["acceptance"]["max_ambiguity"]
