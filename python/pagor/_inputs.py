"""What the public functions accept, turned into what the extension reads: clouds given as numpy
arrays, as Open3D point clouds (anything with a `.points` attribute) or as file paths; paths;
thread counts. Every misuse raises TypeError or ValueError naming the argument."""
from __future__ import annotations

import errno
import os
from typing import Any, Optional, Tuple, Union

import numpy as np

from . import _pagor

PathLike = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]


def is_path(value: Any) -> bool:
    return isinstance(value, (str, bytes, os.PathLike))


def path_bytes(path: Any, what: str) -> bytes:
    """A path as the file system's bytes; FileNotFoundError naming `what` when there is nothing
    there, ValueError for a NUL byte (the C library would cut the name there), TypeError for
    something that is not a path."""
    if not is_path(path):
        raise TypeError(f"{what}: expected a path (str, bytes or os.PathLike), got "
                        f"{type(path).__name__}")
    raw = os.fsencode(path)
    if b"\0" in raw:
        raise ValueError(f"{what}: the path contains a NUL byte: {os.fsdecode(raw)!r}")
    if not os.path.exists(raw):
        raise FileNotFoundError(errno.ENOENT, f"{what}: no such file", os.fsdecode(raw))
    return raw


def read_cloud(path: Any, labels_path: Any = None,
               what: str = "path") -> Tuple[np.ndarray, Optional[np.ndarray], list]:
    """(points, labels or None, warnings) of a file; see pagor.read_cloud."""
    raw = path_bytes(path, what)
    labels_raw = None if labels_path is None else path_bytes(labels_path, what + "_labels"
                                                             if what != "path" else "labels_path")
    points, labels, origin, warnings = _pagor.read_cloud(raw, labels_raw)
    if any(origin):
        # The file's frame: a cloud far from its origin comes back in float64, precise there.
        points = points.astype(np.float64) + np.asarray(origin, dtype=np.float64)
    return points, labels, warnings


def cloud(value: Any, labels: Any, what: str) -> Tuple[Any, Any, str, list]:
    """(points, labels, name for the report, warnings) of a cloud argument: an array (or
    anything numpy.asarray takes) as it is; an Open3D PointCloud (`.points`) as a view of its
    points; a path read with read_cloud (its labels, when the caller gives none)."""
    if is_path(value):
        points, file_labels, warnings = read_cloud(value, None, what)
        return points, file_labels if labels is None else labels, \
            os.fsdecode(value).encode("utf-8", "backslashreplace").decode("utf-8"), warnings
    if not isinstance(value, np.ndarray) and hasattr(value, "points"):
        # Open3D's legacy PointCloud: .points is a Vector3dVector, a buffer numpy views in place.
        return np.asarray(value.points), labels, "", []
    return value, labels, "", []


def threads(value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"threads: expected an int, got {type(value).__name__}")
    if value < 1:
        raise ValueError(f"threads: expected 1 or more, got {value}")
    if value > 2**31 - 1:
        raise ValueError(f"threads: expected at most 2147483647, got {value}")
    return int(value)


def config(value: Any) -> Any:
    if value is not None and not isinstance(value, dict):
        raise TypeError("config: expected a dict (the JSON configuration's keys) or None, got "
                        f"{type(value).__name__}")
    return value
