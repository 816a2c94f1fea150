"""Type stubs of the private extension pagor._pagor (python/pagor/pybind/). The package's own
modules (pagor/__init__.py, results.py) are the API and carry their own annotations."""
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

__version__: str

class Error(ValueError):
    """A core error (pagor::Error): the core's message, naming the file or key at fault."""

def default_config() -> Dict[str, Any]: ...
def preset_config(name: str) -> Dict[str, Any]: ...
def preset_names() -> List[str]: ...
def check_config(config: Any) -> Dict[str, Any]: ...
def dump_json(document: Dict[str, Any], indent: int) -> str: ...
def read_cloud(
    path: bytes, labels_path: Optional[bytes]
) -> Tuple[np.ndarray, Optional[np.ndarray], Tuple[float, float, float], List[str]]: ...
def synthetic_scene(seed: int) -> Dict[str, np.ndarray]: ...

# {'report': dict (schema pagor.register/1), 'landmarks': {'source' | 'target':
#  {'positions': (N, 3) float64, 'class_index': (N,) int32}}, 'correspondences': {'p', 'q':
#  (M, 3) float64, 'class_index', 'source', 'target': (M,) int32, 'origin': (M,) uint8,
#  'score': (M,) float64}, 'class_names': [str], 'input_warnings': [str]}
RunDict = Dict[str, Any]

def register_clouds(
    source: Any,
    target: Any,
    source_labels: Any,
    target_labels: Any,
    config: Optional[Dict[str, Any]],
    ground_truth: Any,
    threads: int,
    source_name: str,
    target_name: str,
) -> RunDict: ...
def register_correspondences(
    p: Any,
    q: Any,
    weights: Any,
    config: Optional[Dict[str, Any]],
    source: Any,
    target: Any,
    ground_truth: Any,
    threads: int,
) -> RunDict: ...

# define_sets: the result lines of `pagor bench --out` (sets.py). spec: ['manifest', PATH] or
# ['kitti', ROOT, SEQUENCE, PAIRS_FILE]. A row: {'index': int, 'pair': str, 'line': str | None,
# 'failed': str | None, 'warnings': [str]}.
def bench_pairs(
    spec: List[str], indices: List[int], config_json: str, threads: int = ...
) -> List[Dict[str, Any]]: ...
def pair_keys(spec: List[str], config_json: str) -> List[Tuple[str, str]]: ...
def tool_version() -> str: ...
def config_json(config: Optional[Dict[str, Any]]) -> str: ...
def config_file_json(path: str, base_preset: str = ...) -> str: ...
def progress_text(done: int, total: int, ran: int, to_run: int, elapsed_s: float) -> str: ...

class FileLock:
    def __init__(self, path: str, purpose: str) -> None: ...
    @property
    def lock_path(self) -> str: ...
