"""drillflex: drill-string mechanics from Python (docs/python.md).

    import drillflex
    case = drillflex.Case.from_file("examples/rotary-bha-build/case.yaml")
    st = drillflex.static(case.with_values({"operation.wob": "30 klbf"}))
    print(st.bit.side_force, st.nodes["axial_force"][:3])   # SI
    print(st)                                               # the command line's summary
"""
from drillflex import units
from drillflex.case import Case
from drillflex.errors import ConvergenceError, DrillflexError, InputError, UnitError
from drillflex.results import (BucklingResult, ModesResult, Record, StaticResult, TendencyResult, TransientResult,
                               VibrationResult)
from drillflex.calibrate import calibrate
from drillflex.roadmap import RoadmapResult, roadmap
from drillflex.runs import buckling, modes, run, static, tendency, transient, vibration

__all__ = [
    "Case", "units", "static", "modes", "vibration", "buckling", "transient", "tendency", "run", "roadmap", "calibrate",
    "StaticResult", "ModesResult", "VibrationResult", "BucklingResult", "TransientResult", "TendencyResult",
    "RoadmapResult", "Record",
    "DrillflexError", "InputError", "UnitError", "ConvergenceError",
]
