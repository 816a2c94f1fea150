"""Pagor: global point-cloud registration with low overlap (semantic landmarks, a pyramid of
consistency graphs, cascaded densest cliques, GNC-TLS poses, verification on the dense clouds).

    import pagor
    result = pagor.register("source.pcd", "target.pcd")        # or N x 3 arrays, Open3D clouds
    if result.accepted:
        use(result.T_target_source)                              # 4 x 4, source -> target frame

`register(source, target, ...)` registers two clouds, `register_correspondences(p, q, ...)` a
matcher's correspondences; both return a `Result` (the report of ``pagor register --json`` and
numpy arrays; picklable). `read_cloud(path)` reads every format the pagor tool reads.
Configurations are dicts with the keys of the JSON configuration (`default_config()`,
`preset_config(name)`, `check_config(dict)`). `run_pairs(pairs, config)` runs a whole set (a
manifest, a KITTI pairs file or a list) on every core or on a Dask cluster and returns the rows
``pagor bench --out`` writes; ``python3 -m pagor bench`` writes them as the tool does. Bad arguments raise ValueError or TypeError naming
the argument or the configuration key (`Error`, a ValueError, for the core's own checks); a
missing file raises FileNotFoundError.
"""
from __future__ import annotations

import warnings as _warnings
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _inputs, _pagor
from .results import ORIGINS, Correspondences, Landmarks, Level, Result
from .sets import KittiPairs, Rows, run_pairs

__version__: str = _pagor.__version__
Error = _pagor.Error
Error.__module__ = "pagor"

__all__ = ["register", "register_correspondences", "read_cloud", "synthetic_scene",
           "default_config", "preset_config", "preset_names", "check_config", "Result", "Level",
           "Landmarks", "Correspondences", "ORIGINS", "Error", "__version__", "run_pairs",
           "KittiPairs", "Rows"]


def _warn(messages: List[str]) -> None:
    for message in messages:
        _warnings.warn(message, UserWarning, stacklevel=3)


def register(source: Any, target: Any, source_labels: Optional[Any] = None,
             target_labels: Optional[Any] = None, config: Optional[Dict[str, Any]] = None, *,
             ground_truth: Optional[Any] = None, threads: int = 1) -> Result:
    """Registers `source` to `target`: finds T_target_source, the transform that maps source
    points into the target frame, with no initial guess.

    source, target: the clouds, each an N x 3 float32 or float64 array [m] (a numpy array, or
        anything numpy.asarray takes; any strides, read in place), an Open3D PointCloud (its
        `.points`), or a file path (str or os.PathLike: read as read_cloud reads it, with the
        file's labels unless labels are given). Points are copied once into the core's float32
        cloud; a cloud lying far from the origin (a georeferenced one, 300 km out) is kept
        relative to an origin near its points, as the file readers do, and the pose comes back
        in the frames of the points as given. A point farther than 1e6 m from the cloud's
        centre (a corrupt 1e30) is dropped with a UserWarning naming `source` or `target`, as
        the pagor tool drops it; a NaN or infinite coordinate is a ValueError naming the point.
    source_labels, target_labels: one integer label per point (uint32, or any integer type
        within 0 .. 2**32 - 1) in the configured label scheme (default ``auto``: recognised
        from the labels), or None (class-agnostic keypoints then).
    config: a dict with the JSON configuration's keys (absent keys: its 'preset', else the
        default), or None for default_config().
    ground_truth: a 4 x 4 T_target_source to judge the result against (errors per level, the
        diagnosis).
    threads: for graph construction and verification (as ``pagor register --threads``).

    The core runs with the GIL released (other Python threads keep running); Ctrl+C cancels
    between stages. Returns a Result. Wrong shapes or dtypes, a label count other than the
    point count, an unknown config key or a value out of range raise ValueError (pagor.Error
    for the core's checks) naming the argument or key; a wrong type raises TypeError; a
    missing file FileNotFoundError.
    """
    source, source_labels, source_name, source_warnings = _inputs.cloud(
        source, source_labels, "source")
    target, target_labels, target_name, target_warnings = _inputs.cloud(
        target, target_labels, "target")
    run = _pagor.register_clouds(source, target, source_labels, target_labels,
                                 _inputs.config(config), ground_truth, _inputs.threads(threads),
                                 source_name, target_name)
    _warn(source_warnings + target_warnings + run["input_warnings"])
    return Result(run)


