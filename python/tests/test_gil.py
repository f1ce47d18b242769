"""The GIL is released while computing: another Python thread makes progress
during a long call."""
import random
import threading
import time

import numpy as np
import pytest

import meshdiff


def ticks_during(call):
    """Runs call() while a second thread ticks every millisecond (in Python,
    so only while it holds the GIL); returns the ticks during the call and its
    duration."""
    stamps = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    time.sleep(0.05)  # the ticker is running
    t0 = time.perf_counter()
    call()
    t1 = time.perf_counter()
    stop.set()
    thread.join()
    return sum(t0 < s < t1 for s in stamps), t1 - t0


@pytest.fixture(scope="module")
def bunnies(data):
    return meshdiff.read_mesh(data / "bunny_res3.ply") + meshdiff.read_mesh(data / "bunny_res4_ascii.ply")


def test_the_ticker_stops_while_the_gil_is_held():
    """The control: sorting a list of floats holds the GIL in C, so the ticker
    barely moves; the tests below would fail on a call that held it."""
    values = [random.random() for _ in range(1_500_000)]
    ticks, seconds = ticks_during(lambda: sorted(values))
    assert ticks < 0.05 * seconds * 1000, f"{ticks} ticks in {seconds:.2f} s"


def test_a_second_thread_runs_during_a_long_compare(bunnies):
    V1, F1, V2, F2 = bunnies
    ticks, seconds = ticks_during(lambda: meshdiff.compare(V1, F1, V2, F2, samples=1_000_000, threads=1))
    assert seconds > 0.1, "the compare is too short to tell"
    # About one tick per millisecond when the GIL is free (at least 50 a second on a busy
    # machine); next to none if it were held.
    assert ticks >= 0.05 * seconds * 1000, f"{ticks} ticks in {seconds:.2f} s"


def test_a_second_thread_runs_during_queries(bunnies):
    V1, F1, _, _ = bunnies
    index = meshdiff.DistanceIndex(V1, F1)
    P = np.random.default_rng(3).uniform(-0.2, 0.2, size=(400_000, 3))
    ticks, seconds = ticks_during(lambda: index.query(P, threads=1))
    assert seconds > 0.05, "the queries are too short to tell"
    assert ticks >= 0.05 * seconds * 1000, f"{ticks} ticks in {seconds:.2f} s"


def test_threads_from_python_threads_give_the_same_result(bunnies):
    """Calls from several Python threads at once (each with its own OpenMP
    thread count) give the result of one call."""
    V1, F1, V2, F2 = bunnies
    expected = meshdiff.compare(V1, F1, V2, F2, levels=[1, 2], samples=50_000)
    results = [None] * 3

    def run(i):
        results[i] = meshdiff.compare(V1, F1, V2, F2, levels=[1, 2], samples=50_000, threads=i + 1)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(r == expected for r in results)
