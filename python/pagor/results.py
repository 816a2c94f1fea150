"""The result of a registration: `Result` with its `Level`s, `Landmarks` and `Correspondences`.

Plain Python objects holding the report (a dict, schema ``pagor.register/1``: what
``pagor register --json`` writes) and numpy arrays, so they pickle (multiprocessing, Dask) and
compare as data. Every attribute is read from the report or from the arrays the run produced; none
is computed here on its own account.
"""
from __future__ import annotations

from typing import Any, Dict, Generic, List, Optional, Tuple, TypeVar, overload

import numpy as np

from . import _pagor

__all__ = ["Result", "Level", "Landmarks", "Correspondences", "ORIGINS"]

#: The names of CorrespondenceOrigin, in the order of its codes: who made a correspondence.
ORIGINS: Tuple[str, ...] = ("landmark", "matcher")


def _transform(value: Any) -> Optional[np.ndarray]:
    """A report's 4 x 4 row-major nested list as a float64 array; None for null."""
    return None if value is None else np.array(value, dtype=np.float64).reshape(4, 4)


_T = TypeVar("_T")


def _renamed_state(state: Dict[str, Any], old: str) -> Dict[str, Any]:
    """A pickled object's state with the report under `_data` (pickles of 0.1 before it kept it
    as `_level` or `_report`)."""
    if "_data" not in state and old in state:
        state = dict(state)
        state["_data"] = state.pop(old)
    return state


class _Key(Generic[_T]):
    """A read-only attribute that is the report's key of the same name (None where the report
    does not hold it): the name is written once, as the attribute's."""

    def __init__(self, doc: str):
        self.__doc__ = doc
        self._key = ""

    def __set_name__(self, owner: type, name: str) -> None:
        self._key = name

    @overload
    def __get__(self, obj: None, owner: type) -> "_Key[_T]": ...

    @overload
    def __get__(self, obj: object, owner: type) -> _T: ...

    def __get__(self, obj: Any, owner: Optional[type] = None) -> Any:
        if obj is None:
            return self
        return obj._data.get(self._key)

    def __set__(self, obj: Any, value: Any) -> None:
        raise AttributeError(f"'{self._key}' is read-only: it is the report's")


def _indent(indent: Optional[int]) -> int:
    if indent is None:
        return -1
    if isinstance(indent, bool) or not isinstance(indent, int):
        raise TypeError(f"indent: expected an int or None, got {type(indent).__name__}")
    return max(-1, min(16, indent))


class Level:
    """One level of the pyramid: its threshold, graph, clique and pose (the report's
    ``levels[i]``; attributes the report does not hold are None)."""

    def __init__(self, level: Dict[str, Any]):
        self._data = level
        #: The level's densest clique: indices into `Result.correspondences`, increasing (int64).
        self.clique: np.ndarray = np.asarray(level.get("clique", []), dtype=np.int64)

    level: _Key[int] = _Key(
        """The level's index, 0 for the tightest threshold.""")

    epsilon: _Key[float] = _Key(
        """The TRIM threshold: [m] for a difference TRIM, unitless for a ratio TRIM.""")

    vertices: _Key[int] = _Key(
        """Correspondences with at least one consistency edge at this level.""")

    edges: _Key[int] = _Key(
        """Consistency edges at this level.""")

    clique_size: _Key[int] = _Key(
        """Members of the level's clique (len(clique)).""")

    clique_proven: _Key[Optional[bool]] = _Key(
        """Whether the clique is proven maximum on its level.""")

    inliers: _Key[int] = _Key(
        """GNC-TLS inliers of the level's pose (a count).""")

    pose_valid: _Key[bool] = _Key(
        """Whether the level has a pose (its clique was large enough for the pose model).""")

    @property
    def T_target_source(self) -> Optional[np.ndarray]:
        """The level's pose (4 x 4 float64) in the frames of the inputs; None when invalid."""
        return _transform(self._data.get("T_target_source"))

    score_D: _Key[Optional[float]] = _Key(
        """Verification score D [m] on the clouds, lower is better; None when not scored (no
    valid pose, or no clouds).""")

    support: _Key[Optional[int]] = _Key(
        """Selected without clouds: the correspondences the pose explains; None otherwise.""")

    translation_error_m: _Key[Optional[float]] = _Key(
        """Translation error against the ground truth [m]; None without one.""")

    rotation_error_deg: _Key[Optional[float]] = _Key(
        """Rotation error against the ground truth [deg]; None without one.""")

    success: _Key[Optional[bool]] = _Key(
        """Within the success criterion of the ground truth; None without one.""")

    def to_dict(self) -> Dict[str, Any]:
        """The report's ``levels[i]`` (the dict itself: do not change it)."""
        return self._data

    def __setstate__(self, state: Dict[str, Any]) -> None:
        self.__dict__.update(_renamed_state(state, "_level"))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Level) and self._data == other._data

    def __repr__(self) -> str:
        return (f"<pagor.Level {self._data.get('level', -1)}: epsilon "
                f"{self._data.get('epsilon', 0.0):g}, clique {self._data.get('clique_size', 0)}"
                f", inliers {self._data.get('inliers', 0)}>")


