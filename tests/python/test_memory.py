"""No leak: 200 runs of a small case (its typed results, results.json and an error each) leave the
resident memory where the first 100 left it, within a few MB."""
from __future__ import annotations

import gc
import os

import drillflex

GROWTH_LIMIT = 4 * 1024 * 1024  # bytes


def _rss() -> int:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _once(case: drillflex.Case) -> None:
    st = drillflex.static(case)
    md = drillflex.modes(case)
    results = drillflex.run("static", case)
    assert st.converged and len(md.frequency_hz) and results["static"]["converged"]
    str(st)
    try:
        case.with_values({"string[9].length": "1 m"})
    except drillflex.InputError:
        pass


def test_no_leak_over_200_runs(small: drillflex.Case) -> None:
    for _ in range(100):
        _once(small)
    gc.collect()
    after_100 = _rss()
    for _ in range(100):
        _once(small)
    gc.collect()
    growth = _rss() - after_100
    print(f"RSS after 100 runs {after_100 / 2**20:.1f} MB, growth over the next 100: {growth / 2**20:.2f} MB")
    assert growth < GROWTH_LIMIT
