"""pagor.run_pairs and `python3 -m pagor bench --scheduler` on a real Dask cluster (a LocalCluster
of two worker processes, one thread each): the rows equal the CLI's, times and the build's name
aside, and a worker that dies mid-run loses no pair and duplicates none."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

import pagor
from bench_rows import NAMES, SEMREG_CONFIG, have_semreg, read_rows, untimed

distributed = pytest.importorskip("distributed")
pytestmark = pytest.mark.skipif(not have_semreg(), reason="no semreg-dev data")
HERE = Path(__file__).resolve().parent


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """Two worker processes; they import pagor and dask_dying from the PYTHONPATH given here."""
    marker = tmp_path_factory.mktemp("dask") / "died"
    paths = [str(HERE), *os.environ.get("PYTHONPATH", "").split(os.pathsep)]
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in paths if p)
    os.environ["PAGOR_TEST_DIE_MARKER"] = str(marker)
    os.environ["PAGOR_TEST_DIE_INDEX"] = "2"
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None, silence_logs=40) as c:
        with distributed.Client(c) as client:
            yield client, marker


def test_rows_through_dask_equal_the_tools(cluster, manifest, reference):
    client, _ = cluster
    rows = pagor.run_pairs(manifest, SEMREG_CONFIG, client=client, shard_size=1, progress=False)
    assert [r["pair"] for r in rows] == NAMES
    assert [untimed(r, build=True) for r in rows] == [untimed(r, build=True) for r in reference]
    local = pagor.run_pairs(manifest, SEMREG_CONFIG, progress=False)
    assert [untimed(r) for r in rows] == [untimed(r) for r in local]  # same build: keys too


def test_a_worker_killed_mid_run_loses_and_duplicates_nothing(cluster, manifest, reference,
                                                              monkeypatch):
    client, marker = cluster
    import dask_dying
    monkeypatch.setattr(pagor.sets, "run_shard", dask_dying.dying_shard)
    seen = [row["index"] for row in pagor.sets.iter_rows(
        manifest, SEMREG_CONFIG, client=client, shard_size=1, progress=False)]
    assert marker.exists(), "no worker died: the test did not test anything"
    assert sorted(seen) == [0, 1, 2, 3]  # each pair once, the killed one's too
    client.wait_for_workers(2, timeout=60)  # the nanny restarted the dead one


def test_the_module_with_a_scheduler_writes_the_tools_file(cluster, manifest, reference,
                                                           tmp_path):
    client, _ = cluster
    out = tmp_path / "dask.jsonl"
    done = subprocess.run([sys.executable, "-m", "pagor", "bench", "--manifest", str(manifest),
                           "--config", str(SEMREG_CONFIG), "--scheduler",
                           client.scheduler.address, "--out", str(out)],
                          capture_output=True, text=True, check=True)
    assert "4 of 4 pairs" in done.stdout
    assert "4/4 pairs" in done.stderr  # the progress line's last state
    rows = read_rows(out)
    assert [untimed(r, build=True) for r in rows] == [untimed(r, build=True) for r in reference]
    assert len({r["pair"] for r in rows}) == len(rows)