def register_correspondences(p: Any, q: Any, weights: Optional[Any] = None,
                             config: Optional[Dict[str, Any]] = None, *,
                             source: Optional[Any] = None, target: Optional[Any] = None,
                             ground_truth: Optional[Any] = None, threads: int = 1) -> Result:
    """Registers a matcher's correspondences (FPFH, FCGF, GeDi, ...): p[i] in the source
    matches q[i] in the target, through the same pipeline as
    ``pagor register --correspondences`` (the pyramid of consistency graphs, the densest clique
    and the pose per level).

    p, q: N x 3 float arrays [m] (copied once, as float64); a coordinate beyond 1e7 m is a
        ValueError naming the row (as a correspondences file's line). At most 20000.
    weights: N non-negative numbers or None (kept as each correspondence's score).
    config: as register's.
    source, target: clouds to verify the candidates on (as register's: arrays, Open3D clouds or
        paths), or None: then the level is selected without clouds, `accepted` is False and
        `verified` is False (the reason says there was nothing to verify on).
    ground_truth: a 4 x 4 T_target_source to judge the result against.

    Returns a Result (to_json(): schema pagor.register/1). The GIL is released while the core
    runs.
    """
    warnings: List[str] = []
    if source is not None:
        source, _, _, source_warnings = _inputs.cloud(source, None, "source")
        warnings += source_warnings
    if target is not None:
        target, _, _, target_warnings = _inputs.cloud(target, None, "target")
        warnings += target_warnings
    run = _pagor.register_correspondences(p, q, weights, _inputs.config(config), source, target,
                                          ground_truth, _inputs.threads(threads))
    _warn(warnings + run["input_warnings"])
    return Result(run)


def read_cloud(path: _inputs.PathLike,
               labels_path: Optional[_inputs.PathLike] = None
               ) -> Tuple[np.ndarray, Optional[np.ndarray]]:
    """Reads a cloud as the pagor tool does: KITTI .bin (float32 x, y, z, reflectance), .pcd
    (ASCII, binary, binary_compressed) or .ply, with labels from the file's `label` field or from
    a SemanticKITTI .label file (labels_path).

    Returns (points, labels): an N x 3 array [m] in the file's frame (float32; float64 for a
    cloud lying farther than 1 km from its file's origin, whose float32 coordinates would lose
    centimetres) and an N uint32 array, or None without labels. Points with a non-finite
    coordinate, or farther than 1e6 m from the cloud's centre, are dropped with a UserWarning
    naming the file. A missing file raises FileNotFoundError; a NUL byte in a path ValueError;
    an unreadable or malformed file pagor.Error (a ValueError) naming the file.
    """
    points, labels, warnings = _inputs.read_cloud(path, labels_path)
    _warn(warnings)
    return points, labels


def synthetic_scene(seed: int = 7) -> Dict[str, np.ndarray]:
    """The generated outdoor scene (``pagor register --synthetic SEED``): a dict with 'source',
    'target' (N x 3 float32 [m]), 'source_labels', 'target_labels' (uint32, semantickitti-train
    ids) and 'T_target_source' (4 x 4), the transform that maps source points into the target
    frame. seed: an int in 0 .. 2**64 - 1."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"seed: expected an int, got {type(seed).__name__}")
    if not 0 <= seed < 2**64:
        raise ValueError(f"seed: expected 0 .. 2**64 - 1, got {seed}")
    return _pagor.synthetic_scene(int(seed))


def default_config() -> Dict[str, Any]:
    """The default configuration as a dict: every parameter, with the keys of the JSON
    configuration (``pagor config --print-default``; docs/config.md lists them with units)."""
    return _pagor.default_config()


def preset_config(name: str) -> Dict[str, Any]:
    """A preset as a dict: 'default', 'paper' (the published configuration) or 'indoor' (a scan
    against a floor plan); preset_names() lists them. An unknown name raises pagor.Error (a
    ValueError) listing the names."""
    if not isinstance(name, str):
        raise TypeError(f"name: expected a str, got {type(name).__name__}")
    return _pagor.preset_config(name)


def preset_names() -> List[str]:
    """The names preset_config() takes."""
    return _pagor.preset_names()


def check_config(config: Dict[str, Any]) -> Dict[str, Any]:
    """Checks a configuration dict as register() would and returns it complete: absent keys
    filled from its 'preset' (else the default). An unknown key, a wrong type, a value out of
    range or a string that is not valid UTF-8 raises pagor.Error or ValueError naming the key
    path, e.g. 'config: graph.bogus: unknown key'; a config that is not a dict TypeError."""
    if not isinstance(config, dict):
        raise TypeError("config: expected a dict (the JSON configuration's keys), got "
                        f"{type(config).__name__}")
    return _pagor.check_config(config)


