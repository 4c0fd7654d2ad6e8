"""Every entry point: the typed results (SI, views of the run's storage), their summaries, run()'s
dict, units and progress."""
from __future__ import annotations

import gc
import json

import numpy as np
import pytest

import drillflex
from conftest import ROOT, ROTATING


def test_static_typed_result(example: drillflex.Case) -> None:
    st = drillflex.static(example)
    assert st.converged and st.stable
    n = len(st.nodes["s"])
    assert n == 1015
    assert st.nodes["md"].shape == (n,) and st.nodes["position"].shape == (n, 3)
    assert st.nodes["s"][0] == 0.0
    assert st.nodes["md"][0] == pytest.approx(7400 * 0.3048, abs=0.1)  # SI: the bit at 7400 ft
    assert st.nodes["axial_force"][0] < 0  # compression at the bit
    # The same run's results.json, in the case's field units.
    stored = json.loads(st.run.results_json()[0])["static"]
    assert drillflex.units.convert(st.bit.side_force, "N", "lbf") == pytest.approx(stored["bit"]["side_force"], rel=1e-15)
    assert st.bit.inclination_tendency == "build"
    assert len(st.contacts["normal_force"]) == len(stored["contacts"]) > 0
    assert st.contacts["component_name"][0] == "near-bit stabilizer"
    assert len(st.reactions) == 2 and st.reactions[0].force.shape == (3,)
    # The pipe above the model takes the top's tension at rest: the hook's axial reaction there.
    assert st.pipe_above.tension == pytest.approx(st.reactions[1].force[0], rel=1e-3)
    assert not st.pipe_above.buckled
    assert drillflex.units.convert(st.pipe_above.tension, "N", "lbf") == pytest.approx(
        stored["pipe_above"]["tension"], rel=1e-12)
    assert str(st).startswith("static: converged")
    assert f"bit: side force {stored['bit']['side_force']:.5g} lbf" in str(st)


def test_arrays_view_the_runs_storage(small: drillflex.Case) -> None:
    st = drillflex.static(small)
    force = st.nodes["axial_force"]
    assert not force.flags.writeable and not force.flags.owndata
    assert force.base is not None
    with pytest.raises(ValueError):
        force[0] = 1.0
    # Columns of the same stations are strided views of one vector of station results: the same
    # stride, a station's record, and their first values within one record of each other.
    torque = st.nodes["torque"]
    apart = abs(torque.__array_interface__["data"][0] - force.__array_interface__["data"][0])
    assert force.strides == torque.strides and force.strides[0] > force.itemsize and apart < force.strides[0]
    assert st.nodes["position"].strides[0] == force.strides[0]
    expected = force.copy()
    del st
    gc.collect()
    assert (force == expected).all()  # the array keeps the results alive


def test_modes_typed_result(small: drillflex.Case) -> None:
    md = drillflex.modes(small)
    assert len(md.frequency_hz) == 6
    assert (np.diff(md.eigenvalue) >= 0).all()
    assert md.displacement[0].shape == (len(md.s), 3)
    assert md.first_lateral is not None
    assert md.critical_speed == pytest.approx(2 * np.pi * md.frequency_hz[md.first_lateral])
    assert md.first_frequency_hz == md.frequency_hz[md.first_lateral]
    assert md.campbell is None
    assert str(md).startswith("modes:")


def test_vibration_typed_result(example: drillflex.Case) -> None:
    vb = drillflex.vibration(example.with_values({"analyses.vibration.rpm": "{from: 60, to: 120, step: 5}"}))
    assert len(vb.rotary_speed) == 13
    assert vb.rotary_speed[0] == pytest.approx(60 * np.pi / 30)  # rad/s
    assert vb.max_lateral_displacement.shape == vb.rotary_speed.shape
    assert vb.safe_windows.ndim == 2 and vb.safe_windows.shape[1] == 2
    # The critical speeds (rad/s): the peaks, ascending, and the same speeds as the records (most severe first).
    assert len(vb.critical_rotary_speed) >= 1 and np.all(np.diff(vb.critical_rotary_speed) > 0)
    assert np.all((vb.critical_rotary_speed >= vb.rotary_speed[0]) & (vb.critical_rotary_speed <= vb.rotary_speed[-1]))
    assert sorted(r.rotary_speed for r in vb.critical_speeds) == list(vb.critical_rotary_speed)
    assert len(vb.excitation_displacement) == 2
    assert "vibration" in str(vb)


