"""What the run_pairs and Dask tests share: a small set of the shared pairs (a manifest of four
semreg-dev pairs, one a known negative, with absolute paths), the CLI's result lines for it, and
rows without what depends on when and by which build they were made."""
import json
import os
import subprocess
from pathlib import Path

from conftest import SHARED_DATA, SOURCE_DIR

SEMREG = SHARED_DATA / "semreg-dev"
SEMREG_CONFIG = SOURCE_DIR / "bench" / "manifests" / "semreg-dev.json"
NAMES = ["03", "04", "05", "03-vs-08"]


def have_semreg():
    return (SEMREG / "03" / "source.pcd").exists()


def pair_dicts():
    """The four pairs as run_pairs' list form."""
    pairs = []
    for name in NAMES[:3]:
        d = SEMREG / name
        pairs.append({"source": d / "source.pcd", "target": d / "target.pcd",
                      "gt": d / "T_target_source.txt", "name": name})
    pairs.append({"source": SEMREG / "03" / "source.pcd", "target": SEMREG / "08" / "target.pcd",
                  "name": "03-vs-08", "overlap": False})
    return pairs


def write_manifest(path: Path) -> Path:
    lines = []
    for p in pair_dicts():
        words = [f'"{p["source"]}"', f'"{p["target"]}"']
        if "gt" in p:
            words.append(f'gt="{p["gt"]}"')
        words.append(f'name={p["name"]}')
        if p.get("overlap") is False:
            words.append("overlap=no")
        lines.append(" ".join(words))
    path.write_text("# four semreg-dev pairs\n" + "\n".join(lines) + "\n")
    return path


def _without_times(value):
    if isinstance(value, dict):
        return {k: _without_times(v) for k, v in value.items() if not k.endswith("_ms")}
    if isinstance(value, list):
        return [_without_times(v) for v in value]
    return value


def untimed(row: dict, build: bool = False) -> dict:
    """A row without its times (every key ending in _ms: timings_ms, the diagnosis' time_ms,
    each level's clique_time_ms); with `build`, also without
    what names the build that made it (run_key, tool_version: the pagor tool and the Python
    extension are two builds)."""
    row = _without_times(row)
    if build:
        row.pop("run_key", None)
        row.pop("tool_version", None)
    return row


def read_rows(path: Path):
    return [json.loads(line) for line in Path(path).read_text().splitlines()]


def cli_rows(manifest: Path, out: Path, *extra):
    """`pagor bench --manifest M --config semreg-dev.json --out F`: its lines as dicts."""
    subprocess.run([os.environ["PAGOR_CLI"], "bench", "--manifest", str(manifest), "--config",
                    str(SEMREG_CONFIG), "--out", str(out), *extra], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    return read_rows(out)
