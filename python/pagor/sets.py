"""Many pairs at once: `run_pairs` runs a set of pairs (a manifest, a KITTI pairs file or a list)
and gives the rows ``pagor bench --out`` writes, on this machine's cores or on the workers of a
Dask cluster (dask.distributed). Each row is made by the core as the tool makes it (the
extension's bench_pairs: the pair's report, its name, run key and the build that made it).

With Dask the pairs go to the workers in shards of a few pairs; each worker reads the pairs'
files itself (they must be on storage every worker sees, at the same paths) and sends back the
shard's rows. A shard is a pure function of its arguments (no side effects), so a shard whose
worker died is simply run again by the scheduler, and the rows are taken once per pair whatever
comes back twice."""
from __future__ import annotations

import hashlib
import math
import os
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from typing import Any, Dict, Iterator, List, NamedTuple, Optional, Sequence, Set, Tuple

from . import _pagor

__all__ = ["run_pairs", "KittiPairs", "Rows"]


class KittiPairs(NamedTuple):
    """A KITTI pairs file (``source target`` frame numbers per line) of one sequence, as
    ``pagor bench --kitti-root ROOT --sequence SEQ --pairs FILE``."""
    root: str
    pairs: str
    sequence: str = "00"


class Rows(list):
    """The result lines of the pairs that ran, as dicts, in set order (``pagor bench --out``'s
    lines). `failed` maps the name of each pair that failed on its own account to why (naming
    its file): such a pair has no row, as in the tool."""
    failed: Dict[str, str]


# What the workers are told the set is: ("manifest", PATH), ("kitti", ROOT, SEQ, FILE) or
# ("manifest-text", TEXT) for a list of pairs, which each worker writes to a file of its own.
Spec = Tuple[str, ...]


def _quote(value: Any, what: str) -> str:
    text = os.fspath(value)
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if not isinstance(text, str) or not text:
        raise TypeError(f"{what}: expected a path or text, got {type(value).__name__}")
    if "\n" in text or "\0" in text:
        raise ValueError(f"{what}: a line break or NUL in {text!r}")
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


_PAIR_KEYS = ("gt", "source_labels", "target_labels", "scheme", "name", "overlap")


def _manifest_line(pair: Any, k: int) -> str:
    """One manifest line of a pair given as (source, target[, gt]) or a dict with 'source',
    'target' and the manifest's keys (gt, source_labels, target_labels, scheme, name,
    overlap)."""
    what = f"pairs[{k}]"
    if isinstance(pair, dict):
        unknown = set(pair) - {"source", "target", *_PAIR_KEYS}
        if unknown:
            raise ValueError(f"{what}: unknown key {sorted(unknown)[0]!r} (known: source, "
                             f"target, {', '.join(_PAIR_KEYS)})")
        if "source" not in pair or "target" not in pair:
            raise ValueError(f"{what}: needs 'source' and 'target'")
        fields = dict(pair)
    elif isinstance(pair, (tuple, list)) and len(pair) in (2, 3):
        fields = {"source": pair[0], "target": pair[1]}
        if len(pair) == 3 and pair[2] is not None:
            fields["gt"] = pair[2]
    else:
        raise TypeError(f"{what}: expected (source, target[, gt]) or a dict, got "
                        f"{type(pair).__name__}")
    words = []
    for key in ("source", "target", *_PAIR_KEYS):
        if fields.get(key) is None:
            continue
        value = fields[key]
        if key in ("source", "target", "gt", "source_labels", "target_labels"):
            value = _absolute(value)  # the manifest is written elsewhere
        if key == "overlap" and isinstance(value, bool):
            value = "yes" if value else "no"
        quoted = _quote(value, f"{what}.{key}")
        words.append(quoted if key in ("source", "target") else f"{key}={quoted}")
    return " ".join(words)


def _absolute(path: Any) -> str:
    """A path from the working directory, `..` kept: the names in the rows stay those of the
    files as given (os.path.abspath would rewrite them)."""
    text = os.fsdecode(os.fspath(path))
    return text if os.path.isabs(text) else os.path.join(os.getcwd(), text)


