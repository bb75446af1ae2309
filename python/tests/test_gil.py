"""Long computations release the GIL: a Python thread keeps running while
the engine samples in another.

A thread that notes the time in a loop needs the GIL for every step. While
a call holds the GIL the thread stands still (CPython cannot take the GIL
from a call into native code), so its notes show a gap as long as the call;
while the call has released the GIL, the gaps stay short. A call that holds
the GIL (the builtin `sum` over a long range) checks that the measure sees
the difference.
"""

from __future__ import annotations

import threading
import time
from typing import Callable, List, Tuple

import numpy as np

import t2spline

from conftest import EXAMPLE


def longest_stall(call: Callable[[], object]) -> Tuple[float, float]:
    """The longest time a looping Python thread stood still while `call`
    ran, and how long `call` took, in seconds."""
    notes: List[float] = []
    started, stop = threading.Event(), threading.Event()

    def spin() -> None:
        started.set()
        while not stop.is_set():
            notes.append(time.perf_counter())

    thread = threading.Thread(target=spin)
    thread.start()
    started.wait()
    begin = time.perf_counter()
    call()
    end = time.perf_counter()
    stop.set()
    thread.join()
    inside = [begin] + [t for t in notes if begin <= t <= end] + [end]
    return max(b - a for a, b in zip(inside, inside[1:])), end - begin


def test_the_measure_sees_a_call_that_holds_the_gil() -> None:
    stall, duration = longest_stall(lambda: sum(range(20_000_000)))
    assert stall > 0.5 * duration, (stall, duration)


def test_a_thread_runs_while_a_large_sample_is_computed() -> None:
    curve = t2spline.benchmark_curve()
    stall, duration = longest_stall(lambda: curve.sample(4_000_000))
    assert stall < 0.5 * duration, (stall, duration)


def test_a_thread_runs_while_a_job_runs() -> None:
    stall, duration = longest_stall(lambda: t2spline.run(EXAMPLE, samples=1_000_000))
    assert stall < 0.5 * duration, (stall, duration)


def test_two_threads_sample_at_once_with_the_same_results() -> None:
    curve = t2spline.benchmark_curve()
    results: list = [None, None]

    def work(k: int) -> None:
        results[k] = curve.sample(200_000)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    first, second = results
    assert all((first[name] == second[name]).all() for name in first)


def test_a_thread_runs_while_a_fuzzy_surface_is_sampled_and_solved() -> None:
    terrain = t2spline.FuzzySurface.from_job(str(EXAMPLE.parent / "fuzzy-terrain.json"))
    stall, duration = longest_stall(lambda: terrain.sample(1000, 1000))
    assert stall < 0.5 * duration, (stall, duration)
    solution = terrain.solve(0.5)
    stall, duration = longest_stall(lambda: solution.sample(1000, 1000))
    assert stall < 0.5 * duration, (stall, duration)


def test_a_thread_runs_while_points_are_graded() -> None:
    curve = t2spline.benchmark_curve()
    # Enough points that grading them takes far longer than a thread switch
    # (5 ms): 1 000 points take 4 ms, too short for the other thread to be
    # scheduled at all.
    points = np.random.default_rng(0).uniform([0.0, -2.0], [9.0, 3.0], size=(50_000, 2))
    stall, duration = longest_stall(lambda: curve.membership(points))
    assert stall < 0.5 * duration, (stall, duration)
