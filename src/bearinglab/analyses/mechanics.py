"""Analyses of the bearing's mechanics: the quasi-static load distribution with its
orbit (``static``), stiffness and displacements over loads (``stiffness``), the kinematic
defect frequencies (``frequencies``) and the outer-ring natural frequencies
(``ring-modes``, seed 000). Physics is never repeated here: each analysis builds the
models from the request (:mod:`bearinglab.inputs`), calls the library once and keeps the
result.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..engine import reraise_interrupt
from ..errors import InputError
from ..inputs import (
    INPUTS,
    FormErrors,
    Input,
    balls_only,
    bearing_from,
    bearing_warnings,
    condition_from,
    lubricant_from,
    no_effect,
    restate,
    speed_from,
)
from .base import BEARING_INPUTS, FILES, Analysis, Outcome, inputs, plot_file, specs

_LOADS = inputs("radial_load_n", "axial_load_n")
#: the form-error inputs, by the names the contact check gives them
_FORM_INPUTS = ("waviness", "ball_size_error_um", "surface3d")
_SPEED0 = {"speed_rpm": INPUTS["speed_rpm"].with_(default=0.0, help="Inner-ring speed [rpm].")}


# ------------------------------------------------------------------ quasi-static
@dataclass(frozen=True)
class StaticResult:
    """The load distribution of a request (:func:`bearinglab.quasistatic.
    solve_load_distribution`), with form errors at the instant the shaft angle is 0, and
    the inner-ring orbit when asked (:func:`bearinglab.quasistatic.orbit.inner_ring_orbit`).
    """

    bearing: object
    distribution: object
    designation: str | None = None
    orbit: object = None
    imperfections: object = None
    seed: int | None = None
    #: the form errors as ball diameter errors at rest [m]
    diameter_errors: object = None
    warnings: tuple = field(default_factory=tuple)

    def to_dict(self) -> dict:
        d = self.distribution.to_dict()
        out = {"designation": self.designation, **d, "warnings": list(self.warnings)}
        if self.imperfections is not None:
            out["imperfections"] = self.imperfections.to_dict()
            out["seed"] = self.seed
            out["effective_diameter_error_um"] = (self.diameter_errors * 1e6).tolist()
        if self.orbit is not None:
            out["orbit_kind"] = "time" if self.orbit.time is not None else "ball_set"
            out["orbit"] = self.orbit.to_dict()
            out["orbit_peak_to_peak_um"] = self.orbit.peak_to_peak * 1e6
        return out

    def to_pandas(self):
        """The per-ball table."""
        return self.distribution.to_pandas()

    def plot(self, axes=None):
        """Polar load distribution and contact angles; returns (fig, axes)."""
        return self.distribution.plot(axes)


def static(values: dict) -> StaticResult:
    """The ``static`` request: load distribution, stiffness matrix and, with ``orbit``
    (or form errors and ``orbit``), the inner-ring orbit."""
    from ..plausibility import contact_warnings, operating_warnings
    from ..quasistatic import solve_load_distribution
    from ..quasistatic.orbit import inner_ring_orbit

    condition = condition_from(values)
    oil, temperature, unused = lubricant_from(values)
    if condition.shaft_speed == 0:  # each of these acts through the balls' speed
        given = [(n, bool(values.get(n))) for n in ("gyroscopic", "ring_expansion", "film")]
        unused += no_effect(given, "at `speed_rpm` 0 (no rolling speed)")
    forms = FormErrors(
        specs(values.get("waviness")),
        values.get("ball_size_error_um"),
        specs(values.get("surface3d")),
    )
    orbit = bool(values.get("orbit"))
    if orbit and forms.given and condition.shaft_speed <= 0:
        raise InputError(
            "speed_rpm",
            values.get("speed_rpm"),
            "a speed > 0 rpm with `orbit` and form errors (the orbit then runs in time)",
        )
    bearing, decoded = bearing_from(values)
    try:
        plausibility = operating_warnings(bearing, condition)
    except InputError as exc:
        raise restate(exc, values, STATIC.options) from None
    if bearing.rolling_element == "roller":
        return _static_rollers(values, bearing, decoded, condition, plausibility)
    seed = values.get("seed")
    imperfections = forms.build(bearing, seed)
    options = {
        "lubricant": oil,
        "temperature": temperature,
        "gyroscopic": bool(values.get("gyroscopic")),
        "race_control": values.get("race_control") or "outer",
        "ring_expansion": bool(values.get("ring_expansion")),
    }
    errors = (
        None
        if imperfections is None  # the form errors at t = 0, ball 0 under the load
        else imperfections.diameter_errors_at_rest(bearing, condition.radial_load_angle)
    )
    result = solve_load_distribution(bearing, condition, ball_diameter_errors=errors, **options)
    # the contact pressures the form errors cause (ISO 76), at rest and over the orbit
    cause = {n: values[n] for n in _FORM_INPUTS if values.get(n)} if forms.given else {}
    pressure = contact_warnings(bearing, result, cause=cause)
    path = None
    if orbit:
        path = inner_ring_orbit(
            bearing,
            condition,
            imperfections=imperfections,
            points=values.get("orbit_points"),
            **options,
        )
        if imperfections is not None:  # the worst instant, t = 0 among them
            pressure = contact_warnings(bearing, path, cause=cause)
    warnings = (
        bearing_warnings(bearing, decoded)
        + plausibility
        + unused
        + list(result.warnings)
        + pressure
    )
    return StaticResult(
        bearing,
        result,
        values.get("designation"),
        path,
        imperfections,
        None if imperfections is None else (seed or 0),
        errors,
        tuple(warnings),
    )


#: The static inputs that act through the balls only (their film, spin, orbit and form
#: errors): a roller bearing refuses them.
BALL_STATIC = (
    "film",
    "gyroscopic",
    "ring_expansion",
    "orbit",
    "waviness",
    "ball_size_error_um",
    "surface3d",
)


def _static_rollers(values, bearing, decoded, condition, plausibility) -> StaticResult:
    """The load distribution of a roller bearing, by slices
    (:func:`bearinglab.quasistatic.solve_load_distribution`); the inputs that act through
    balls only are refused, naming the first given."""
    from ..plausibility import pressure_warnings
    from ..quasistatic import solve_load_distribution

    for name in BALL_STATIC:
        if values.get(name):
            raise InputError(
                name,
                values[name],
                "no value for a roller bearing (modelled for ball bearings only)",
            )
    unused = no_effect(
        [("race_control", values.get("race_control") not in (None, "outer"))],
        "for a roller bearing",
    )
    result = solve_load_distribution(bearing, condition, slices=values.get("slices") or 30)
    warnings = (
        bearing_warnings(bearing, decoded)
        + plausibility
        + unused
        + list(result.warnings)
        + pressure_warnings(bearing, result)
    )
    return StaticResult(bearing, result, values.get("designation"), warnings=tuple(warnings))


def _static_columns(r: StaticResult) -> dict:
    d = r.to_dict()
    d["tilt_x_mrad"], d["tilt_y_mrad"] = d["tilt_mrad"]
    return d


STATIC = Analysis(
    "static",
    "Quasi-static load distribution (solve_load_distribution), with the orbit on request.",
    {
        **BEARING_INPUTS,
        **_LOADS,
        **_SPEED0,
        **inputs(
            "radial_load_angle_deg",
            "misalignment_mrad",
            "film",
            "lubricant",
            "temperature_c",
            "gyroscopic",
            "race_control",
            "ring_expansion",
        ),
        "orbit": Input(
            "bool",
            False,
            "Also the inner-ring centre orbit: over one ball spacing (uniform balls), or, "
            "with form errors, in time over one cage revolution (seed 003 eqs. 14-18; needs "
            "`speed_rpm` > 0).",
        ),
        "orbit_points": Input(
            "integer",
            None,
            "Orbit positions: per ball spacing (default 24) or instants in time (default 64 "
            "per shaft revolution).",
            low=2,
            high=100_000,
        ),
        **inputs("waviness", "ball_size_error_um", "surface3d", "seed", "slices"),
    },
    run=static,
    outputs={
        "radial_displacement_um": "f",
        "axial_displacement_um": "f",
        "tilt_x_mrad": "f",
        "tilt_y_mrad": "f",
        "radial_stiffness_n_per_um": "f",
        "axial_stiffness_n_per_um": "f",
        "max_ball_load_n": "f",
        "max_roller_load_n": "f",
        "equilibrium_residual_n": "f",
        "diametral_clearance_um": "f",
        "orbit_peak_to_peak_um": "f",
        "warnings": "s",
    },
    largest=500,
    columns=_static_columns,
    warm=("bearinglab.quasistatic",),
    files={
        **plot_file("the load distribution and the contact angles"),
        "orbit_plot": Input(
            "path",
            None,
            "Draw the orbit, the displacements and the ball centres to this .png, .svg or "
            ".pdf file (implies `orbit`).",
        ),
        "stiffness_csv": Input(
            "path", None, "Write the 5x5 stiffness matrix (SI) to this CSV file."
        ),
    },
)


# ------------------------------------------------------------------ stiffness over loads
_STIFFNESS_OUT = {
    "radial_displacement_um": "f",
    "axial_displacement_um": "f",
    "radial_stiffness_n_per_um": "f",
    "axial_stiffness_n_per_um": "f",
    "max_ball_load_n": "f",
    "max_roller_load_n": "f",
}


def _stiffness_line(case: dict, radial: list[float]) -> list:
    """One stiffness_map line: the cases' radial loads at one (bearing, axial load, speed,
    direction); results in the order of ``radial``."""
    from ..quasistatic.study import stiffness_map
    from .base import pick

    bearing, _ = bearing_from(case)
    condition_from(case)  # the checks of the loads and the speed
    table = stiffness_map(
        bearing,
        radial,
        [case.get("axial_load_n") or 0.0],
        [case.get("speed_rpm") or 0.0],
        radial_load_angle=math.radians(case.get("radial_load_angle_deg", -90.0)),
        workers=1,
        gyroscopic=bool(case.get("gyroscopic")),
        race_control=case.get("race_control") or "outer",
    )
    # stiffness_map returns the loads sorted: put the rows back in the cases' order
    order = np.argsort(np.asarray(radial, float), kind="stable")
    out: list = [None] * len(radial)
    for row, i in zip(table.to_dict(orient="records"), order, strict=True):
        if row["status"] == "ok":
            out[i] = pick(row, _STIFFNESS_OUT)
        else:
            out[i] = InputError(
                "radial_load_n", row["radial_load_n"], "a load the bearing carries", row["status"]
            )
    return out


@dataclass(frozen=True)
class _Row:
    """One stiffness case's columns, as a result."""

    row: dict

    def to_dict(self) -> dict:
        return dict(self.row)