class _Rows:
    """Rows that each have a class: `class_index` into `class_names`, -1 for none."""

    class_index: np.ndarray
    class_names: Tuple[str, ...]

    @property
    def class_name(self) -> np.ndarray:
        """Each row's class name (an array of str; "" where there is none: a matcher's
        correspondence)."""
        table = np.array(list(self.class_names) + [""], dtype=str)
        return table[np.where(self.class_index < 0, len(self.class_names), self.class_index)]

    def __len__(self) -> int:
        return len(self.class_index)


class Landmarks(_Rows):
    """A cloud's landmarks: `positions` (N x 3 float64 [m], in the frame of the points as given)
    and `class_index` (N int32, into `class_names`; the configured classes)."""

    def __init__(self, positions: np.ndarray, class_index: np.ndarray,
                 class_names: Tuple[str, ...]):
        self.positions = positions
        self.class_index = class_index
        self.class_names = class_names

    def __repr__(self) -> str:
        return f"<pagor.Landmarks: {len(self)}>"


class Correspondences(_Rows):
    """The putative correspondences the pyramid was built on; each level's `clique` indexes
    them. `p`, `q`: source and target points (N x 3 float64 [m], in the frames of the inputs);
    `class_index` (N int32, into `class_names`; -1 for a matcher's correspondence, which has no
    class); `origin` (N str: 'landmark' from the clouds' landmarks, 'matcher' given to
    register_correspondences); `source`, `target`: the landmark (or keypoint) ids (N int32);
    `score`: a landmark pair's similarity in [0, 1], or a matcher's weight (N float64)."""

    def __init__(self, arrays: Dict[str, np.ndarray], class_names: Tuple[str, ...]):
        self.p: np.ndarray = arrays["p"]
        self.q: np.ndarray = arrays["q"]
        self.class_index: np.ndarray = arrays["class_index"]
        self.origin: np.ndarray = np.array(ORIGINS, dtype=str)[arrays["origin"]]
        self.source: np.ndarray = arrays["source"]
        self.target: np.ndarray = arrays["target"]
        self.score: np.ndarray = arrays["score"]
        self.class_names = class_names

    def __repr__(self) -> str:
        counts = ", ".join(f"{o} {int((self.origin == o).sum())}" for o in ORIGINS)
        return f"<pagor.Correspondences: {len(self)} ({counts})>"


