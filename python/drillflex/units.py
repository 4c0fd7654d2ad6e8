"""Units through drillflex's own unit layer (the case files' syntax: "ft", "klbf", "ft*lbf", "ppg",
"deg/100ft", "rpm", ...). Results are in SI; convert them for display with :func:`convert`."""
from __future__ import annotations

from typing import overload

import numpy as np

from drillflex import _core


@overload
def convert(value: float, from_unit: str, to_unit: str) -> float: ...
@overload
def convert(value: np.ndarray, from_unit: str, to_unit: str) -> np.ndarray: ...


def convert(value, from_unit, to_unit):
    """``value`` (a number or an array) in ``from_unit`` converted to ``to_unit``.

    ``convert(st.nodes["md"], "m", "ft")``; raises :class:`drillflex.UnitError` when the units are of
    different kinds. An array's elements convert exactly as the numbers alone would.
    """
    if np.ndim(value) == 0 and not isinstance(value, np.ndarray):
        return _core.convert(float(value), from_unit, to_unit)
    from_si, to_si = _core.unit_scales(from_unit, to_unit)
    return np.asarray(value, dtype=float) * from_si / to_si