def _stiffness(values: dict) -> _Row:
    result = _stiffness_line(values, [values.get("radial_load_n") or 0.0])[0]
    if isinstance(result, Exception):
        raise result
    return _Row(result)


def _stiffness_batch(cases: list[dict], seed: int) -> list:
    """Group a partition's cases into stiffness_map lines; a line that fails as a whole
    (a bad bearing, a negative load) is retried case by case so only bad cases fail."""
    lines: dict = {}
    for i, case in enumerate(cases):
        key = tuple((k, v) for k, v in case.items() if k not in ("case", "radial_load_n"))
        lines.setdefault(key, []).append(i)
    out: list = [None] * len(cases)
    for members in lines.values():
        first = cases[members[0]]
        try:
            results = _stiffness_line(first, [cases[i].get("radial_load_n", 0.0) for i in members])
        except Exception as exc:  # noqa: BLE001 - retried case by case below
            reraise_interrupt(exc)  # a Ctrl-C is no failed line
            results = []
            for i in members:
                try:
                    results.append(_stiffness(cases[i]).row)
                except Exception as exc:  # noqa: BLE001 - a failed case never stops a study
                    reraise_interrupt(exc)
                    results.append(exc)
        for i, r in zip(members, results, strict=True):
            out[i] = r
    return out


