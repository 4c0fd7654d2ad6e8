"""Shared fixtures of the Python module's tests (run by CTest, label python, with PYTHONPATH set to the
build's python directory and DRILLFLEX_EXE to the command line's executable)."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

import drillflex

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "rotary-bha-build" / "case.yaml"
ROTATING = ROOT / "examples" / "rotary-bha-build" / "rotating.yaml"

# A small case with no well: a vertical pendulum of collars under its weight, fixed at the top; its
# static solve and modes take milliseconds.
SMALL_CASE = """\
name: small pendulum
units: SI
gravity: 9.81
string:
  - {type: collar, od: 0.2, id: 0.07, length: 9, count: 3}
model: {body_length: 9 m, elements_per_body: 10, modes_per_body: 6}
supports:
  - {at: 27 m, fix: [x, y, z, rx, ry, rz]}
analyses:
  static: {}
  modes: {count: 6}
"""


@pytest.fixture(scope="session")
def example() -> drillflex.Case:
    return drillflex.Case.from_file(str(EXAMPLE))


@pytest.fixture(scope="session")
def small() -> drillflex.Case:
    return drillflex.Case.from_yaml(SMALL_CASE, "small.yaml")


@pytest.fixture(scope="session")
def executable() -> Path:
    path = Path(os.environ.get("DRILLFLEX_EXE", ROOT / "build" / "drillflex"))
    if not path.exists():
        pytest.skip(f"no drillflex executable at {path} (set DRILLFLEX_EXE)")
    return path
