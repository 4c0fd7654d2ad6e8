"""The typed results of drillflex's analyses. Every number is SI (m, N, N·m, Pa, rad, rad/s, s, Hz
where the name says so); the arrays are read-only numpy views of the run's own storage. ``str()`` of
a result is the command line's summary of it, in the case's units."""
from __future__ import annotations

from types import SimpleNamespace
from typing import Any, Dict, List, Optional

import numpy as np

from drillflex import _core


class Record(SimpleNamespace):
    """A group of named values (the bit's report, a support's reaction, a critical speed)."""


def _records(items: List[Dict[str, Any]]) -> List[Record]:
    return [Record(**{k: np.asarray(v) if isinstance(v, tuple) else v for k, v in item.items()}) for item in items]


class Result:
    """What every typed result has: the run it came from and its summary as ``str()``."""

    analysis = ""

    def __init__(self, run: _core.Run, fields: Dict[str, Any]) -> None:
        self.run = run
        self.__dict__.update(fields)

    def __str__(self) -> str:
        return self.run.summary(self.analysis)

    def __repr__(self) -> str:
        return f"<drillflex.{type(self).__name__}>\n{self}"


class StaticResult(Result):
    """The static equilibrium (``drillflex.static``).

    ``converged``, ``stable`` (no negative tangent stiffness), ``iterations``, ``load_steps``,
    ``residual_norm`` (N), ``method`` (how it was found), ``warnings`` (list of str), ``q`` (the
    equilibrium's coordinates).
    ``nodes``: one array per quantity, one entry per station from the bit up: ``s``, ``md`` (m; with
    a well the MD of the hole's cross-section through the station, else ``s``), ``position``,
    ``displacement``, ``rotation``, ``force``, ``moment`` (n×3), ``lateral_offset``, ``axial_force``
    (tension > 0), ``torque``, ``bending_moment``, ``shear_force``, ``bending_stress``,
    ``von_mises_stress``, and with a well ``wall_contact``, ``hole_offset``,
    ``offset_high_side_angle``, ``clearance``, ``hole_diameter``.
    ``contacts``: the wall contacts carrying force, as arrays ``s``, ``md``, ``normal_force``,
    ``friction_force``, ``high_side_angle``, ``component`` (index in the string), ``contact_point``,
    ``normal`` (n×3), and the list ``component_name``.
    ``reactions``: per support, a Record ``s``, ``force``, ``moment`` (string frame).
    ``pipe_above``: with the pipe above the model (``model.top: string_above``), a Record ``s``,
    ``force``, ``moment`` (what it holds the top with, string frame), ``tension`` (the top's tension
    at rest it takes) and ``buckled``; else None.
    ``mwd``: in a well with an MWD (or ``analyses.static.mwd_at``), a Record ``s``, ``md``,
    ``axis_inclination``, ``hole_inclination``, ``sag`` (axis − hole, rad: subtract it from the survey's
    inclination), ``axis_azimuth``, ``hole_azimuth``; else None.
    ``bit``: in a well, a Record ``side_force``, ``build_force`` (> 0 builds), ``walk_force``
    (> 0 walks right), ``tilt`` (rad), ``inclination_tendency``, ``azimuth_tendency``,
    ``tendency_threshold`` (N); else None.
    """

    analysis = "static"

    def __init__(self, run: _core.Run) -> None:
        fields = run.static_fields()
        fields["reactions"] = _records(fields["reactions"])
        fields["bit"] = Record(**fields["bit"]) if fields["bit"] is not None else None
        fields["pipe_above"] = Record(**fields["pipe_above"]) if fields["pipe_above"] is not None else None
        fields["mwd"] = Record(**fields["mwd"]) if fields["mwd"] is not None else None
        super().__init__(run, fields)


class ModesResult(Result):
    """The natural modes about the static equilibrium (``drillflex.modes``).

    Per mode (arrays in order of ω²): ``frequency_hz``, ``eigenvalue`` (rad²/s²), ``damping_ratio``,
    ``axial_fraction``, ``torsional_fraction``, ``lateral_fraction``, ``rigid_body``,
    ``negative_stiffness``, ``near_zero``, ``whirl_index``; lists ``kind`` and ``whirl``; shapes
    ``displacement`` and ``rotation`` (a list of n_stations×3 arrays, at the stations ``s``).
    ``first_lateral``: the index of the first lateral mode (None without one); ``critical_speed``: its
    critical rotary speed at 1× (rad/s; ``units.convert(x, "rad/s", "rpm")``).
    ``gyroscopic``, ``rotary_speed``; ``campbell``: a Record (``rotary_speed``, ``frequency_hz``
    speeds×modes, ``synchronous``, ``basis_size``) when the case asks for a Campbell diagram.
    """

    analysis = "modes"

    def __init__(self, run: _core.Run) -> None:
        fields = run.modes_fields()
        campbell = fields["campbell"]
        if campbell is not None:
            campbell["synchronous"] = _records(campbell["synchronous"])
            fields["campbell"] = Record(**campbell)
        super().__init__(run, fields)

    @property
    def first_frequency_hz(self) -> Optional[float]:
        """The first lateral mode's frequency (Hz), or None."""
        return None if self.first_lateral is None else float(self.frequency_hz[self.first_lateral])


