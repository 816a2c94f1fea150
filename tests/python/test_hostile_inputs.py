"""Issue 35's hostile-input findings, each a known answer: clouds far from the origin re-framed
as the file readers do, a corrupt 1e30 point dropped with a warning naming the argument,
non-UTF-8 strings in a config dict, a NUL in a path, correspondences beyond 1e7 m, a large
to_json indent, hexadecimal in a correspondences file."""
import os
import re
import subprocess

import numpy as np
import pytest

import pagor


@pytest.fixture(scope="module")
def scene():
    return pagor.synthetic_scene(seed=7)


def shifted(T, offset):
    """T_target_source between frames whose origins moved by -offset (points + offset)."""
    S = np.eye(4)
    S[:3, 3] = offset
    return S @ T @ np.linalg.inv(S)


def displacement(T, T_true, points):
    """Largest distance between the points moved by T and by the true transform [m]."""
    return np.abs((points @ T[:3, :3].T + T[:3, 3]) - (points @ T_true[:3, :3].T + T_true[:3, 3]))\
        .max()


@pytest.mark.parametrize("offset", [[3000.0, 2000.0, 30.0], [300e3, 200e3, 30.0],
                                    [-4.2e6, 5.1e6, 120.0]])
def test_float64_clouds_far_from_the_origin_are_registered_in_their_own_frame(scene, offset):
    source = scene["source"].astype(np.float64) + offset
    target = scene["target"].astype(np.float64) + offset
    truth = shifted(scene["T_target_source"], np.array(offset))
    r = pagor.register(source, target, scene["source_labels"], scene["target_labels"],
                       ground_truth=truth)
    assert r.accepted and r.diagnosis["verdict"] == "success", r.acceptance
    assert r.ground_truth["translation_error_m"] < 0.1
    # the pose in the caller's frame moves the clouds' points to within 5 cm of the truth
    assert displacement(r.T_target_source, truth, source) < 0.05
    # landmarks and correspondences come back in the caller's frame too
    landmarks = r.landmarks["source"].positions
    assert np.abs(np.median(landmarks, axis=0) - offset).max() < 100
    c = r.correspondences
    np.testing.assert_array_equal(c.p, landmarks[c.source])
    clique = r.levels[r.selected_level].clique
    moved = c.p[clique] @ truth[:3, :3].T + truth[:3, 3]
    assert np.linalg.norm(moved - c.q[clique], axis=1).max() < 1.0


def test_far_correspondences_with_far_clouds_are_verified_on_them(scene):
    offset = np.array([300e3, 200e3, 30.0])
    T = shifted(scene["T_target_source"], offset)
    source = scene["source"].astype(np.float64) + offset
    target = scene["target"].astype(np.float64) + offset
    rng = np.random.default_rng(4)
    p = source[rng.choice(len(source), 200, replace=False)]
    q = p @ T[:3, :3].T + T[:3, 3]
    q[120:] = target[rng.choice(len(target), 80, replace=False)]
    r = pagor.register_correspondences(p, q, source=source, target=target, ground_truth=T)
    assert r.verified and r.ground_truth["success"], r.acceptance
    np.testing.assert_array_equal(r.correspondences.p, p)  # given back in the caller's frame
    assert displacement(r.T_target_source, T, source) < 0.05


def test_a_corrupt_point_is_dropped_with_a_warning_naming_the_argument(scene):
    reference = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                               scene["target_labels"])
    source = np.vstack([scene["source"][:100], [[1e30, 0.0, 0.0]], scene["source"][100:]])
    labels = np.concatenate([scene["source_labels"][:100], [9], scene["source_labels"][100:]])
    with pytest.warns(UserWarning, match=r"^source: dropped 1 point lying more than 1e6 m"):
        r = pagor.register(source.astype(np.float32), scene["target"], labels,
                           scene["target_labels"])
    np.testing.assert_array_equal(r.T_target_source, reference.T_target_source)
    target = np.vstack([scene["target"], [[0.0, -1e30, 0.0], [2e6, 0.0, 0.0]]])
    target_labels = np.concatenate([scene["target_labels"], [9, 9]])
    with pytest.warns(UserWarning, match=r"^target: dropped 2 points"):
        r = pagor.register(scene["source"], target, scene["source_labels"], target_labels)
    np.testing.assert_array_equal(r.T_target_source, reference.T_target_source)


def test_a_cloud_of_corrupt_points_only_is_a_value_error_naming_it():
    with pytest.raises(ValueError, match="target: no point lies within 1e6 m"):
        pagor.register(np.zeros((10, 3)), np.full((10, 3), 1e30))


