"""The GIL is released while C++ runs: Python keeps running beside a case, and two threads running
cases give the single run's results. How fast two cases run side by side is a speed figure, measured
by bench/python_threads.py, not asserted here (no timed tests: a loaded machine would decide it)."""
from __future__ import annotations

import threading
import time
from typing import Callable

import drillflex


def _count_until(stop: Callable[[], bool]) -> int:
    count = 0
    while not stop():
        count += 1
    return count


def test_python_runs_while_a_case_runs(example: drillflex.Case) -> None:
    done = threading.Event()

    def solve() -> None:
        drillflex.static(example)
        done.set()

    thread = threading.Thread(target=solve)
    start = time.perf_counter()
    thread.start()
    beside = _count_until(done.is_set)
    seconds = time.perf_counter() - start
    thread.join()
    deadline = time.perf_counter() + seconds
    alone = _count_until(lambda: time.perf_counter() > deadline)
    print(f"Python ran {beside / alone:.0%} of its own pace beside a {seconds:.2f} s case")
    # With the GIL held for the case, Python would not run at all until it ended.
    assert beside > 0.1 * alone


def test_results_of_threads_are_the_same(small: drillflex.Case) -> None:
    results = [None, None]

    def solve(index: int) -> None:
        results[index] = drillflex.static(small).nodes["axial_force"].copy()

    threads = [threading.Thread(target=solve, args=(i,)) for i in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert (results[0] == results[1]).all()