class VibrationResult(Result):
    """The forced response against rotary speed (``drillflex.vibration``).

    Per speed: ``rotary_speed`` (rad/s), ``max_lateral_displacement`` (m), ``max_clearance_ratio``
    (empty without a well), ``max_bending_stress`` (Pa), ``max_contact_force`` (N),
    ``s_max_displacement`` (m). ``critical_rotary_speed`` (rad/s, ascending); ``critical_speeds``:
    Records (``rotary_speed``, ``severity``,
    ``displacement``, ``bending_stress``, ``excitation``, ``frequency``), most severe first;
    ``safe_windows``, ``quietest_windows`` (n×2, from and to, rad/s); ``excitation_frequencies``,
    ``excitation_displacement`` (one array per excitation); ``clearance_fraction``, ``stress_limit``,
    ``closed_contacts``, ``method``, ``basis_size``, ``reduced_check_error``, ``band_modes``,
    ``method_note``.
    """

    analysis = "vibration"

    def __init__(self, run: _core.Run) -> None:
        fields = run.vibration_fields()
        fields["critical_speeds"] = _records(fields["critical_speeds"])
        super().__init__(run, fields)


class BucklingResult(Result):
    """The buckling load (``drillflex.buckling``).

    ``load_factor`` (the loads × it buckle the string), ``critical_load`` (N), ``critical_wob`` (N),
    ``lower_bound`` (True: no onset up to ``load_factor``, which with the loads there is a lower bound),
    ``buckled_at_case_loads`` (True: the string lies buckled at the case's loads; ``load_factor`` < 1 is
    the onset found below them), ``onset_above_model`` (True: the pipe above the modelled string
    reaches Dawson–Paslay's F_sin first, at the model's top),
    ``scaled_wob``, ``about_equilibrium``, ``load_factors``, ``reference_load_factor``,
    ``reference_compression``; the frequency method's ``frequency_method_converged``,
    ``frequency_load_factor``, ``frequency_critical_load``, ``unloaded_frequency_hz`` and
    ``frequency_table`` (arrays ``load_factor``, ``compression``, ``frequency_hz``); the buckled shape
    ``mode_displacement``, ``mode_rotation`` (n×3) at ``s``; ``sinusoidal``: the Dawson–Paslay
    screen in a well (a Record), else None.
    """

    analysis = "buckling"

    def __init__(self, run: _core.Run) -> None:
        fields = run.buckling_fields()
        if fields["sinusoidal"] is not None:
            fields["sinusoidal"] = Record(**fields["sinusoidal"])
        super().__init__(run, fields)


class TendencyResult(Result):
    """The steady build and turn rates the BHA drills at the bit's depth (``drillflex.tendency``).

    ``build_rate`` (dI/ds) and ``turn_rate`` (dA/ds; 0 in a vertical hole), ``right_curvature`` and
    ``dogleg_severity``, all in rad/m (× 180/π × 30.48 for deg/100 ft); ``inclination`` and ``azimuth``
    at the bit (rad); ``steerability``, ``weight_on_bit`` (N), ``arc_length`` (m); ``trace``: a Record a
    static of the search (``build_curvature``, ``right_curvature``, ``build_force``, ``walk_force``,
    ``side_force``, ``tilt``, ``tilt_right``, ``deviation_build``, ``deviation_right``, ``method``),
    the answer at ``steady_index``; ``bit``: that Record; ``toolfaces`` (4: a rotating bent motor's
    mean), ``statics``; ``steering``: with a rotary steerable system, a Record ``steer``, ``natural_build``,
    ``natural_right``, ``full_build``, ``full_right`` (curvatures, rad/m), ``type`` (``"push"`` or
    ``"point"``), ``toolface`` (rad), ``force`` (the pads', N; 0 for point) and ``offset`` (the bit's
    tilt, rad; 0 for push), else None.
    """

    analysis = "tendency"

    def __init__(self, run: _core.Run) -> None:
        fields = run.tendency_fields()
        fields["trace"] = [Record(**point) for point in fields["trace"]]
        fields["bit"] = fields["trace"][fields["steady_index"]]
        if fields["steering"] is not None:
            fields["steering"] = Record(**fields["steering"])
        super().__init__(run, fields)


class TransientResult(Result):
    """The time integration (``drillflex.transient``).

    ``samples``: arrays per output sample ``time``, ``surface_speed``, ``surface_torque``,
    ``hook_load``, ``bit_speed``, ``weight_on_bit``, ``torque_on_bit``, ``kinetic_energy``,
    ``potential_energy``; ``probes``: arrays samples×probes ``lateral_y``, ``lateral_z``,
    ``whirl_angle``, ``contact_force``, ``bending_moment`` at the stations ``probe_s``;
    ``final_q``, ``final_v``, ``frame_times``, ``energy_drift``, ``rho_infinity`` and
    ``statistics`` (a Record: steps, rejections, Newton iterations, factorizations, step sizes).
    ``limits``: the string's limits read at every output sample (results.json ``transient.limits``), a
    Record: ``design_factor``; per station ``s``, ``md`` (m) and ``component`` (index in the string);
    ``times`` (s, every sample read); ``largest``, ``when`` and ``history``: dicts by limit name
    (``"yield"``, ``"makeup_torque"``, ``"helical_buckling"``, ``"fatigue"``) of arrays, each station's
    largest utilisation over the samples and the time it was reached (s), and each sample's largest over
    the stations (NaN where the limit does not apply); ``summary``: by limit name a Record (``limit``,
    ``utilisation``, ``s``, ``md``, ``component``, ``time``) of the largest of all, or None where the limit
    applies nowhere; ``closest``: the name of the closest limit (None: none applies). None when the run
    read no limits.
    """

    analysis = "transient"

    def __init__(self, run: _core.Run) -> None:
        fields = run.transient_fields()
        fields["statistics"] = Record(**fields["statistics"])
        limits = fields["limits"]
        if limits is not None:
            limits["summary"] = {name: None if entry is None else Record(**entry)
                                 for name, entry in limits["summary"].items()}
            fields["limits"] = Record(**limits)
        super().__init__(run, fields)