def _spec(pairs: Any, remote: bool = False) -> Spec:
    """What the extension is told the set is. Paths stay as given on this machine (the rows then
    name the files as `pagor bench` run here would); for `remote` workers, which know no working
    directory, they are made absolute. A list's pairs are always absolute (their manifest is
    written elsewhere)."""
    where = _absolute if remote else (lambda p: os.fsdecode(os.fspath(p)))
    if isinstance(pairs, KittiPairs):
        return ("kitti", where(pairs.root), str(pairs.sequence), where(pairs.pairs))
    if isinstance(pairs, (str, bytes, os.PathLike)):
        path = os.fsdecode(os.fspath(pairs))
        if not os.path.exists(path):
            raise FileNotFoundError(2, "pairs: no such manifest", path)
        return ("manifest", where(path))
    if isinstance(pairs, Sequence) and not isinstance(pairs, (str, bytes)):
        if not pairs:
            raise ValueError("pairs: an empty list")
        return ("manifest-text", "".join(_manifest_line(p, k) + "\n"
                                         for k, p in enumerate(pairs)))
    raise TypeError("pairs: expected a manifest path, a KittiPairs or a list of pairs, got "
                    f"{type(pairs).__name__}")


def _resolve(spec: Spec) -> Tuple[List[str], str]:
    """The spec the extension reads, and the temporary path to call 'pairs' in messages."""
    if spec[0] != "manifest-text":
        return list(spec), ""
    digest = hashlib.sha256(spec[1].encode("utf-8", "surrogateescape")).hexdigest()[:16]
    path = os.path.join(tempfile.gettempdir(), f"pagor-pairs-{os.getuid()}-{digest}.txt")
    if not os.path.exists(path):  # content-named: every writer writes the same bytes
        fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path))
        with os.fdopen(fd, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(spec[1])
        os.replace(tmp, path)
    return ["manifest", path], path


def _call(function, spec: Spec, *args):
    resolved, temporary = _resolve(spec)
    try:
        return function(resolved, *args)
    except _pagor.Error as e:
        if temporary:  # "…/pagor-pairs-….txt:3: …" is the list's pairs[2]
            message = str(e)
            prefix = temporary + ":"
            if message.startswith(prefix):
                line, _, rest = message[len(prefix):].partition(":")
                if line.isdigit():
                    message = f"pairs[{int(line) - 1}]:{rest}"
            message = message.replace(temporary, "pairs")
            raise _pagor.Error(message) from None
        raise


def run_shard(spec: Spec, indices: List[int], config_json: str, threads: int = 1) -> List[dict]:
    """Runs pairs `indices` of the set (what a worker does with a shard): a row dict per pair,
    {index, pair, line (the result line, or None), failed (why, or None), warnings}. Reads only
    the pairs' files; no side effects, so running a shard twice gives the same rows."""
    return _call(_pagor.bench_pairs, spec, list(indices), config_json, threads)


def config_json(config: Any, preset: Optional[str] = None) -> str:
    """The configuration as the JSON text the workers parse: None (the default), a dict (the
    JSON configuration's keys) or the path of a JSON configuration file (as ``--config``).
    ``preset`` (as ``--preset``; None: 'default') fills the keys the configuration leaves out; a
    'preset' key of its own wins, as in ``pagor bench``. An unknown preset raises ValueError, even
    where the configuration names its own."""
    if preset is not None:
        names = _pagor.preset_names()
        if not isinstance(preset, str):
            raise TypeError(f"preset: expected a str, got {type(preset).__name__}")
        if preset not in names:
            raise ValueError(f"preset: unknown preset '{preset}' (presets: {', '.join(names)})")
    if config is None or isinstance(config, dict):
        if preset is not None:
            config = {"preset": preset, **(config or {})}
        return _pagor.config_json(config)
    if isinstance(config, (str, bytes, os.PathLike)):
        path = os.fsdecode(os.fspath(config))
        if not os.path.exists(path):
            raise FileNotFoundError(2, "config: no such file", path)
        return _pagor.config_file_json(path, "default" if preset is None else preset)
    raise TypeError("config: expected None, a dict or a JSON file's path, got "
                    f"{type(config).__name__}")


def pair_keys(spec: Spec, config_text: str) -> List[Tuple[str, str]]:
    """Each pair's (name, run key) in set order; bad input raises pagor.Error naming the file."""
    return _call(_pagor.pair_keys, spec, config_text)


class _Progress:
    """One line on stderr: pairs done, rate and time left (the core's progress_text)."""

    def __init__(self, total: int, to_run: int, show: bool):
        self.total, self.to_run, self.show = total, to_run, show
        self.done, self.ran = total - to_run, 0
        self.t0 = time.monotonic()
        self.tty = sys.stderr.isatty()

    def step(self) -> None:
        self.done += 1
        self.ran += 1
        if self.show and self.tty:
            print("\r" + self.text().ljust(70), end="", file=sys.stderr, flush=True)

    def text(self) -> str:
        return _pagor.progress_text(self.done, self.total, self.ran, self.to_run,
                                    time.monotonic() - self.t0)

    def close(self) -> None:
        if self.show:
            print(("\r" if self.tty else "") + self.text().ljust(70), file=sys.stderr, flush=True)


def _shards(indices: List[int], size: int) -> List[List[int]]:
    return [indices[k:k + size] for k in range(0, len(indices), size)]


def _local_rows(spec: Spec, indices: List[int], text: str, jobs: int,
                threads: int) -> Iterator[dict]:
    if jobs <= 1:
        for i in indices:
            yield from run_shard(spec, [i], text, threads)
        return
    with ThreadPoolExecutor(max_workers=jobs) as pool:  # the extension releases the GIL
        futures = [pool.submit(run_shard, spec, [i], text, threads) for i in indices]
        try:
            for future in as_completed(futures):
                yield from future.result()
        finally:
            for future in futures:
                future.cancel()


def _dask_rows(spec: Spec, indices: List[int], text: str, client: Any, threads: int,
               shard_size: Optional[int], progress: bool) -> Iterator[dict]:
    from dask.base import tokenize
    from distributed import as_completed as dask_completed

    if progress and getattr(client, "dashboard_link", None):
        print(f"pagor: Dask dashboard at {client.dashboard_link}", file=sys.stderr, flush=True)
    workers = max(1, len(client.scheduler_info().get("workers", {})))
    size = shard_size or max(1, math.ceil(len(indices) / (4 * workers)))
    futures = []
    for shard in _shards(indices, size):
        key = f"pagor-shard-{shard[0]}-{tokenize(run_shard, spec, shard, text, threads)}"
        futures.append(client.submit(run_shard, spec, shard, text, threads, key=key, retries=2))
    try:
        for future in dask_completed(futures):
            try:
                rows = future.result()
            except Exception as e:  # the shard failed on every try (its workers kept dying)
                raise RuntimeError(f"pairs {future.key}: the shard failed on the workers: "
                                   f"{type(e).__name__}: {e}") from e
            yield from rows
    finally:
        client.cancel(futures)


def iter_rows(pairs: Any, config: Any = None, *, jobs: Optional[int] = None,
              client: Any = None, progress: bool = True, threads: int = 1,
              shard_size: Optional[int] = None, skip: Optional[Set[int]] = None,
              preset: Optional[str] = None,
              _spec_text: Optional[Tuple[Spec, str]] = None) -> Iterator[dict]:
    """The row dicts of run_shard, each pair once, as they finish (any order): what run_pairs
    and ``python3 -m pagor bench`` are made of. `skip`: set indices not to run (taken from an
    earlier run)."""
    spec, text = _spec_text or (_spec(pairs, client is not None), config_json(config, preset))
    names = pair_keys(spec, text)
    indices = [i for i in range(len(names)) if not skip or i not in skip]
    jobs = _jobs(jobs)
    if isinstance(client, str):
        from distributed import Client
        with Client(client) as own:
            yield from iter_rows(pairs, config, client=own, progress=progress, threads=threads,
                                 shard_size=shard_size, skip=skip, _spec_text=(spec, text))
        return
    bar = _Progress(len(names), len(indices), progress)
    seen: Set[int] = set()
    rows = (_dask_rows(spec, indices, text, client, threads, shard_size, progress)
            if client is not None else _local_rows(spec, indices, text, jobs, threads))
    for row in rows:
        if row["index"] in seen:  # a shard run twice (its first worker died after sending it)
            continue
        seen.add(row["index"])
        bar.step()
        yield row
    bar.close()


def _jobs(jobs: Any) -> int:
    if jobs is None:
        return 1
    if jobs == "auto":
        return os.cpu_count() or 1
    if isinstance(jobs, bool) or not isinstance(jobs, int):
        raise TypeError(f"jobs: expected an int or 'auto', got {type(jobs).__name__}")
    if jobs < 1:
        raise ValueError(f"jobs: expected 1 or more, got {jobs}")
    return jobs


def run_pairs(pairs: Any, config: Any = None, *, jobs: Optional[int] = None, client: Any = None,
              progress: bool = True, threads: int = 1, shard_size: Optional[int] = None,
              preset: Optional[str] = None) -> Rows:
    """Runs every pair of a set and returns its rows: the lines ``pagor bench --out`` writes, as
    dicts (pagor.register/1 without the config, with 'pair', 'run_key' and 'tool_version'), in
    set order.

    pairs: a manifest's path (``pagor bench --manifest``: paths relative to it), a
        KittiPairs(root, pairs_file, sequence), or a list of pairs, each (source, target[, gt])
        or a dict with 'source', 'target' and the manifest's keys (gt, source_labels,
        target_labels, scheme, name, overlap); a pair's name is then its line number, 1 up.
        The rows name the files as the tool run here would; a list's relative paths, and with a
        client a relative manifest path, are taken from the working directory (made absolute,
        `..` kept), so those rows name the files by absolute paths.
    config: None (the default), a dict with the JSON configuration's keys, or a JSON file's path
        (as ``--config``).
    preset: the preset the configuration's absent keys come from (as ``--preset``: 'default',
        'paper', 'indoor'); a 'preset' key in the configuration wins.
    jobs: pairs at once on this machine, each on a thread of its own (None: 1; 'auto': the
        cores). Ignored with a client.
    client: a dask.distributed Client, or a scheduler's address ('tcp://host:8786'): the pairs
        go to its workers in shards of `shard_size` pairs (default: about four shards per
        worker); the workers read the files themselves, so the paths must be valid on each.
        A shard whose worker dies is run again; every pair is taken once.
    progress: a line on stderr with pairs done, rate and time left (and the Dask dashboard's
        address when there is one).
    threads: for each pair's parallel stages (as ``--threads``).

    A pair that fails on its own account (a file that cannot be read) has no row: it is in the
    result's `failed` (name: why) and a UserWarning names it. A configuration error raises
    pagor.Error naming the key; a missing manifest FileNotFoundError.
    """
    import json
    import warnings

    spec, text = _spec(pairs, client is not None), config_json(config, preset)
    lines: Dict[int, str] = {}
    out = Rows()
    out.failed = {}
    for row in iter_rows(pairs, config, jobs=jobs, client=client, progress=progress,
                         threads=threads, shard_size=shard_size, _spec_text=(spec, text)):
        for message in row["warnings"]:
            warnings.warn(message, UserWarning, stacklevel=2)
        if row["line"] is None:
            out.failed[row["pair"]] = row["failed"]
            warnings.warn(f"pair {row['pair']} failed: {row['failed']}", UserWarning,
                          stacklevel=2)
        else:
            lines[row["index"]] = row["line"]
    out.extend(json.loads(lines[i]) for i in sorted(lines))
    return out
