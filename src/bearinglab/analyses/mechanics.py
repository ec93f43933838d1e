"""The ``static`` analysis: the quasi-static load distribution of a request, with the
form errors at rest and the inner-ring orbit on request (seed 003). The stiffness over
loads is in :mod:`.stiffness`, the defect frequencies in :mod:`.foundation`, the ring
modes in :mod:`.rings`. Physics is never repeated here: the analysis builds the models
from the request (:mod:`bearinglab.inputs`), calls the library once and keeps the result.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import InputError
from ..inputs import (
    FormErrors,
    Input,
    bearing_from,
    bearing_warnings,
    condition_from,
    lubricant_from,
    no_effect,
    restate,
)
from .base import BEARING_INPUTS, LOADS, SPEED_AT_REST, Analysis, inputs, plot_file, specs

#: the form-error inputs, by the names the contact check gives them
_FORM_INPUTS = ("waviness", "ball_size_error_um", "surface3d")


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
        **LOADS,
        **SPEED_AT_REST,
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
