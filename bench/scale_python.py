"""Issue 36's Python figures: pagor.run_pairs over a set with 1 and 2 local jobs and through Dask
(LocalClusters of 1 and of 2 worker processes, one thread each, started once), each run in turn
(1, 2, Dask 1, Dask 2, 1, 2, ...) so that a drift of the machine's speed hits all alike. Prints
per way the median wall time, rows per second, and the Dask path's overhead per pair against 2
local jobs ((Dask 2 - local 2) / pairs). Timings only: the rows are checked by tests/python.

    PYTHONPATH=build/python /usr/bin/python3 bench/scale_python.py \\
        bench/manifests/semreg-dev.txt bench/manifests/semreg-dev.json [RUNS]
"""
import os
import statistics
import sys
import time

import pagor


def main() -> None:
    manifest, config = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    from distributed import Client, LocalCluster

    def cluster(n):
        return LocalCluster(n_workers=n, processes=True, threads_per_worker=1,
                            dashboard_address=None, silence_logs=40)

    with cluster(1) as one, Client(one) as client1, cluster(2) as two, Client(two) as client:
        ways = {"1 job": dict(jobs=1), "2 jobs": dict(jobs=2),
                "Dask, 1 worker": dict(client=client1, shard_size=1),
                "Dask, 2 workers": dict(client=client, shard_size=1)}
        times = {name: [] for name in ways}
        pairs = 0
        for k in range(runs + 1):  # the first round warms the page cache and the workers
            for name, how in ways.items():
                t0 = time.perf_counter()
                rows = pagor.run_pairs(manifest, config, progress=False, **how)
                if k > 0:
                    times[name].append(time.perf_counter() - t0)
                pairs = len(rows) + len(rows.failed)
        load = os.getloadavg()
        print(f"{pairs} pairs, {runs} runs each, load average {load[0]:.1f} {load[1]:.1f} "
              f"{load[2]:.1f} on {os.cpu_count()} cores")
        print(f"{'way':18} {'wall median [s]':>16} {'min':>7} {'max':>7} {'rows/s':>8}")
        for name, values in times.items():
            median = statistics.median(values)
            print(f"{name:18} {median:16.3f} {min(values):7.3f} {max(values):7.3f} "
                  f"{pairs / median:8.2f}")
        local, dask = statistics.median(times["2 jobs"]), statistics.median(times["Dask, 2 workers"])
        print(f"Dask overhead per pair against 2 local jobs: {1000 * (dask - local) / pairs:.1f} ms")
        print(f"2 jobs / 1 job: {local / statistics.median(times['1 job']):.2f}; "
              f"Dask 2 / Dask 1: {dask / statistics.median(times['Dask, 1 worker']):.2f}; "
              f"Dask 2 / 1 job: {dask / statistics.median(times['1 job']):.2f}")


if __name__ == "__main__":
    main()
