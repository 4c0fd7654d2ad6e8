#!/usr/bin/python3
"""The GIL released while C++ runs, measured: one static of the bundled example alone, and two in two
Python threads at once, interleaved REPEATS times; prints the medians and their ratio (1.0 is two
cases in one case's time, 2.0 no overlap at all). A speed figure, so a benchmark, not a test: run it
on an idle machine, each case on one core:

    OMP_NUM_THREADS=1 PYTHONPATH=build/python /usr/bin/python3 bench/python_threads.py [REPEATS]

The static's result is checked against the single run's (the same axial force at every node), so the
figure comes with the accuracy it was bought at.
"""
import statistics
import sys
import threading
import time
from pathlib import Path

import drillflex

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "rotary-bha-build" / "case.yaml"


def one(case):
    start = time.perf_counter()
    result = drillflex.static(case)
    return time.perf_counter() - start, result


def two(case):
    results = [None, None]

    def solve(index):
        results[index] = drillflex.static(case)

    threads = [threading.Thread(target=solve, args=(i,)) for i in range(2)]
    start = time.perf_counter()
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return time.perf_counter() - start, results


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    case = drillflex.Case.from_file(str(EXAMPLE))
    _, reference = one(case)  # warm up
    alone, together = [], []
    for _ in range(repeats):
        seconds, result = one(case)
        alone.append(seconds)
        seconds, results = two(case)
        together.append(seconds)
        for other in [result] + results:
            assert (other.nodes["axial_force"] == reference.nodes["axial_force"]).all()
    a, b = statistics.median(alone), statistics.median(together)
    print(f"one case {a:.3f} s, two in two threads {b:.3f} s (medians of {repeats}, interleaved): ratio {b / a:.2f}; "
          f"results equal to the single run's")


if __name__ == "__main__":
    main()