@pytest.mark.parametrize("config,message", [
    ({"label_scheme": b"semantic\xffkitti".decode("utf-8", "surrogateescape")},
     r"config: label_scheme: the string 'semantic\\udcffkitti' is not valid UTF-8 text"),
    ({"graph": {b"\xfe".decode("utf-8", "surrogateescape"): 1}},
     r"config: graph: the key '\\udcfe' is not valid UTF-8 text"),
    ({"landmarks": {"classes": [{"name": "\ud800"}]}},
     r"config: landmarks.classes\[0\].name: the string '\\ud800' is not valid UTF-8"),
])
def test_a_string_that_is_not_utf8_is_a_value_error_naming_the_key(config, message):
    with pytest.raises(ValueError, match=message):
        pagor.check_config(config)
    with pytest.raises(ValueError, match=message):
        pagor.register(np.zeros((10, 3)), np.zeros((10, 3)), config=config)


def test_a_nul_in_a_path_is_a_value_error(tmp_path):
    scan = tmp_path / "scan.bin"
    np.zeros((10, 4), np.float32).tofile(scan)
    with pytest.raises(ValueError, match="path: the path contains a NUL byte"):
        pagor.read_cloud(str(scan) + "\0.pcd")
    with pytest.raises(ValueError, match="labels_path: the path contains a NUL byte"):
        pagor.read_cloud(scan, str(tmp_path / "scan.label\0x"))
    with pytest.raises(ValueError, match="source: the path contains a NUL byte"):
        pagor.register(str(scan) + "\0", np.zeros((10, 3)))
    with pytest.raises(ValueError, match="path: the path contains a NUL byte"):
        pagor._pagor.read_cloud(os.fsencode(scan) + b"\0.pcd", None)  # the extension checks too


def test_a_file_name_that_is_not_utf8_is_read(tmp_path):
    name = os.fsencode(tmp_path) + b"/scan-\xff.bin"
    rows = np.hstack([np.arange(30, dtype=np.float32).reshape(10, 3), np.zeros((10, 1), np.float32)])
    rows.tofile(name)
    points, labels = pagor.read_cloud(name)
    np.testing.assert_array_equal(points, rows[:, :3])
    assert labels is None
    points, _ = pagor.read_cloud(os.fsdecode(name))
    assert len(points) == 10


def test_a_georeferenced_file_comes_back_in_float64_in_its_frame(tmp_path):
    rows = np.array([[512345.25, 5412345.5, 101.0, 1.0], [512346.0, 5412344.0, 102.5, 1.0]] * 50)
    rows[:, 0] += np.arange(100) * 0.5
    path = tmp_path / "far.ply"
    path.write_text("ply\nformat ascii 1.0\nelement vertex 100\nproperty double x\n"
                    "property double y\nproperty double z\nproperty float intensity\n"
                    "end_header\n" + "".join(f"{x} {y} {z} {i}\n" for x, y, z, i in rows))
    points, _ = pagor.read_cloud(path)
    assert points.dtype == np.float64
    np.testing.assert_allclose(points, rows[:, :3], atol=1e-3)  # float32 would be 0.5 m off


@pytest.mark.parametrize("side", ["p", "q"])
def test_a_correspondence_beyond_1e7_m_is_a_value_error_naming_the_row(side):
    rng = np.random.default_rng(1)
    points = {"p": rng.uniform(-10, 10, (50, 3)), "q": rng.uniform(-10, 10, (50, 3))}
    points[side][7, 2] = 1e30
    with pytest.raises(ValueError, match=rf"^{side}: point 7 \(.*1e\+30\) lies farther than "
                                         r"1e\+07 m from the origin"):
        pagor.register_correspondences(points["p"], points["q"])


def test_a_large_to_json_indent_is_clamped_not_read_past_a_buffer(scene):
    r = pagor.register_correspondences(scene["source"][:60].astype(float),
                                       scene["source"][:60].astype(float) + 1.0)
    text = r.to_json(100000)
    assert text == r.to_json(16) and "\0" not in text
    assert max(len(line) - len(line.lstrip(" ")) for line in text.splitlines()) % 16 == 0
    assert r.to_json(2**31 - 1) == text


@pytest.mark.parametrize("line,message", [
    ("0x10 2 3 4 5 6", r"c\.txt:2: px '0x10' is not a finite number \(column 1; numbers are "
                       r"decimal, hexadecimal is not read\)"),
    ("1 2 3 4 5 1e30", r"c\.txt:2: qz '1e30' lies farther than 1e7 m from the origin"),
])
def test_the_cli_refuses_hexadecimal_and_1e30_in_a_correspondences_file(tmp_path, line, message):
    cli = os.environ.get("PAGOR_CLI")
    if not cli:
        pytest.skip("PAGOR_CLI is not set (ctest sets it)")
    path = tmp_path / "c.txt"
    path.write_text("1 2 3 4 5 6\n" + line + "\n" + "7 8 9 10 11 12\n" * 5)
    run = subprocess.run([cli, "register", "--correspondences", str(path)], capture_output=True,
                         text=True)
    assert run.returncode == 1
    assert re.search(message, run.stderr), run.stderr
