"""Bad arguments raise ValueError (pagor.Error for the core's own checks) with a message naming
what was wrong, never crash; the module keeps working afterwards."""
import json

import numpy as np
import pytest

import pagor
from conftest import SHARED_DATA

rng = np.random.default_rng(5)
CLOUD = rng.uniform(-20, 20, (500, 3)).astype(np.float32)
LABELS = np.zeros(500, np.uint32)


def with_nan(index):
    cloud = CLOUD.copy()
    cloud[index, 1] = np.nan
    return cloud


BAD_CLOUDS = [
    (CLOUD[:, :2], r"source: expected an N x 3 array of points, got shape \(500, 2\)"),
    (CLOUD.ravel(), r"source: expected an N x 3 array of points, got shape \(1500,\)"),
    (CLOUD[None], r"source: expected an N x 3 array .*got shape \(1, 500, 3\)"),
    (np.zeros((0, 3), np.float32), r"source: no points"),
    (CLOUD.astype(np.int32), r"source: expected float32 or float64 coordinates, got dtype int32"),
    (CLOUD.astype(np.float16), r"got dtype float16"),
    (CLOUD.astype(">f4"), r"got dtype >f4"),
    (with_nan(17), r"source: point 17 has a non-finite coordinate \(.*nan"),
    (np.where(CLOUD > 19.9, np.inf, CLOUD), r"source: point \d+ has a non-finite coordinate"),
    (None, r"source: expected an array, got None"),
    ([[0.0, 1.0, 2.0], [1.0, "x", 3.0]], r"source: expected float32 or float64 coordinates"),
]


@pytest.mark.parametrize("cloud,message", BAD_CLOUDS)
def test_a_bad_cloud_raises_value_error(cloud, message):
    with pytest.raises(ValueError, match=message):
        pagor.register(cloud, CLOUD)


BAD_LABELS = [
    (LABELS[:499], r"source_labels: 499 labels for 500 points; expected one label per point"),
    (LABELS.astype(np.float32), r"source_labels: expected integer labels \(uint32\), got dtype float32"),
    (LABELS.reshape(50, 10), r"source_labels: expected a 1-D array of labels, got shape \(50, 10\)"),
    (np.full(500, -1, np.int64), r"source_labels: labels must be within 0 .. 4294967295, got -1 .. -1"),
    (np.full(500, 2**32, np.uint64), r"within 0 .. 4294967295, got 4294967296"),
]


@pytest.mark.parametrize("labels,message", BAD_LABELS)
def test_bad_labels_raise_value_error(labels, message):
    with pytest.raises(ValueError, match=message):
        pagor.register(CLOUD, CLOUD, source_labels=labels)


BAD_CONFIGS = [
    ({"graph": {"bogus": 1}}, r"config: graph.bogus: unknown key"),
    ({"bogus": {}}, r"config: bogus: unknown key"),
    ({"verification": {"mu": 5000}}, r"config: verification.mu: 5000 is outside"),
    ({"graph": {"thresholds": "x"}}, r"config: graph.thresholds"),
    ({"graph": {"thresholds": [0.1, float("nan")]}}, r"config: graph.thresholds\[1\]: nan is not a finite number"),
    ({"preset": "nope"}, r"nope"),
    ({"correspondences": {"max_correspondences": 2**32}}, r"max_correspondences"),
    ({"verification": {"mu": object()}}, r"config: verification.mu: a value of type object cannot be a JSON value"),
    ({1: 2}, r"config: the document: keys must be strings"),
]


@pytest.mark.parametrize("config,message", BAD_CONFIGS)
def test_a_bad_config_raises_value_error_with_the_key(config, message):
    with pytest.raises(ValueError, match=message):
        pagor.register(CLOUD, CLOUD, config=config)
    with pytest.raises(ValueError, match=message):
        pagor.check_config(config)


def test_a_config_that_is_not_a_dict_is_a_type_error():
    with pytest.raises(TypeError, match="config: expected a dict"):
        pagor.register(CLOUD, CLOUD, config='{"graph": {}}')


def test_core_errors_are_pagor_errors_and_value_errors():
    assert issubclass(pagor.Error, ValueError)
    with pytest.raises(pagor.Error, match="unknown key"):
        pagor.check_config({"bogus": 1})
    with pytest.raises(pagor.Error, match="paper"):  # the message lists the presets
        pagor.preset_config("nope")


