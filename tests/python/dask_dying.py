"""A shard function for the Dask test, imported by the workers (tests/python is on their
PYTHONPATH): it kills its worker process the first time it is given the pair whose index is in
PAGOR_TEST_DIE_INDEX, leaving the marker file PAGOR_TEST_DIE_MARKER, and runs pagor's own shard
otherwise. The scheduler then runs the shard again on a worker that lives."""
import os

from pagor import sets


def dying_shard(spec, indices, config_json, threads=1):
    marker = os.environ["PAGOR_TEST_DIE_MARKER"]
    if int(os.environ["PAGOR_TEST_DIE_INDEX"]) in indices:
        try:
            fd = os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            pass
        else:
            os.write(fd, f"{os.getpid()}\n".encode())
            os.close(fd)
            os._exit(1)  # as a crash or the OOM killer would: no reply, no clean-up
    return sets.run_shard(spec, indices, config_json, threads)
