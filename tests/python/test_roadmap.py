"""drillflex.roadmap: against the soft-string references a straight hole gives exactly (Johancsik et al.
1984; the C++ test tests/pipeline/roadmap_test.cpp has the same case), and equal to the command line's
roadmap.json and roadmap.csv to the last digit (both go through pipeline::RunRoadmap and
ComposeRoadmapFiles)."""
from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

import drillflex
from drillflex.tables import read_csv_table
from test_equality import plain

STEEL, MUD, GRAVITY = 7850.0, 1200.0, 9.81  # kg/m³, kg/m³, m/s² (the case's built-in steel and default g)

# Three 9 m collars and 9 m joints of plain pipe to the surface in a straight hole at 30°, the bit
# at 297 m (27 m of collars and 30 joints).
STRAIGHT_HOLE = """\
name: roadmap
units: SI
well:
  survey: [[0, 30, 0], [400, 30, 0]]
  hole: [{diameter: 0.2159}]
  bit_md: 297
fluid: {density: 1200}
string:
  - {type: collar, od: 0.1715, id: 0.0714, length: 9, count: 3}
  - {type: pipe, od: 0.127, id: 0.1086, length: 9, count: 5}
model: {body_length: 9, elements_per_body: 4, modes_per_body: 4}
operation: {wob: 40 kN, torque_on_bit: 2 kN*m, rpm: 60}
analyses:
  static: {}
"""


def tube_weight(od: float, inner: float) -> float:
    """Buoyed weight of a metre of plain tube, N/m: steel less the mud it displaces, inside and out."""
    return GRAVITY * (STEEL - MUD) * math.pi / 4.0 * (od * od - inner * inner)


def buoyed_weight(bit_md: float) -> float:
    return tube_weight(0.1715, 0.0714) * 27.0 + tube_weight(0.127, 0.1086) * (bit_md - 27.0)


@pytest.fixture(scope="module")
def straight_hole() -> drillflex.Case:
    return drillflex.Case.from_yaml(STRAIGHT_HOLE, "roadmap.yaml")


@pytest.fixture(scope="module")
def result(straight_hole: drillflex.Case) -> drillflex.RoadmapResult:
    return drillflex.roadmap(straight_hole, from_md=207, step="45 m", friction=[0.2, 0.4], jobs=2)


def test_points_depth_by_depth_each_friction_factor(result: drillflex.RoadmapResult) -> None:
    np.testing.assert_array_equal(result.bit_md, [207, 207, 252, 252, 297, 297])
    np.testing.assert_array_equal(result.friction, [0.2, 0.4] * 3)
    assert result.message == [""] * 6
    assert result.settings.from_md == 207.0 and result.settings.step == 45.0
    assert result.settings.friction == [0.2, 0.4]
    assert result.settings.rotary_speed == pytest.approx(60 * math.pi / 30)  # the case's rpm, rad/s
    assert not result.pick_up.flags.writeable


def test_straight_inclined_hole_drags_mu_w_sin_i(result: drillflex.RoadmapResult) -> None:
    # Pulling out W cos I + μ W sin I, running in W cos I − μ W sin I, rotating W cos I, within 0.1 %.
    inclination = math.radians(30.0)
    for k in range(len(result)):
        weight = buoyed_weight(result.bit_md[k])
        mu = result.friction[k]
        axial, drag = weight * math.cos(inclination), mu * weight * math.sin(inclination)
        assert result.pick_up[k] == pytest.approx(axial + drag, rel=1e-3)
        assert result.slack_off[k] == pytest.approx(axial - drag, rel=1e-3)
        assert result.rotating[k] == pytest.approx(axial, rel=1e-3)
    shallow = result.at(0.4)
    np.testing.assert_array_equal(shallow["bit_md"], [207, 252, 297])
    assert np.all(np.diff(shallow["pick_up"]) > 0) and np.all(np.diff(shallow["off_bottom_torque"]) > 0)
    with pytest.raises(ValueError, match="no friction factor 0.3"):
        result.at(0.3)


def test_equals_the_command_line(result: drillflex.RoadmapResult, executable: Path, tmp_path: Path) -> None:
    path = tmp_path / "roadmap.yaml"
    path.write_text(STRAIGHT_HOLE)
    out = tmp_path / "out"
    subprocess.run([str(executable), "roadmap", str(path), "-o", str(out), "--from", "207", "--step", "45 m",
                    "--friction", "0.2, 0.4", "--no-report"], check=True, capture_output=True)
    command_line = json.loads((out / "roadmap.json").read_text())
    mine = result.json()
    tables = mine.pop("tables")
    assert plain(mine) == command_line
    csv, command_line_csv = tables["roadmap.csv"], read_csv_table((out / "roadmap.csv").read_text())
    for column in ("bit_md", "pick_up", "slack_off", "rotating", "off_bottom_torque", "on_bottom_torque"):
        np.testing.assert_array_equal(csv[column], command_line_csv[column])
        # The table's numbers carry 10 significant digits (io::CsvTable::Number); the case's units are SI.
        np.testing.assert_allclose(csv[column], getattr(result, column), rtol=1e-9)


def test_progress_after_each_point(straight_hole: drillflex.Case) -> None:
    calls = []
    drillflex.roadmap(straight_hole, from_md="252 m", step=45, friction=[0.3],
                      progress=lambda analysis, done, total: calls.append((analysis, done, total)))
    assert calls == [("roadmap", 1.0, 2.0), ("roadmap", 2.0, 2.0)]


def test_a_start_below_the_bit_is_an_input_error(straight_hole: drillflex.Case) -> None:
    with pytest.raises(drillflex.InputError) as error:
        drillflex.roadmap(straight_hole, from_md="400 m")
    assert error.value.key == "analyses.roadmap.from"
    assert "below the bit MD" in error.value.reason
    with pytest.raises(ValueError, match="jobs"):
        drillflex.roadmap(straight_hole, jobs=0)
