"""Where ``python3 -m pagor bench --out FILE`` keeps its results, as ``pagor bench --out`` does
(app/cli/bench_journal.hpp): each result line is keyed by its ``run_key``; as a pair finishes its
line is appended and flushed to FILE.partial (pairs in the order they finish); the finished run
writes FILE atomically with this run's lines in set order and removes FILE.partial. A killed run
leaves FILE as it was and FILE.partial with every pair finished so far; ``--resume`` continues
FILE.partial (or, when there is none, FILE), taking a line only for a pair whose key matches. One
writer at a time: FILE.lock, the same lock the pagor tool takes."""
from __future__ import annotations

import json
import os
import tempfile
from typing import Dict, Iterable, Optional

from . import _pagor


def _write_atomic(path: str, text: str) -> None:
    """Writes `path` whole: a temporary file beside it, flushed and renamed into place."""
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=os.path.basename(path) + ".", suffix=".tmp", dir=directory)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


class Journal:
    """The journal of `out`, locked while it is open (close() or finish() releases it)."""

    def __init__(self, out: str, resume: bool, purpose: str = "python3 -m pagor bench --out"):
        self.out = out
        self.partial = out + ".partial"
        self._lock: Optional[_pagor.FileLock] = _pagor.FileLock(out, purpose)
        self.done: Dict[str, str] = {}  # run_key -> the line as written
        if not resume:
            _write_atomic(self.partial, "")  # a fresh journal; `out` stays until finish()
        elif not os.path.exists(self.partial) and os.path.exists(out):
            with open(out, encoding="utf-8", errors="surrogateescape") as f:
                _write_atomic(self.partial, f.read())
        elif not os.path.exists(self.partial):
            _write_atomic(self.partial, "")
        with open(self.partial, encoding="utf-8", errors="surrogateescape") as f:
            text = f.read()
        if text and not text.endswith("\n"):  # a line cut by a kill: dropped, its pair re-run
            text = text[:text.rfind("\n") + 1]
            _write_atomic(self.partial, text)
        for number, line in enumerate(text.splitlines(), 1):
            if not line:
                continue
            where = f"{self.partial}:{number}"
            try:
                row = json.loads(line)
            except ValueError as e:
                raise ValueError(f"{where}: not JSON ({e})") from None
            if not isinstance(row, dict) or "pair" not in row or \
                    not isinstance(row.get("run_key"), str):
                raise ValueError(f"{where}: not a result line of pagor bench (needs \"pair\" and "
                                 "\"run_key\")")
            self.done[row["run_key"]] = line
        self._file = open(self.partial, "a", encoding="utf-8", errors="surrogateescape")

    def find(self, key: str) -> Optional[str]:
        """The line recorded under `key`, or None."""
        return self.done.get(key) if key else None

    def append(self, line: str, key: str) -> None:
        """Appends one result line (as the extension made it) and flushes it to the disk."""
        self._file.write(line + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())
        self.done[key] = line

    def finish(self, keys: Iterable[str]) -> None:
        """Writes `out` with the lines recorded under `keys`, in that order (a key without a
        line, a pair that failed, is left out), removes the journal and releases the lock."""
        text = "".join(self.done[k] + "\n" for k in keys if k in self.done)
        self._file.close()
        _write_atomic(self.out, text)
        os.unlink(self.partial)
        self.close()

    def close(self) -> None:
        if not self._file.closed:
            self._file.close()
        self._lock = None
