"""Running a case's analyses: one function per analysis with a typed result, and ``run`` with what
results.json holds. Each goes through the C++ pipeline (pipeline::RunCase) with the GIL released."""
from __future__ import annotations

from typing import Any, Callable, Dict, Optional, Sequence, Union

from drillflex import _core
from drillflex.case import CaseLike, as_case
from drillflex.errors import ConvergenceError
from drillflex.results import (BucklingResult, ModesResult, StaticResult, TendencyResult, TransientResult,
                               VibrationResult)
from drillflex.tables import results_dict

# progress(analysis, done, total): the running analysis ("transient") and how far it is (the
# simulated time and the duration, s). log(line): the run's notes (the model's size, ...).
Progress = Optional[Callable[[str, float, float], Any]]
Log = Optional[Callable[[str], Any]]


def _run(case: CaseLike, analyses: Sequence[str], progress: Progress, log: Log,
         keep_finished: bool = False) -> _core.Run:
    return _core.run(as_case(case), list(analyses), progress, log, keep_finished)


def static(case: CaseLike, *, progress: Progress = None, log: Log = None) -> StaticResult:
    """The static equilibrium of a case (a Case or a case file's path)."""
    return StaticResult(_run(case, ["static"], progress, log))


def modes(case: CaseLike, *, progress: Progress = None, log: Log = None) -> ModesResult:
    """The natural modes about the case's static equilibrium."""
    return ModesResult(_run(case, ["modes"], progress, log))


def vibration(case: CaseLike, *, progress: Progress = None, log: Log = None) -> VibrationResult:
    """The forced response against rotary speed (the case's ``analyses.vibration``)."""
    return VibrationResult(_run(case, ["vibration"], progress, log))


def buckling(case: CaseLike, *, progress: Progress = None, log: Log = None) -> BucklingResult:
    """The buckling load of the case's loads."""
    return BucklingResult(_run(case, ["buckling"], progress, log))


def tendency(case: CaseLike, *, progress: Progress = None, log: Log = None) -> TendencyResult:
    """The steady build and turn rates of the case's BHA (its ``analyses.tendency`` settings)."""
    return TendencyResult(_run(case, ["tendency"], progress, log))


def transient(case: CaseLike, *, progress: Progress = None, log: Log = None) -> TransientResult:
    """The time integration of the case's ``analyses.transient``."""
    return TransientResult(_run(case, ["transient"], progress, log))


def run(analyses: Union[str, Sequence[str]], case: CaseLike, *, progress: Progress = None,
        log: Log = None) -> Dict[str, Any]:
    """What the command line's results.json holds after ``drillflex <analyses> CASE``, as a dict.

    ``analyses``: "static", "modes", "vibration", "buckling", "transient", "tendency", a list of them, or "run"
    (those the case lists). Values are in the case's output units, as in the file; its lists of
    numbers and of records are numpy arrays (drillflex.tables), and ``tables`` holds each CSV table
    the command line writes beside it.

    An analysis that does not finish raises ConvergenceError once the others have run: its
    ``results`` is this dict for the analyses that finished (``failures`` in it names the others, as
    ``drillflex run --keep-finished`` writes), its ``failures`` the list of them.
    """
    names = [analyses] if isinstance(analyses, str) else list(analyses)
    finished = _run(case, names, progress, log, keep_finished=True)
    json_text, tables = finished.results_json()
    results = results_dict(json_text, tables)
    failures = [{"analysis": name, "message": why} for name, why in finished.failures]
    if failures:
        raise ConvergenceError("; ".join(f"{f['analysis']}: {f['message']}" for f in failures),
                               results=results, failures=failures)
    return results
