"""The module's results equal the command line's results.json on the bundled example, to the last
digit: both go through pipeline::RunCase and ComposeResultFiles."""
from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import drillflex
from conftest import EXAMPLE


def plain(value: Any) -> Any:
    """A tabulated value back as json.load reads it (arrays as lists, records as dicts)."""
    if isinstance(value, dict):
        return {key: plain(item) for key, item in value.items()}
    if isinstance(value, list):
        return [plain(item) for item in value]
    if isinstance(value, np.ndarray):
        if value.dtype.names:
            return [{name: plain(record[name]) for name in value.dtype.names} for record in value]
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


@pytest.fixture(scope="module")
def command_line(executable: Path, tmp_path_factory: pytest.TempPathFactory) -> dict:
    directory = tmp_path_factory.mktemp("cli")
    subprocess.run([str(executable), "run", str(EXAMPLE), "-o", str(directory), "--no-report"], check=True,
                   capture_output=True)
    return json.loads((directory / "results.json").read_text())


@pytest.fixture(scope="module")
def module_run() -> dict:
    return drillflex.run("run", str(EXAMPLE))


def test_results_json_is_the_command_lines(command_line: dict, module_run: dict) -> None:
    ours = plain({key: value for key, value in module_run.items() if key != "tables"})
    assert ours == command_line


def test_key_figures_to_the_last_digit(command_line: dict, module_run: dict) -> None:
    assert module_run["static"]["bit"]["side_force"] == command_line["static"]["bit"]["side_force"]
    assert module_run["modes"][0]["frequency_hz"] == command_line["modes"][0]["frequency_hz"]
    assert module_run["critical_rpm"]["first_lateral"] == command_line["critical_rpm"]["first_lateral"]
    assert module_run["vibration"]["critical_rpm"][0] == command_line["vibration"]["critical_rpm"][0]


def test_typed_results_match_in_si(command_line: dict, example: drillflex.Case) -> None:
    st = drillflex.static(example)
    side_force = drillflex.units.convert(st.bit.side_force, "N", "lbf")
    assert side_force == pytest.approx(command_line["static"]["bit"]["side_force"], rel=1e-15)
    md = drillflex.modes(example)
    assert md.frequency_hz[0] == command_line["modes"][0]["frequency_hz"]
    assert 60.0 * md.first_frequency_hz == command_line["critical_rpm"]["first_lateral"]
    assert drillflex.units.convert(md.critical_speed, "rad/s", "rpm") == pytest.approx(
        command_line["critical_rpm"]["first_lateral"], rel=1e-14)


def test_summary_is_what_the_command_line_prints(executable: Path, example: drillflex.Case, tmp_path: Path) -> None:
    printed = subprocess.run([str(executable), "static", str(EXAMPLE), "-o", str(tmp_path), "--no-report"],
                             check=True, capture_output=True, text=True).stdout
    assert str(drillflex.static(example)) in printed