STIFFNESS = Analysis(
    "stiffness",
    "Radial and axial stiffness and displacements (stiffness_map lines, warm-started).",
    {
        **BEARING_INPUTS,
        **_LOADS,
        **_SPEED0,
        **inputs("radial_load_angle_deg", "gyroscopic", "race_control"),
    },
    run=_stiffness,
    outputs=_STIFFNESS_OUT,
    largest=2000,
    batch=_stiffness_batch,
    warm=("bearinglab.quasistatic.study",),
)


# ------------------------------------------------------------------ stiffness map
#: Most cases of one stiffness map.
MAX_MAP_CASES = 1_000_000
#: The forms a grid of values is given in.
_GRID = "START:STOP:COUNT (COUNT 1..10000), a list A,B,C or one value"


def grid(name: str, text) -> np.ndarray:
    """The values of input ``name`` given as a grid ``text`` ('a:b:n': n values from a to
    b, 'a,b,c' or one value), each checked against the input's range in the table.

    >>> grid("speed_rpm", "0:3000:4").tolist()
    [0.0, 1000.0, 2000.0, 3000.0]
    """
    text = str(text)
    try:
        if ":" in text:
            a, b, n = text.split(":")
            if not 1 <= int(n) <= 10000:
                raise ValueError
            values = np.linspace(float(a), float(b), int(n))
        else:
            values = np.array([float(v) for v in text.split(",")])
    except ValueError:
        raise InputError(name, text, _GRID) from None
    for v in values:
        INPUTS[name].check(name, float(v))
    return values