@pytest.mark.parametrize("truth,message", [
    (np.eye(3), r"ground_truth: expected a 4 x 4 transform, got shape \(3, 3\)"),
    (np.diag([1.0, 1.0, -1.0, 1.0]), r"ground_truth: the rotation part has determinant -1"),
    (np.full((4, 4), np.nan), r"ground_truth: not all entries are finite"),
])
def test_a_bad_ground_truth_raises_value_error(truth, message):
    with pytest.raises(ValueError, match=message):
        pagor.register(CLOUD, CLOUD, ground_truth=truth)


def test_zero_threads_raise_value_error():
    with pytest.raises(ValueError, match="threads: expected 1 or more, got 0"):
        pagor.register(CLOUD, CLOUD, threads=0)


def test_read_cloud_names_the_file(tmp_path):
    # A missing file is FileNotFoundError (it was pagor.Error); the rest stays ValueError.
    with pytest.raises(FileNotFoundError, match="nowhere.pcd"):
        pagor.read_cloud(tmp_path / "nowhere.pcd")
    broken = tmp_path / "broken.pcd"
    broken.write_bytes(b"VERSION .7\nFIELDS x y\nbroken")
    with pytest.raises(ValueError, match="broken.pcd"):
        pagor.read_cloud(broken)
    scan = tmp_path / "scan.bin"
    np.zeros((10, 4), np.float32).tofile(scan)
    np.zeros(9, np.uint32).tofile(tmp_path / "scan.label")
    with pytest.raises(ValueError, match="scan.label"):
        pagor.read_cloud(scan, tmp_path / "scan.label")


BAD_INPUTS = SHARED_DATA / "bad-inputs"


@pytest.mark.parametrize("name", sorted(p.name for p in BAD_INPUTS.glob("*.p[cl][dy]")))
def test_every_shared_bad_cloud_raises_value_error_naming_the_file(name):
    with pytest.raises(ValueError, match=name.replace(".", r"\.")):
        pagor.read_cloud(BAD_INPUTS / name)


@pytest.mark.parametrize("name", ["cfg_1e400_internal_error.json", "cfg_float_to_int_ub.json",
                                  "cfg_maxcorr_1e10_truncated.json",
                                  "cfg_maxcorr_2p32_becomes_0.json", "cfg_seed_negfloat_ub.json"])
def test_every_shared_bad_config_raises_value_error(name):
    path = BAD_INPUTS / name
    if not path.exists():
        pytest.skip(f"no {path}")
    with pytest.raises(ValueError, match="config: "):
        pagor.check_config(json.loads(path.read_text()))


def test_a_config_nested_without_end_raises_value_error():
    deep = []
    for _ in range(100000):
        deep = [deep]
    with pytest.raises(ValueError, match="config: graph.trim.*nested deeper than 64 levels"):
        pagor.check_config({"graph": {"trim": deep}})


BAD_CORRESPONDENCES = [
    (dict(p=CLOUD, q=CLOUD[:499]), r"p and q: 500 source points and 499 target points"),
    (dict(p=CLOUD[:, :2], q=CLOUD), r"p: expected an N x 3 array"),
    (dict(p=CLOUD, q=with_nan(3)), r"q: point 3 has a non-finite coordinate"),
    (dict(p=CLOUD, q=CLOUD, weights=np.ones(3)), r"weights: expected 500 weights"),
    (dict(p=CLOUD, q=CLOUD, weights=-np.ones(500)), r"weights: weight 0 is -1.0; expected a finite number >= 0"),
    (dict(p=CLOUD, q=CLOUD, config={"gnc": {"bogus": 1}}), r"config: gnc.bogus: unknown key"),
    (dict(p=np.zeros((20001, 3)), q=np.zeros((20001, 3))), r"20001 correspondences .*20000"),
]


@pytest.mark.parametrize("kwargs,message", BAD_CORRESPONDENCES)
def test_bad_correspondences_raise_value_error(kwargs, message):
    with pytest.raises(ValueError, match=message):
        pagor.register_correspondences(**kwargs)


def test_the_module_works_after_errors():
    for cloud, _ in BAD_CLOUDS:
        with pytest.raises(ValueError):
            pagor.register(cloud, CLOUD)
    scene = pagor.synthetic_scene(seed=7)
    result = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                            scene["target_labels"])
    assert result.T_target_source is not None