def test_buckling_typed_result() -> None:
    case = drillflex.Case.from_yaml("""\
name: column
units: SI
string:
  - {type: collar, od: 0.1, id: 0.05, length: 10}
model: {body_length: 5 m, elements_per_body: 6, modes_per_body: 4}
supports:
  - {at: 0, fix: [x, y, z, rx]}
  - {at: 10 m, fix: [y, z]}
loads:
  - {at: 10 m, force: [-1000, 0, 0]}
analyses:
  buckling: {}
""")
    bk = drillflex.buckling(case)
    assert bk.load_factor > 1
    assert not bk.lower_bound  # an onset found, not a bound
    assert bk.critical_load == pytest.approx(1000 * bk.load_factor, rel=1e-6)
    assert bk.mode_displacement.shape == (len(bk.s), 3)
    assert "buckling" in str(bk)


def test_buckling_where_the_pipe_above_buckles_first() -> None:
    # 300 ft of 4-3/4 in collars in a horizontal 8-1/2 in hole: the compression is the WOB all along,
    # so the pipe above the model (model.top: string_above) reaches Dawson-Paslay's F_sin with them.
    case = drillflex.Case.from_yaml("""\
name: horizontal collars
units: SI
well:
  survey: [[0, 90, 0], [2000 m, 90, 0]]
  hole: 8.5 in
  bit_md: 1500 m
string:
  - {type: collar, od: 4.75 in, id: 2.25 in, length: 91.44 m}
operation: {wob: 177.93 kN}
analyses:
  buckling: {}
""")
    bk = drillflex.buckling(case)
    assert bk.onset_above_model
    assert not bk.buckled_at_case_loads
    assert not bk.lower_bound
    assert bk.sinusoidal is not None
    # The onset is the pipe above's F_sin (the collars' own section), as the screen computes it.
    assert bk.critical_wob == pytest.approx(bk.sinusoidal.sinusoidal_load, rel=0.02)


def test_transient_with_progress() -> None:
    case = drillflex.Case.from_file(str(ROTATING)).with_values(
        {"analyses.transient.duration": "0.004 s", "analyses.transient.output_interval": "0.001 s"})
    calls = []
    tr = drillflex.transient(case, progress=lambda analysis, done, total: calls.append((analysis, done, total)))
    assert tr.samples["time"][-1] == pytest.approx(0.004)
    assert tr.probes["lateral_y"].shape == (len(tr.samples["time"]), 3)
    assert tr.statistics.steps > 0
    assert calls and all(name == "transient" for name, _, _ in calls)
    assert calls[-1][1] == pytest.approx(calls[-1][2])
    assert str(tr).startswith("transient")


def test_progress_callback_errors_propagate() -> None:
    case = drillflex.Case.from_file(str(ROTATING)).with_values({"analyses.transient.duration": "0.004 s"})

    def stop(analysis: str, done: float, total: float) -> None:
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        drillflex.transient(case, progress=stop)


def test_run_returns_results_json(small: drillflex.Case) -> None:
    results = drillflex.run("static", small)
    nodes = results["static"]["nodes"]
    assert isinstance(nodes, np.ndarray) and nodes.dtype.names is not None
    assert nodes[0]["axial_force"] == nodes["axial_force"][0]
    assert results["static"]["converged"] is True
    assert "static.csv" in results["tables"]
    assert results["tables"]["static.csv"]["axial_force"][0] == pytest.approx(nodes["axial_force"][0])
    both = drillflex.run("run", small)
    assert "modes" in both and "static" in both


def test_log_receives_the_notes(small: drillflex.Case) -> None:
    lines = []
    drillflex.static(small, log=lines.append)
    assert any(line.startswith("model:") for line in lines)


def test_units_convert() -> None:
    assert drillflex.units.convert(1.0, "ft", "m") == 0.3048
    feet = drillflex.units.convert(np.array([0.3048, 3.048]), "m", "ft")
    assert feet == pytest.approx([1.0, 10.0])
    assert drillflex.units.convert(1.0, "klbf", "N") == pytest.approx(4448.2216152605)
    assert drillflex.units.convert([60.0], "rpm", "rad/s")[0] == pytest.approx(2 * np.pi)


def test_tendency_typed_result(example: drillflex.Case) -> None:
    td = drillflex.tendency(example)
    per_100_ft = 180.0 / np.pi * 30.48  # rad/m to deg/100 ft
    # The same run's results.json, in the case's field units.
    stored = json.loads(td.run.results_json()[0])["tendency"]
    assert td.build_rate * per_100_ft == pytest.approx(stored["build_rate"], rel=1e-12)
    assert td.turn_rate * per_100_ft == pytest.approx(stored["turn_rate"], rel=1e-12)
    assert stored["statics"] == len(td.trace)
    # At the steady curvature the bit drills along the hole: d = tilt + S F / WOB = 0.
    bit = td.bit
    assert abs(bit.tilt + td.steerability * bit.build_force / td.weight_on_bit) < 1e-6
    assert abs(bit.tilt_right + td.steerability * bit.walk_force / td.weight_on_bit) < 1e-6
    assert "tendency: builds" in str(td)


