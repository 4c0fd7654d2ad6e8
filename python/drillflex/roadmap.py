"""The torque-and-drag roadmap (``drillflex roadmap``): the hook loads pulling out, running in and
rotating off bottom, and the surface torque off and on bottom, against bit depth, for each friction
factor. It goes through the C++ pipeline (pipeline::RunRoadmap) with the GIL released."""
from __future__ import annotations

from typing import Any, Callable, Dict, Optional, Sequence, Union

import numpy as np

from drillflex import _core
from drillflex.case import CaseLike, as_case
from drillflex.results import Record
from drillflex.tables import results_dict

# A depth or a speed as the case file gives one: "2500 ft", "0.3 m/s", or a number in the case's units.
Value = Union[str, float, int]

COLUMNS = ("bit_md", "friction", "pick_up", "slack_off", "rotating", "off_bottom_torque", "on_bottom_torque")


class RoadmapResult:
    """A roadmap's points, one per bit depth and friction factor (depth by depth, each friction
    factor at each depth), in SI: ``bit_md`` (m), ``friction``, the hook loads ``pick_up``,
    ``slack_off``, ``rotating`` (N, tension at the surface), the surface torques
    ``off_bottom_torque`` and ``on_bottom_torque`` (N·m, at the case's WOB and TOB) as arrays, NaN
    where a point's run failed and ``message`` says why; ``settings`` (a Record: ``from_md``,
    ``step``, ``friction``, ``rotary_speed`` rad/s, ``trip_speed`` m/s) as completed from the case;
    ``json()``: roadmap.json's object with ``tables`` (roadmap.csv), in the case's output units, as the
    command line writes them.
    """

    def __init__(self, fields: Dict[str, Any]) -> None:
        for name in COLUMNS:
            array = np.asarray(fields[name])
            array.flags.writeable = False
            setattr(self, name, array)
        self.message = list(fields["message"])
        self.settings = Record(**fields["settings"])
        self._json = fields["json"]
        self._tables = fields["tables"]

    def json(self) -> Dict[str, Any]:
        """roadmap.json's object, tabulated (drillflex.tables), with ``tables``: roadmap.csv."""
        return results_dict(self._json, self._tables)

    def at(self, friction: float) -> Dict[str, np.ndarray]:
        """The points of one friction factor (a dict of the columns, by depth)."""
        chosen = np.isclose(self.friction, friction, rtol=0.0, atol=1e-12)
        if not chosen.any():
            raise ValueError(f"no friction factor {friction} in this roadmap (it has {sorted(set(self.friction))})")
        return {name: getattr(self, name)[chosen] for name in COLUMNS}

    def __len__(self) -> int:
        return len(self.bit_md)

    def __repr__(self) -> str:
        failed = sum(1 for m in self.message if m)
        factors = len(self.settings.friction)
        return (f"<drillflex.RoadmapResult: {len(self)} points, {factors} friction factor{'' if factors == 1 else 's'}, "
                f"{failed} failed>")


def roadmap(case: CaseLike, *, from_md: Optional[Value] = None, step: Optional[Value] = None,
            friction: Optional[Sequence[float]] = None, jobs: int = 1,
            progress: Optional[Callable[[str, float, float], Any]] = None) -> RoadmapResult:
    """The case's torque-and-drag roadmap, as ``drillflex roadmap CASE [--from] [--step] [--friction]
    [--jobs]``: ``from_md``, ``step`` and ``friction`` replace the case's ``analyses.roadmap`` values
    (the case's syntax: ``"2500 ft"``, or a number in its units; docs/case-format.md "Roadmaps").
    ``progress("roadmap", done, total)`` is called after each point."""
    values: Dict[str, Any] = {}
    if from_md is not None:
        values["analyses.roadmap.from"] = from_md
    if step is not None:
        values["analyses.roadmap.step"] = step
    if friction is not None:
        values["analyses.roadmap.friction"] = "[" + ", ".join(repr(float(f)) for f in friction) + "]"
    chosen = as_case(case)
    if values:
        chosen = chosen.with_values(values)
    return RoadmapResult(_core.roadmap(chosen, jobs, progress))
