"""Errors: the command line's messages with their file, line and key; solvers that fail."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

import drillflex
from conftest import SMALL_CASE


def test_bad_case_raises_input_error_with_line_and_key() -> None:
    text = SMALL_CASE.replace("od: 0.2,", "od: 8 lbf,")
    with pytest.raises(drillflex.InputError) as raised:
        drillflex.Case.from_yaml(text, "bad.yaml")
    error = raised.value
    assert error.file == "bad.yaml"
    assert error.line == 5
    assert error.key == "string[0].od"
    assert str(error).startswith("bad.yaml:5:")
    assert "string[0].od:" in str(error)
    assert isinstance(error, ValueError)


def test_message_is_the_command_lines(tmp_path: Path, executable: Path) -> None:
    case = tmp_path / "bad.yaml"
    case.write_text(SMALL_CASE.replace("count: 3", "count: three"))
    with pytest.raises(drillflex.InputError) as raised:
        drillflex.Case.from_file(str(case))
    printed = subprocess.run([str(executable), "check", str(case)], capture_output=True, text=True)
    assert printed.returncode != 0
    assert str(raised.value) in printed.stderr
    assert raised.value.key == "string[0].count"


def test_unknown_key_path_in_with_values(small: drillflex.Case) -> None:
    with pytest.raises(drillflex.InputError) as raised:
        small.with_values({"fluidd.density": "10 ppg"})
    assert raised.value.key == "fluidd"  # the section the reader refuses
    assert "unknown key 'fluidd'" in str(raised.value)
    with pytest.raises(drillflex.InputError) as raised:
        small.with_values({"string[5].length": "3 m"})
    assert raised.value.key == "string[5].length"
    assert raised.value.line == 5
    assert "no item [5]" in str(raised.value)


def test_bad_value_in_with_values_names_its_key(small: drillflex.Case) -> None:
    with pytest.raises(drillflex.InputError) as raised:
        small.with_values({"string[0].length": "9 lbf"})
    assert raised.value.key == "string[0].length"
    assert raised.value.line == 5  # where the value it replaces stands


def test_missing_file() -> None:
    with pytest.raises(drillflex.InputError, match="cannot open the case file"):
        drillflex.static("no/such/case.yaml")


def test_solver_failure_raises_convergence_error(small: drillflex.Case) -> None:
    # One Newton iteration a load step cannot find the hanging string's equilibrium.
    with pytest.raises(drillflex.ConvergenceError, match="Newton solver failed"):
        drillflex.static(small.with_values({"analyses.static": "{max_iterations: 1}"}))


def test_run_raises_with_the_finished_results_attached() -> None:
    # tests/cases/keep-finished.yaml: its buckling fails after its static and modes have finished.
    from conftest import ROOT
    with pytest.raises(drillflex.ConvergenceError, match="buckling: the string's lowest lateral frequency") as raised:
        drillflex.run("run", str(ROOT / "tests" / "cases" / "keep-finished.yaml"))
    error = raised.value
    assert [f["analysis"] for f in error.failures] == ["buckling"]
    assert error.results is not None
    assert len(error.results["modes"]) == 3
    assert "static" in error.results and "buckling" not in error.results
    assert "modes.csv" in error.results["tables"]


def test_unknown_analysis(small: drillflex.Case) -> None:
    with pytest.raises(ValueError, match="unknown analysis 'statics'"):
        drillflex.run("statics", small)


def test_wrong_case_type() -> None:
    with pytest.raises(TypeError):
        drillflex.static(42)  # type: ignore[arg-type]


def test_units_errors() -> None:
    with pytest.raises(drillflex.UnitError, match="cannot convert"):
        drillflex.units.convert(1.0, "m", "lbf")
