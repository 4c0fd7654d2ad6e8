"""The errors drillflex raises (the C++ engine's InputError, UnitError and SolverError)."""
from __future__ import annotations

from typing import Any, Dict, Optional, Sequence


class DrillflexError(Exception):
    """Every error of drillflex's own."""


class InputError(DrillflexError, ValueError):
    """A case (or a value set in one) that cannot be read.

    ``str(error)`` is the command line's message, ``file:line:column: key: what was expected``.
    ``file``, ``line`` and ``column`` say where (``line`` and ``column`` 1-based, 0 when unknown),
    ``key`` the key path (``"string[2].od"``; ``""`` for the file as a whole), ``reason`` what was
    expected.
    """

    def __init__(self, message: str, file: str = "", line: int = 0, column: int = 0, key: str = "",
                 reason: str = "") -> None:
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.reason = reason or message


class UnitError(DrillflexError, ValueError):
    """A unit that cannot be read, or a conversion between units of different kinds."""


class ConvergenceError(DrillflexError, RuntimeError):
    """A solver that did not reach its goal; the message says which, where and why.

    Raised by ``drillflex.run`` when some of the analyses did not finish: ``results`` then holds what
    the others' results.json holds (the dict ``run`` returns, with their ``failures``), and
    ``failures`` a list of ``{"analysis": name, "message": why}``; elsewhere ``results`` is None and
    ``failures`` empty.
    """

    def __init__(self, message: str, results: Optional[Dict[str, Any]] = None,
                 failures: Sequence[Dict[str, str]] = ()) -> None:
        super().__init__(message)
        self.results = results
        self.failures = list(failures)
