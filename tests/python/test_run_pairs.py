"""pagor.run_pairs and `python3 -m pagor bench` on this machine: the rows are the lines `pagor
bench --out` writes (times and the build's name aside), with one job and two, from a manifest or
a list; the file is the tool's, a killed run resumes, the lock is the tool's, bad input names the
argument."""
import json
import os
import subprocess
import sys

import pytest

import pagor
from bench_rows import (NAMES, SEMREG_CONFIG, cli_rows, have_semreg, pair_dicts, read_rows,
                        untimed)

pytestmark = pytest.mark.skipif(not have_semreg(), reason="no semreg-dev data")


@pytest.fixture(scope="module")
def one_job(manifest):
    return pagor.run_pairs(manifest, SEMREG_CONFIG, progress=False)


def test_rows_equal_the_tools_lines(one_job, reference):
    assert [r["pair"] for r in one_job] == NAMES
    assert [untimed(r, build=True) for r in one_job] == [untimed(r, build=True) for r in reference]
    assert one_job.failed == {}
    assert all(r["tool_version"].startswith("pagor " + pagor.__version__) for r in one_job)
    assert [r["acceptance"]["accepted"] for r in one_job] == [True, True, True, False]
    assert one_job[3]["negative"] is True


def test_two_jobs_and_a_list_give_the_same_rows(one_job, manifest):
    two = pagor.run_pairs(manifest, SEMREG_CONFIG, jobs=2, progress=False)
    assert [untimed(r) for r in two] == [untimed(r) for r in one_job]
    listed = pagor.run_pairs(pair_dicts(), json.loads(SEMREG_CONFIG.read_text()), jobs=2,
                             progress=False)
    assert [untimed(r) for r in listed] == [untimed(r) for r in one_job]


def test_a_pair_that_fails_fails_only_its_row(tmp_path, one_job):
    empty = tmp_path / "empty.pcd"
    empty.write_text("")
    pairs = pair_dicts()[:1] + [{"source": empty, "target": empty, "name": "broken"}]
    with pytest.warns(UserWarning, match="pair broken failed: .*empty.pcd"):
        rows = pagor.run_pairs(pairs, SEMREG_CONFIG, jobs=2, progress=False)
    assert [untimed(r) for r in rows] == [untimed(one_job[0])]
    assert list(rows.failed) == ["broken"] and "empty.pcd" in rows.failed["broken"]


def bench(*args, check=True):
    return subprocess.run([sys.executable, "-m", "pagor", "bench", *map(str, args)],
                          capture_output=True, text=True, check=check)


def test_the_module_writes_the_tools_file_and_resumes(tmp_path, manifest, one_job, reference):
    out = tmp_path / "rows.jsonl"
    bench("--manifest", manifest, "--config", SEMREG_CONFIG, "--jobs", 2, "--out", out,
          "--quiet")
    rows = read_rows(out)
    assert [untimed(r) for r in rows] == [untimed(r) for r in one_job]
    assert [untimed(r, build=True) for r in rows] == [untimed(r, build=True) for r in reference]
    assert not (tmp_path / "rows.jsonl.partial").exists()
    # A run killed after two pairs (one of them mid-line): FILE.partial holds them in the order
    # they finished; --resume runs the other two and writes the file in set order.
    lines = out.read_text().splitlines()
    (tmp_path / "rows.jsonl.partial").write_text(lines[2] + "\n" + lines[0] + "\n" + lines[1][:40])
    out.write_text('{"previous": "run"}\n')
    done = bench("--manifest", manifest, "--config", SEMREG_CONFIG, "--jobs", 2, "--out", out,
                 "--resume", "--quiet")
    assert "4 of 4 pairs" in done.stdout and "2 taken from the earlier run" in done.stdout
    resumed = out.read_text().splitlines()
    assert resumed[0] == lines[0] and resumed[2] == lines[2]  # taken as they were, times too
    assert [untimed(json.loads(r)) for r in resumed] == [untimed(r) for r in one_job]


