"""drillflex.Case: reading from a file, YAML text and a dict, and changed copies by key path."""
from __future__ import annotations

import pytest

import drillflex
from conftest import EXAMPLE, SMALL_CASE


def test_from_file_reads_the_case(example: drillflex.Case) -> None:
    assert example.name == "8-1/2 in rotary BHA in a build-and-hold well"
    assert example.units == "field"
    assert example.file == str(EXAMPLE)
    assert example.analyses == ["static", "modes", "vibration"]
    assert example.text == EXAMPLE.read_text()
    assert "rotary BHA" in repr(example)


def test_from_yaml_and_from_dict_read_the_same_case() -> None:
    from_yaml = drillflex.Case.from_yaml(SMALL_CASE)
    from_dict = drillflex.Case.from_dict({
        "name": "small pendulum", "units": "SI", "gravity": 9.81,
        "string": [{"type": "collar", "od": 0.2, "id": 0.07, "length": 9, "count": 3}],
        "model": {"body_length": "9 m", "elements_per_body": 10, "modes_per_body": 6},
        "supports": [{"at": "27 m", "fix": ["x", "y", "z", "rx", "ry", "rz"]}],
        "analyses": {"static": {}, "modes": {"count": 6}},
    })
    assert from_dict.name == from_yaml.name == "small pendulum"
    assert from_dict.file == "<dict>"
    a, b = drillflex.static(from_yaml), drillflex.static(from_dict)
    assert (a.nodes["axial_force"] == b.nodes["axial_force"]).all()


def test_with_values_makes_a_changed_copy(example: drillflex.Case) -> None:
    changed = example.with_values({"operation.wob": "30 klbf", "string[4].length": "40 ft"})
    assert changed is not example
    assert changed.text == example.text
    base = drillflex.run("static", example)
    more = drillflex.run("static", changed)
    assert base["operation"]["weight_on_bit"] == 25.0
    assert more["operation"]["weight_on_bit"] == 30.0
    # The string stabilizer moved 35 ft further from the bit: the string is 35 ft longer.
    assert more["static"]["nodes"]["s"][-1] - base["static"]["nodes"]["s"][-1] == pytest.approx(35.0)


def test_with_values_takes_numbers_and_booleans(small: drillflex.Case) -> None:
    changed = small.with_values({"string[0].length": 10, "string[0].count": 2, "supports[0].at": "20 m"})
    st = drillflex.static(changed)
    assert st.nodes["s"][-1] == pytest.approx(20.0)