def test_tendency_refuses_a_negative_steerability(example: drillflex.Case) -> None:
    with pytest.raises(drillflex.InputError) as raised:
        drillflex.tendency(example.with_values({"analyses.tendency.steerability": "-0.1"}))
    assert "steerability" in str(raised.value)


def test_tendency_point_the_bit_steering() -> None:
    # V9's point-the-bit: the bit, full-gauge blades at the 0.8 deg fulcrum (2.75 ft) and 14.75 ft up.
    path = ROOT / "validation" / "v9-tendency" / "point-the-bit.yaml"
    td = drillflex.tendency(drillflex.Case.from_yaml(path.read_text(), str(path)))
    steering = td.steering
    assert steering.type == "point"
    assert steering.offset == pytest.approx(np.radians(0.8), rel=1e-12)
    assert steering.force == 0.0
    three_point = 2.0 * np.radians(0.8) / (14.75 * 0.3048)  # 2 theta / L, rad/m
    assert steering.full_build == pytest.approx(three_point, rel=2e-3)
    assert td.build_rate == pytest.approx(steering.full_build, rel=1e-12)  # the case steers all the time
    assert abs(steering.natural_build) < 1e-3 * three_point


# tests/cases/held-collar.yaml (as tests/pipeline/transient_limits_test.cpp): a collar (3 in × 1.181 in)
# clamped at its lower end, held under 200 kN of tension and 5 kN·m of torque at its top, rated 500 MPa
# (design factor 1.25), make-up torque 20 kN·m. By hand: A = π/4 (0.0762² − 0.03²), J = π/32 (0.0762⁴ − 0.03⁴),
# σ_vm = √((N/A)² + 3 (T (D/2)/J)²) = 114.5702 MPa: 0.2864255 of 400 MPa; the torque 5/20 = 0.25. The model's
# section torque reads up to 1/cos φ of the load's, φ = (T/cos φ) L_b/(G J) the relative twist of the two
# bodies' frames (its couplings measure it by sin φ; docs/validation.md V11b): the utilisations lie between
# the hand's at T and at T/cos φ.
HELD_COLLAR = ROOT / "tests" / "cases" / "held-collar.yaml"


def test_transient_limits_typed_against_the_hand_computation() -> None:
    area = np.pi / 4 * (0.0762**2 - 0.03**2)
    polar = np.pi / 32 * (0.0762**4 - 0.03**4)
    sigma, tau = 200e3 / area, 5e3 * 0.0381 / polar
    stress = np.sqrt(sigma**2 + 3 * tau**2) / (500e6 / 1.25)
    assert stress == pytest.approx(0.2864255, rel=1e-6)
    tr = drillflex.transient(drillflex.Case.from_file(str(HELD_COLLAR)))
    limits = tr.limits
    assert limits is not None
    assert limits.design_factor == 1.25
    assert len(limits.times) == 6 and limits.times[-1] == pytest.approx(0.01)
    assert limits.s.shape == limits.md.shape == limits.component.shape
    assert set(limits.largest) == {"yield", "makeup_torque", "helical_buckling", "fatigue"}
    # Every station but the tip's (its forces are half an element in), at every sample.
    phi = linear = 5e3 * 2.54 / (2.1e11 / 2.6 * polar)
    for _ in range(50):
        phi = linear / np.cos(phi)
    high = np.sqrt(sigma**2 + 3 * (tau / np.cos(phi))**2) / (500e6 / 1.25)

    def within(values: object, low: float, top: float) -> bool:
        values = np.asarray(values)
        return bool(np.all(values >= low * (1 - 1e-6)) and np.all(values <= top * (1 + 1e-6)))

    assert within(limits.largest["yield"][:-1], stress, high)
    assert within(limits.largest["makeup_torque"][:-1], 0.25, 0.25 / np.cos(phi))
    assert within(limits.history["yield"], stress, high)
    assert np.all(np.isnan(limits.largest["helical_buckling"]))  # no well: no buckling screen
    assert np.all(np.isnan(limits.history["fatigue"]))  # not rotating
    assert limits.summary["helical_buckling"] is None and limits.summary["fatigue"] is None
    assert limits.closest == "yield"
    assert within(limits.summary["yield"].utilisation, stress, high)
    assert within(limits.summary["makeup_torque"].utilisation, 0.25, 0.25 / np.cos(phi))
    assert 0.0 <= limits.summary["yield"].time <= 0.01
    assert not limits.largest["yield"].flags.writeable  # a view of the run's own storage
    # What results.json writes is the same envelope.
    written = drillflex.run("transient", drillflex.Case.from_file(str(HELD_COLLAR)))
    assert written["transient"]["limits"]["summary"]["yield"]["utilisation"] == pytest.approx(
        limits.summary["yield"].utilisation, rel=1e-12)