def test_a_preset_gives_the_tools_lines_under_that_preset(tmp_path, manifest, one_job):
    """--preset paper over the semreg-dev configuration, as `pagor bench --preset paper`: the
    file's absent keys come from the paper's preset, in both."""
    from bench_rows import cli_rows
    if not os.environ.get("PAGOR_CLI"):
        pytest.skip("PAGOR_CLI is not set (ctest sets it)")
    tool = cli_rows(manifest, tmp_path / "cli.jsonl", "--preset", "paper")
    out = tmp_path / "rows.jsonl"
    bench("--manifest", manifest, "--config", SEMREG_CONFIG, "--preset", "paper", "--jobs", 2,
          "--out", out, "--quiet")
    rows = read_rows(out)
    assert [untimed(r, build=True) for r in rows] == [untimed(r, build=True) for r in tool]
    # Another configuration than without the preset (the run key hashes it), the one a file
    # naming the preset gives.
    assert all(a["run_key"] != b["run_key"] for a, b in zip(rows, one_job))
    named = pagor.run_pairs(manifest, {"preset": "paper", **json.loads(SEMREG_CONFIG.read_text())},
                            progress=False)
    assert [r["run_key"] for r in rows] == [r["run_key"] for r in named]
    bad = bench("--manifest", manifest, "--preset", "bogus", "--out", out, check=False)
    assert bad.returncode == 2 and "--preset" in bad.stderr and "paper" in bad.stderr
    # The library takes the same preset, and refuses an unknown one whatever the configuration.
    lib = pagor.run_pairs(manifest, SEMREG_CONFIG, preset="paper", progress=False)
    assert [r["run_key"] for r in lib] == [r["run_key"] for r in named]
    for config in (None, {"preset": "paper"}, SEMREG_CONFIG):
        with pytest.raises(ValueError, match="preset: unknown preset 'bogus'"):
            pagor.run_pairs(manifest, config, preset="bogus")


def test_the_lock_and_bad_input_name_what_is_wrong(tmp_path, manifest):
    out = tmp_path / "rows.jsonl"
    held = pagor._pagor.FileLock(str(out), "a test")
    refused = bench("--manifest", manifest, "--out", out, check=False)
    assert refused.returncode == 1 and "rows.jsonl" in refused.stderr
    assert "a test" in refused.stderr or str(os.getpid()) in refused.stderr
    del held
    usage = bench("--manifest", manifest, "--jobs", "0", "--out", out, check=False)
    assert usage.returncode == 2 and "--jobs" in usage.stderr
    missing = bench("--manifest", tmp_path / "nope.txt", "--out", out, check=False)
    assert missing.returncode == 1 and "nope.txt" in missing.stderr
    with pytest.raises(FileNotFoundError, match="pairs: no such manifest"):
        pagor.run_pairs(tmp_path / "nope.txt")
    with pytest.raises(ValueError, match="jobs: expected 1 or more, got 0"):
        pagor.run_pairs(manifest, jobs=0)
    with pytest.raises(ValueError, match=r"pairs\[0\]: unknown key 'labels'"):
        pagor.run_pairs([{"source": "a", "target": "b", "labels": "c"}])
    with pytest.raises(pagor.Error, match=r"pairs\[0\]: .*nope.pcd"):
        pagor.run_pairs([(tmp_path / "nope.pcd", tmp_path / "nope.pcd")])
    with pytest.raises(pagor.Error, match="graph.bogus"):
        pagor.run_pairs(manifest, {"graph": {"bogus": 1}})


def test_a_relative_manifest_gives_the_tools_lines_from_the_same_directory(
        tmp_path, monkeypatch, reference):
    """The shared semreg-dev manifest, named relative to the source tree as in the README: its
    pairs' paths are relative to it, and the rows name them as the tool does."""
    from conftest import SOURCE_DIR
    monkeypatch.chdir(SOURCE_DIR)
    manifest = "bench/manifests/semreg-dev.txt"
    rows = pagor.run_pairs(manifest, "bench/manifests/semreg-dev.json", jobs=2, progress=False)
    tool = cli_rows(manifest, tmp_path / "cli.jsonl")
    assert len(rows) == 15 and rows[0]["source"].endswith("semreg-dev/03/source.pcd")
    assert [untimed(r, build=True) for r in rows] == [untimed(r, build=True) for r in tool]