@dataclass(frozen=True)
class StiffnessMap:
    """Stiffness and displacements over a grid of loads and speeds
    (:func:`bearinglab.quasistatic.study.stiffness_map`): the ``table`` (one row per case,
    ``status`` "ok", "no load" or why not), the ``bearing``, the request's
    ``designation`` and the ``warnings``."""

    table: object
    bearing: object
    designation: str | None = None
    warnings: tuple = field(default_factory=tuple)

    @property
    def solved(self):
        """The rows that solved."""
        return self.table[self.table["status"] == "ok"]

    def to_dict(self) -> dict:
        """The cases, how many solved, every row (non-finite values as null), warnings."""
        rows = [
            {
                k: (None if isinstance(v, float) and not math.isfinite(v) else v)
                for k, v in r.items()
            }
            for r in self.table.to_dict(orient="records")
        ]
        return {
            "designation": self.designation,
            "cases": len(rows),
            "solved": len(self.solved),
            "rows": rows,
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        """The table, one row per case."""
        return self.table

    def plot(self, ax=None):
        """C_r and C_a over the radial load, one line per (axial load, speed); (fig, axes)."""
        from ..plotting import stiffness_map_figure

        if not len(self.solved):
            raise InputError(
                "radial_load_n",
                None,
                "a map with at least one solved case to draw",
                "no case of the map solved, status: "
                + ", ".join(sorted(set(self.table["status"]))),
            )
        return stiffness_map_figure(self.solved, ax)


def stiffness_map_request(values: dict, progress=None) -> StiffnessMap:
    """The ``stiffness-map`` request: the stiffness over the grids ``radial_load_n``,
    ``axial_load_n`` and ``speed_rpm``, every value checked before any work;
    ``progress(done, total)`` in cases."""
    from ..quasistatic.study import stiffness_map

    radial, axial, speeds = (
        grid(n, values.get(n) if values.get(n) is not None else STIFFNESS_MAP.options[n].default)
        for n in ("radial_load_n", "axial_load_n", "speed_rpm")
    )
    total = len(radial) * len(axial) * len(speeds)
    if total > MAX_MAP_CASES:
        raise InputError(
            "radial_load_n",
            values.get("radial_load_n"),
            f"a grid of at most {MAX_MAP_CASES:g} cases in all (radial x axial x speed counts)",
        )
    workers = values.get("workers") or 0
    bearing, decoded = bearing_from(values)
    from ..quasistatic import check_speed

    try:  # every speed of the grid, before any work
        check_speed(bearing, float(np.max(speeds)) * math.pi / 30.0)
    except InputError as exc:
        raise restate(exc, values, STIFFNESS_MAP.options) from None
    table = stiffness_map(
        bearing,
        radial,
        axial,
        speeds,
        workers=workers or None,
        progress=progress,
        gyroscopic=bool(values.get("gyroscopic")),
        race_control=values.get("race_control") or "outer",
    )
    return StiffnessMap(
        table, bearing, values.get("designation"), tuple(bearing_warnings(bearing, decoded))
    )


STIFFNESS_MAP = Analysis(
    "stiffness-map",
    "Radial and axial stiffness over a grid of loads and speeds (stiffness_map).",
    {
        **BEARING_INPUTS,
        "radial_load_n": INPUTS["radial_load_n"].with_(
            kind="text",
            default="0:2000:21",
            help="Radial loads: START:STOP:COUNT, A,B,C or one value [N].",
        ),
        "axial_load_n": INPUTS["axial_load_n"].with_(
            kind="text", default="0", help="Axial loads [N], same forms."
        ),
        "speed_rpm": INPUTS["speed_rpm"].with_(
            kind="text", default="0", help="Speeds [rpm], same forms."
        ),
        **inputs("gyroscopic", "race_control"),
        "workers": INPUTS["workers"].with_(
            default=0, help="Worker processes (default 0: all cores).", low=0, high=64
        ),
    },
    run=stiffness_map_request,
    files={
        "output": FILES["output"].with_(help="Write the table to this CSV file."),
        **plot_file("the radial and axial stiffness over the radial load"),
    },
)


# ------------------------------------------------------------------ kinematics
def frequencies(values: dict) -> Outcome:
    """The ``frequencies`` request: kinematic defect frequencies (pure rolling)."""
    from ..inputs import given_fields
    from ..kinematics import defect_frequencies, geometry_inputs
    from ..plausibility import speed_factor_warnings

    shaft_speed = speed_from(values, positive=False)
    bearing, decoded = bearing_from(values)
    f = defect_frequencies(bearing, shaft_speed, outer_rotating=bool(values.get("outer_rotating")))
    used = geometry_inputs(bearing)
    unused = [(name, field not in used) for name, field in given_fields(values).items()]
    warnings = (
        bearing_warnings(bearing, decoded)
        + speed_factor_warnings(bearing, shaft_speed)
        + no_effect(unused, "on the defect frequencies (pure rolling: Z, D_w, d_m, contact angle)")
    )
    return Outcome(f, values.get("designation"), tuple(warnings), bearing)


_FREQ_OUT = {
    f"{n}_{u}": "f" for u in ("hz", "order") for n in ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
}
_FREQ_OUT["shaft_hz"] = "f"

FREQUENCIES = Analysis(
    "frequencies",
    "Kinematic defect frequencies (defect_frequencies).",
    {
        **BEARING_INPUTS,
        "speed_rpm": INPUTS["speed_rpm"].with_(default=...),
        **inputs("outer_rotating"),
    },
    run=frequencies,
    outputs=_FREQ_OUT,
    largest=20000,
    files=plot_file("the defect frequencies"),
)


# ------------------------------------------------------------------ ring modes
_RING_INPUTS = {
    "axial_load_n": INPUTS["axial_load_n"].with_(
        default=None,
        help="Axial load A [N], for K_x from the bearing (default 200 N).",
        low=0.0,
        low_open=True,
    ),
    "modes": Input("text", "2:6", "Modes FIRST:LAST or m1,m2,...; m = 1 is the rigid-body mode."),
    "ring_mass_kg": Input(
        "number",
        None,
        "Vibrating mass of the outer ring incl. sensors [kg].",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "radial_stiffness_n_per_m": Input(
        "number",
        None,
        "Radial bearing stiffness K_x [N/m].",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "rigid_body_frequency_hz": Input(
        "number",
        None,
        "f_1 of the ring on the ball springs [Hz] (instead of sqrt(K_x / ring mass) / 2 pi).",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "free_frequencies_hz": Input(
        "text",
        None,
        "Measured free-ring frequencies f2,f3,... [Hz], one per flexural mode asked for.",
    ),
    "ball_mass_ratio": Input(
        "number", None, "kappa = n m_b / m_k.", low=0.0, high=1e15, low_open=True, high_open=True
    ),
    "contact_stiffness_ratio": Input(
        "number",
        None,
        "K1/K2 (outer over inner contact stiffness).",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "stiffness_from": Input(
        "text",
        None,
        "K_x from seed 000's closed form (axial load, contact angle; the default) or from "
        "the load-distribution stiffness at the axial load.",
        choices=("closed-form", "load-distribution"),
    ),
}
#: Axial load for K_x when none is given [N].
DEFAULT_RING_AXIAL_LOAD = 200.0


def _modes(text: str) -> list[int]:
    try:
        if ":" in text:
            a, b = (int(v) for v in text.split(":"))
            ms = list(range(a, b + 1))
        else:
            ms = [int(v) for v in text.split(",")]
    except ValueError:
        ms = []
    if not ms or min(ms) < 1 or max(ms) > 50:
        raise InputError("modes", text, "FIRST:LAST or a list of mode numbers 1..50")
    return ms


def _free_frequencies(text, flexural: list[int]):
    if text is None:
        return None
    try:
        free = [float(v) for v in str(text).split(",")]
    except ValueError:
        free = []
    if not free or not all(math.isfinite(f) and f > 0 for f in free):
        raise InputError("free_frequencies_hz", text, "positive frequencies f2,f3,... [Hz]")
    if len(free) != len(flexural):
        raise InputError(
            "free_frequencies_hz", text, f"{len(flexural)} values, one per flexural mode {flexural}"
        )
    return dict(zip(flexural, free, strict=True))


def _solve_modes(values: dict, bearing, ms, free, ball_count):
    from ..rings import ring_modes as solve

    axial = values.get("axial_load_n")
    source = values.get("stiffness_from")
    return solve(
        bearing,
        axial_load=(DEFAULT_RING_AXIAL_LOAD if axial is None else axial) if bearing else None,
        modes=ms,
        ring_mass=values.get("ring_mass_kg"),
        radial_stiffness=values.get("radial_stiffness_n_per_m"),
        rigid_body_frequency=values.get("rigid_body_frequency_hz"),
        free_frequencies=free,
        ball_mass_ratio=values.get("ball_mass_ratio"),
        contact_stiffness_ratio=values.get("contact_stiffness_ratio"),
        ball_count=ball_count,
        radial_stiffness_from=(source or "closed-form").replace("-", "_"),
    )


def ring_modes(values: dict) -> Outcome:
    """The ``ring-modes`` request: from a bearing, or from the paper's ring-level inputs
    alone (balls, ring_mass_kg with radial_stiffness_n_per_m or rigid_body_frequency_hz,
    free_frequencies_hz, ball_mass_ratio)."""
    ms = _modes(values.get("modes") or "2:6")
    free = _free_frequencies(values.get("free_frequencies_hz"), [m for m in ms if m >= 2])
    ring_level = values.get("designation") is None and all(
        values.get(k) is None for k in ("ball_diameter_mm", "pitch_diameter_mm", "geometry")
    )
    bearing = decoded = ball_count = None
    if ring_level:
        ball_count = values.get("balls")
        if ball_count is None:
            raise InputError(
                "designation",
                None,
                "a designation, explicit geometry, or the ring-level inputs `balls`, "
                "`ring_mass_kg` with `radial_stiffness_n_per_m` (or `rigid_body_frequency_hz`), "
                "`free_frequencies_hz` and `ball_mass_ratio`",
            )
    else:
        bearing, decoded = bearing_from(values)
        balls_only(
            bearing, values, "the outer-ring modes of seed 000 are those of a ring on ball springs"
        )
    try:
        r = _solve_modes(values, bearing, ms, free, ball_count)
    except InputError as exc:
        raise restate(exc, values, RING_MODES.options) from None
    # the axial load gives K_x, from a bearing, when K_x is not given; given f1, K_x is
    # only reported (f1 fixes the contact stiffness)
    if r.to_dict()["axial_load_n"] is None:
        why = (
            "with `radial_stiffness_n_per_m` (K_x is given)"
            if values.get("radial_stiffness_n_per_m") is not None
            else "without a bearing (K_x from the axial load needs the bearing's contacts)"
        )
    elif values.get("rigid_body_frequency_hz") is not None:
        why = "on the frequencies with `rigid_body_frequency_hz` (only on the K_x reported)"
    else:
        why = None
    given = [
        (n, why is not None and values.get(n) is not None)
        for n in ("axial_load_n", "stiffness_from")
    ]
    warnings = (bearing_warnings(bearing, decoded) if bearing is not None else []) + list(
        r.warnings
    )
    warnings += no_effect(given, why or "")
    return Outcome(r, values.get("designation"), tuple(warnings), bearing)


_MODES = (2, 3, 4, 5, 6)


def _ring_columns(r: Outcome) -> dict:
    d = r.to_dict()
    for m in d["modes"]:
        k = m["m"]
        if k not in _MODES:
            continue
        d[f"m{k}_free_hz"] = m["free_hz"]
        d[f"m{k}_approx_low_hz"], d[f"m{k}_approx_high_hz"] = (
            min(m["approx_hz"]),
            max(m["approx_hz"]),
        )
        refined = [f for f in m["refined_hz"] if f is not None]
        if refined:
            d[f"m{k}_refined_low_hz"], d[f"m{k}_refined_high_hz"] = min(refined), max(refined)
    return d


_RING_OUT = {
    "rigid_body_frequency_hz": "f",
    "radial_stiffness_n_per_um": "f",
    "ring_mass_kg": "f",
    "ball_mass_ratio": "f",
    "contact_stiffness_ratio": "f",
}
for _m in _MODES:
    for _k in ("free", "approx_low", "approx_high", "refined_low", "refined_high"):
        _RING_OUT[f"m{_m}_{_k}_hz"] = "f"

RING_MODES = Analysis(
    "ring-modes",
    "Outer-ring natural frequencies (ring_modes, seed 000).",
    {**BEARING_INPUTS, **_RING_INPUTS},
    run=ring_modes,
    outputs=_RING_OUT,
    largest=2000,
    columns=_ring_columns,
    warm=("bearinglab.rings",),
    probe={"modes": "2:6"},
    files=plot_file("the frequencies"),
)
