"""``python3 -m pagor bench``: the pairs of a set, on this machine's cores or on a Dask cluster,
written as ``pagor bench --out`` writes them (one result line per pair, in set order, through a
journal: a killed run loses no finished pair, ``--resume`` continues it, one writer at a time).

    python3 -m pagor bench --manifest M [--config C] [--preset P] [--jobs N | --scheduler ADDRESS] --out F [--resume]
    python3 -m pagor bench --kitti-root ROOT [--sequence 00] --pairs FILE ... --out F

Errors are one line naming the file or argument, exit status 1; wrong usage exits with 2."""
from __future__ import annotations

import argparse
import os
import sys
from typing import List, Optional

from . import _pagor, sets
from ._journal import Journal


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python3 -m pagor")
    commands = parser.add_subparsers(dest="command", required=True)
    bench = commands.add_parser(
        "bench", help="run a set of pairs and write pagor bench's result lines")
    what = bench.add_mutually_exclusive_group(required=True)
    what.add_argument("--manifest", metavar="FILE", help="pairs manifest (as pagor bench's)")
    what.add_argument("--kitti-root", metavar="DIR", help="KITTI root holding sequences/")
    bench.add_argument("--sequence", default="00", help="KITTI sequence (default 00)")
    bench.add_argument("--pairs", metavar="FILE", help="KITTI pairs file (with --kitti-root)")
    bench.add_argument("--config", metavar="FILE",
                       help="configuration JSON (absent keys: the preset's values)")
    bench.add_argument("--preset", metavar="NAME", choices=_pagor.preset_names(),
                       help="base configuration: " + ", ".join(_pagor.preset_names())
                       + " (default default; paper: the published one)")
    where = bench.add_mutually_exclusive_group()
    where.add_argument("--jobs", metavar="N", help="pairs at once on this machine (default 1; "
                       "'auto': the cores)")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="a Dask scheduler, e.g. tcp://host:8786: its workers run the pairs")
    bench.add_argument("--shard-size", metavar="N", type=int,
                       help="pairs per Dask task (default: about four tasks per worker)")
    bench.add_argument("--threads", metavar="N", type=int, default=1,
                       help="threads inside each pair (default 1)")
    bench.add_argument("--out", metavar="FILE", required=True,
                       help="the results: one JSON line per pair")
    bench.add_argument("--resume", action="store_true",
                       help="continue a killed run, keeping the pairs already written")
    bench.add_argument("--quiet", action="store_true", help="no progress line")
    return parser


def _jobs(text: Optional[str], parser: argparse.ArgumentParser) -> int:
    if text is None or text == "auto":
        return os.cpu_count() or 1 if text else 1
    if not text.isdigit() or int(text) < 1:
        parser.error(f"--jobs: expected a number of jobs 1 or more or 'auto', got '{text}'")
    return int(text)


def _same_file(a: str, b: str) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.abspath(a) == os.path.abspath(b)


def bench(args: argparse.Namespace, parser: argparse.ArgumentParser) -> int:
    if args.kitti_root and not args.pairs:
        parser.error("--kitti-root needs --pairs FILE")
    if args.shard_size is not None and args.shard_size < 1:
        parser.error(f"--shard-size: expected 1 or more, got {args.shard_size}")
    if args.threads < 1:
        parser.error(f"--threads: expected 1 or more, got {args.threads}")
    jobs = _jobs(args.jobs, parser)
    inputs = [p for p in (args.manifest, args.config, args.pairs) if p]
    for path in inputs:
        if os.path.exists(args.out) and _same_file(args.out, path):
            parser.error(f"--out {args.out} is an input of the run")
    pairs = (sets.KittiPairs(args.kitti_root, args.pairs, args.sequence) if args.kitti_root
             else args.manifest)
    spec, text = sets._spec(pairs, args.scheduler is not None), sets.config_json(args.config, args.preset)
    names = sets.pair_keys(spec, text)
    journal = Journal(args.out, args.resume)
    try:
        keys = [key for _, key in names]
        skip = {i for i, key in enumerate(keys) if journal.find(key)}
        failed = 0
        for row in sets.iter_rows(pairs, jobs=jobs, client=args.scheduler,
                                  progress=not args.quiet, threads=args.threads,
                                  shard_size=args.shard_size, skip=skip,
                                  _spec_text=(spec, text)):
            for message in row["warnings"]:
                print(f"pagor: warning: {message}", file=sys.stderr)
            if row["line"] is None:
                failed += 1
                print(f"{row['pair']}: failed: {row['failed']}", file=sys.stderr)
            elif keys[row["index"]]:
                journal.append(row["line"], keys[row["index"]])
        journal.finish(keys)
    except BaseException:
        journal.close()  # FILE.partial stays for --resume
        raise
    print(f"{len(names) - failed} of {len(names)} pairs in {args.out}"
          + (f" ({len(skip)} taken from the earlier run)" if skip else "")
          + (f"; {failed} failed" if failed else ""))
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        return bench(args, parser)
    except (_pagor.Error, OSError, ValueError, RuntimeError) as e:
        print(f"python3 -m pagor: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("python3 -m pagor: interrupted; --resume continues", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
