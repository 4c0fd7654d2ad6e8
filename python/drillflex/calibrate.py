"""Calibration to the rig's readings (``drillflex calibrate``): the open- and cased-hole friction factors,
the hook-load offset and the bit torque coefficient fitted to a readings CSV or WITSML log. It goes
through the C++ pipeline (pipeline::Calibrate) with the GIL released."""
from __future__ import annotations

import os
from typing import Any, Dict, Optional, Sequence

from drillflex import _core
from drillflex.case import CaseLike, as_case
from drillflex.tables import results_dict


def calibrate(case: CaseLike, readings: "str | os.PathLike[str]", *, fit: Optional[Sequence[str]] = None,
              model: str = "stiff", jobs: int = 1) -> Dict[str, Any]:
    """The case's torque-and-drag model fitted to ``readings``, as ``drillflex calibrate CASE --readings
    FILE [--fit ...] [--model ...] [--jobs N]``: results.json's object (its ``calibration``: each
    parameter's ``value``, ``low`` and ``high`` of its 95 % interval, ``fitted`` and ``note``; the
    correlation; the residuals' RMS; the readings with the fitted model's values), in the case's output
    units, with ``tables`` (calibration.csv). ``fit``: parameter names (open_hole_friction,
    cased_hole_friction, hook_load_offset, bit_torque_coefficient); none: all the readings determine."""
    result = _core.calibrate(as_case(case), os.fspath(readings), list(fit or []), model, jobs)
    return results_dict(result["json"], result["tables"])
