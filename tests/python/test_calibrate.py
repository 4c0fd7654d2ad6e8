"""drillflex.calibrate: against Johancsik's closed form in a straight hole (readings written from it, the
soft-string model fitting them must give back the friction and the hook-load offset they were written
with), and equal to the command line's results.json (both go through pipeline::Calibrate and
ComposeCalibrationFiles)."""
from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import pytest

import drillflex
from test_roadmap import STRAIGHT_HOLE, buoyed_weight

FRICTION, OFFSET = 0.3, 100e3  # what the readings are written with; N
INCLINATION = math.radians(30.0)


@pytest.fixture(scope="module")
def readings(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Pick-up and slack-off hook loads W cos I ± μ W sin I + offset at three depths (kN), no torque."""
    lines = ["bit_md,activity,hook_load,surface_torque,wob,rpm", "m,-,kN,kN*m,kN,rpm"]
    for md in (207.0, 252.0, 297.0):
        weight = buoyed_weight(md)
        for activity, sign in (("pick_up", 1.0), ("slack_off", -1.0)):
            hook = weight * (math.cos(INCLINATION) + sign * FRICTION * math.sin(INCLINATION)) + OFFSET
            lines.append(f"{md},{activity},{hook / 1e3!r},,0,0")
    path = tmp_path_factory.mktemp("calibrate") / "readings.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_the_soft_string_gives_back_what_wrote_the_readings(readings: Path) -> None:
    case = drillflex.Case.from_yaml(STRAIGHT_HOLE, "roadmap.yaml")
    result = drillflex.calibrate(case, readings, model="soft")["calibration"]
    parameters = result["parameters"]
    assert parameters["open_hole_friction"]["value"] == pytest.approx(FRICTION, abs=1e-6)
    assert parameters["hook_load_offset"]["value"] == pytest.approx(OFFSET, rel=1e-6)
    # No cased hole and no torque: those two are held, with the reason.
    assert not parameters["cased_hole_friction"]["fitted"]
    assert not parameters["bit_torque_coefficient"]["fitted"]
    assert "torque" in parameters["bit_torque_coefficient"]["note"]


def test_equals_the_command_line(readings: Path, executable: Path, tmp_path: Path) -> None:
    case_file = tmp_path / "straight.yaml"
    case_file.write_text(STRAIGHT_HOLE)
    out = tmp_path / "out"
    subprocess.run([str(executable), "calibrate", str(case_file), "--readings", str(readings), "--model", "soft",
                    "-o", str(out), "--no-report"], check=True, capture_output=True)
    written = json.loads((out / "results.json").read_text())["calibration"]["parameters"]
    mine = drillflex.calibrate(drillflex.Case.from_file(str(case_file)), readings, model="soft")["calibration"]
    for name, value in written.items():
        assert mine["parameters"][name]["value"] == value["value"], name


def test_bad_readings_raise_input_error(tmp_path: Path) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("bit_md,activity,hook_load,surface_torque,wob,rpm\nm,-,kN,kN*m,kN,rpm\n250,tripping,500,,0,0\n")
    case = drillflex.Case.from_yaml(STRAIGHT_HOLE, "roadmap.yaml")
    with pytest.raises(drillflex.InputError, match="bad.csv"):
        drillflex.calibrate(case, bad, model="soft")
