"""The core runs with the GIL released: other Python threads keep running during a registration,
and registrations in several threads give the results of running them one after another."""
import _thread
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import pagor

# Another thread counts in pure Python and notes the time every STRIDE iterations. Were the GIL
# held by the call, it could note nothing in the middle half of the call (the call's start and end
# convert arrays with the GIL held, and a thread switch there takes at most the switch interval);
# released, it notes one every few tens of microseconds. The problems below take tens of
# milliseconds or more; a call too short for its middle half to clear the switches at its ends
# tells nothing and is skipped (no wall time is asserted).
STRIDE = 1000
MIN_STAMPS = 3


def long_enough(seconds):
    if seconds < 8 * sys.getswitchinterval():
        pytest.skip(f"the call took {seconds * 1000:.1f} ms: too short to tell")


def spinning_during(call):
    """Runs call() while another thread counts; returns (its result, seconds, how many times
    the other thread noted the time in the middle half of the call)."""
    stamps = []
    stop = threading.Event()

    def spin():
        while not stop.is_set():
            for _ in range(STRIDE):
                pass
            stamps.append(time.perf_counter())

    spinner = threading.Thread(target=spin)
    spinner.start()
    try:
        time.sleep(0.05)  # the spinner is running
        start = time.perf_counter()
        result = call()
        end = time.perf_counter()
    finally:
        stop.set()
        spinner.join()
    quarter = (end - start) / 4
    middle = [t for t in stamps if start + quarter < t < end - quarter]
    return result, end - start, len(middle)


def test_another_python_thread_keeps_running_during_a_registration():
    scene = pagor.synthetic_scene(seed=7)
    result, seconds, stamps = spinning_during(lambda: pagor.register(
        scene["source"], scene["target"], scene["source_labels"], scene["target_labels"]))
    assert result.T_target_source is not None
    long_enough(seconds)
    assert stamps >= MIN_STAMPS, f"{stamps} in {seconds:.2f} s: the GIL was held"


def test_correspondences_release_the_gil_too():
    rng = np.random.default_rng(1)
    p, q = rng.uniform(-30, 30, (2, 3000, 3))
    q[:300] = p[:300] + 1.0  # 10 % inliers
    result, seconds, stamps = spinning_during(lambda: pagor.register_correspondences(p, q))
    assert result.levels[result.selected_level].clique_size >= 250
    long_enough(seconds)
    assert stamps >= MIN_STAMPS, f"{stamps} in {seconds:.2f} s: the GIL was held"


def test_registrations_in_threads_equal_sequential_ones():
    scenes = [pagor.synthetic_scene(seed=s) for s in (7, 8)]

    def run(scene):
        return pagor.register(scene["source"], scene["target"], scene["source_labels"],
                              scene["target_labels"]).T_target_source

    sequential = [run(s) for s in scenes]
    with ThreadPoolExecutor(2) as pool:
        parallel = list(pool.map(run, scenes))
    for a, b in zip(sequential, parallel):
        np.testing.assert_array_equal(a, b)


def test_ctrl_c_cancels_a_registration_between_stages():
    scene = pagor.synthetic_scene(seed=3)  # ~1.5 s, most of it after the landmarks
    args = (scene["source"], scene["target"], scene["source_labels"], scene["target_labels"])
    timer = threading.Timer(0.05, _thread.interrupt_main)  # as SIGINT would
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        pagor.register(*args)
    timer.join()
    small = pagor.synthetic_scene(seed=7)  # and the module works on
    assert pagor.register(small["source"], small["target"], small["source_labels"],
                          small["target_labels"]).accepted