class Result:
    """A registration's outcome. The numbers are the report's (`to_dict()`, `to_json()`: schema
    ``pagor.register/1``, what ``pagor register --json`` writes); landmarks, correspondences and
    cliques are numpy arrays. Picklable.

    Attributes besides the report's: `levels` (a list of Level, each with its `clique` as an
    int64 array), `landmarks` ({'source': Landmarks, 'target': Landmarks}; empty without clouds)
    and `correspondences` (Correspondences: the rows the cliques index)."""

    def __init__(self, run: Dict[str, Any]):
        self._data: Dict[str, Any] = run["report"]
        names = tuple(run["class_names"])
        self.landmarks: Dict[str, Landmarks] = {
            side: Landmarks(run["landmarks"][side]["positions"],
                            run["landmarks"][side]["class_index"], names)
            for side in ("source", "target")}
        """Each cloud's landmarks ('source', 'target'); empty without clouds."""
        self.correspondences = Correspondences(run["correspondences"], names)
        """The correspondences the levels' cliques index."""
        self.levels: List[Level] = [Level(level) for level in self._data.get("levels", [])]
        """Per pyramid level: threshold, clique, pose, score (pagor.Level)."""

    @property
    def T_target_source(self) -> Optional[np.ndarray]:
        """The selected transform (4 x 4 float64) that maps source points into the target frame,
        in the frames of the points as given; None when no level has a valid pose."""
        return _transform(self._data.get("T_target_source"))

    selected_level: _Key[Optional[int]] = _Key(
        """Index into `levels` of the selected pose; None when no level has a valid pose.""")

    selected_by: _Key[str] = _Key(
        """'score_D' (lowest D on the clouds) or 'without_clouds' (the best support among the
    correspondences, when there were no clouds).""")

    @property
    def accepted(self) -> bool:
        """The verdict: whether the selected pose is trusted. False when there is no pose, and
        False when there were no clouds to verify it on (`verified` is then False too)."""
        return bool(self._data["acceptance"]["accepted"]) and self.T_target_source is not None

    @property
    def verified(self) -> bool:
        """Whether the pose was judged on clouds (False for correspondences alone)."""
        return bool(self._data["acceptance"].get("verified", True))

    @property
    def acceptance(self) -> Dict[str, Any]:
        """The verdict's numbers: accepted, verified, overlap, inliers, margin, sharpness,
        ambiguity, alternative, adopted (None, or the alternative taken in place of the selected
        pose: from, ratio, inlier_count, score_D, selected_reason, T_target_source), tests, reason (why it was rejected, or that there was nothing to
        verify on), wrong_pose_accepted (accepted while the ground truth calls it wrong)."""
        return self._data["acceptance"]

    @property
    def acceptance_tests(self) -> List[Dict[str, Any]]:
        """Every test of the verdict with its value and threshold, in the order the reason is
        chosen: dicts with name, value, threshold, comparison (">=" or "<="), passed, applies,
        unit, description. Empty when nothing was judged."""
        return self._data["acceptance"].get("tests", [])

    @property
    def alternative(self) -> Optional[Dict[str, Any]]:
        """The best distinct pose that explains the clouds about as well as the selected one
        (description, ratio, only_alternative and only_selected: the disagreeing structure
        points behind the ratio, T_target_source as a 4 x 4 array), or None."""
        alt = self._data["acceptance"].get("alternative")
        if alt is None:
            return None
        return {**alt, "T_target_source": _transform(alt["T_target_source"])}

    @property
    def wrong_pose_accepted(self) -> bool:
        """Accepted although the ground truth calls the pose wrong (False without a truth)."""
        return bool(self._data["acceptance"].get("wrong_pose_accepted", False))

    ground_truth: _Key[Optional[Dict[str, Any]]] = _Key(
        """Against the ground truth given: T_target_source, errors, success, upper_bound (some
    level's pose is right); None without one.""")

    diagnosis: _Key[Optional[Dict[str, Any]]] = _Key(
        """The stage at fault against the ground truth (a dict with 'verdict'); None without
    ground truth.""")

    timings_ms: _Key[Dict[str, float]] = _Key(
        """Wall time per stage and in total ('total') [ms].""")

    @property
    def warnings(self) -> List[str]:
        """The run's warnings (also in the report)."""
        return self._data.get("warnings", [])

    config: _Key[Dict[str, Any]] = _Key(
        """The full configuration used (pagor.check_config's form).""")

    def to_dict(self) -> Dict[str, Any]:
        """The report as a dict (json.loads(to_json())); the Result's own, do not change it."""
        return self._data

    def __setstate__(self, state: Dict[str, Any]) -> None:
        self.__dict__.update(_renamed_state(state, "_report"))

    def to_json(self, indent: Optional[int] = 2) -> str:
        """The report as JSON text, exactly as ``pagor register --json`` writes it (schema
        pagor.register/1; keys sorted). indent: spaces per level, at most 16 (larger is
        clamped); -1 or None: one line."""
        return _pagor.dump_json(self._data, _indent(indent))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Result) and self._data == other._data

    def __repr__(self) -> str:
        T = self.T_target_source
        if T is None:
            return "<pagor.Result: no valid candidate>"
        verdict = ("accepted" if self.accepted else "rejected") if self.verified else \
            "not verified (no clouds)"
        return (f"<pagor.Result: level {self.selected_level}, t = ({T[0, 3]:.3f}, {T[1, 3]:.3f}, "
                f"{T[2, 3]:.3f}) m, {verdict}>")
