"""A case's inputs (engineering units, the command line's option names) as model objects:
the bearing (cached per process: a study asks for the same few bearings again and again),
the operating condition, the imperfections."""

from __future__ import annotations

import functools
import math

from ..errors import InputError
from .cases import Option

#: Bearing options: name -> (Option, BallBearing keyword, SI factor).
BEARING_OPTIONS = {
    "designation": (Option("text", None, "Bearing designation or catalogue name."), None, None),
    "system": (
        Option("text", None, "Read the designation as gost or iso.", ("gost", "iso")),
        None,
        None,
    ),
    "balls": (Option("integer", None, "Number of balls Z."), "ball_count", 1),
    "ball_diameter_mm": (Option("number", None, "Ball diameter D_w [mm]."), "ball_diameter", 1e-3),
    "pitch_diameter_mm": (
        Option("number", None, "Pitch diameter d_m [mm]."),
        "pitch_diameter",
        1e-3,
    ),
    "contact_angle_deg": (
        Option("number", None, "Nominal contact angle [deg]."),
        "contact_angle",
        math.pi / 180,
    ),
    "inner_groove_factor": (
        Option("number", None, "Inner groove factor f_i."),
        "inner_groove_factor",
        1,
    ),
    "outer_groove_factor": (
        Option("number", None, "Outer groove factor f_o."),
        "outer_groove_factor",
        1,
    ),
    "clearance_um": (
        Option("number", None, "Diametral clearance P_d [um] (< 0: preload)."),
        "diametral_clearance",
        1e-6,
    ),
    "bore_mm": (Option("number", None, "Bore d [mm]."), "bore", 1e-3),
    "outside_diameter_mm": (
        Option("number", None, "Outside diameter D [mm]."),
        "outside_diameter",
        1e-3,
    ),
    "width_mm": (Option("number", None, "Width B [mm]."), "width", 1e-3),
}
BEARING_NAMES = tuple(BEARING_OPTIONS)
GEOMETRY_NEEDED = ("balls", "ball_diameter_mm", "pitch_diameter_mm")


def check_bearing_given(given: set) -> None:
    """A study needs a designation or the explicit geometry (checked before it runs)."""
    if "designation" not in given and not set(GEOMETRY_NEEDED) <= given:
        raise InputError(
            "designation", None, "a designation, or balls, ball_diameter_mm and pitch_diameter_mm"
        )


@functools.lru_cache(maxsize=256)
def _bearing(values: tuple):
    from ..catalog import bearing_from_designation
    from ..geometry import BallBearing, Source

    given = dict(values)
    overrides = {}
    for name, value in given.items():
        _, keyword, factor = BEARING_OPTIONS[name]
        if keyword is not None and value is not None:
            overrides[keyword] = int(value) if keyword == "ball_count" else value * factor
    designation = given.get("designation")
    if designation:
        bearing, _ = bearing_from_designation(
            designation, system=given.get("system"), overrides=overrides
        )
        return bearing
    sources = {k: Source("user", "study") for k in overrides}
    return BallBearing(name="user geometry", sources=sources, **overrides)


def bearing_of(case: dict):
    """The BallBearing of a case (designation and/or geometry options)."""
    key = tuple((n, case.get(n)) for n in BEARING_NAMES if case.get(n) is not None)
    return _bearing(key)


def rad_s(case: dict, positive: bool = False) -> float:
    """speed_rpm [rpm] -> [rad/s]; >= 0 (> 0 with ``positive``)."""
    rpm = case["speed_rpm"]
    if not (rpm > 0 if positive else rpm >= 0):
        raise InputError("speed_rpm", rpm, "a speed > 0 rpm" if positive else "a speed >= 0 rpm")
    return rpm * math.pi / 30.0


def condition_of(case: dict, positive_speed: bool = False):
    """OperatingCondition from radial_load_n, axial_load_n, speed_rpm, radial_load_angle_deg
    and misalignment_mrad (a tilt about the radial-plane axis across the load, as the
    ``static`` command takes it)."""
    from ..operating import OperatingCondition

    angle = math.radians(case.get("radial_load_angle_deg", -90.0))
    tilt = (case.get("misalignment_mrad") or 0.0) * 1e-3
    return OperatingCondition(
        radial_load=case.get("radial_load_n", 0.0),
        radial_load_angle=angle,
        axial_load=case.get("axial_load_n", 0.0),
        misalignment=(-tilt * math.sin(angle), tilt * math.cos(angle)),
        shaft_speed=rad_s(case, positive_speed),
    )


#: Form-error options shared by noise and simulate.
FORM_OPTIONS = {
    "waviness_outer_order": Option("integer", None, "Outer-race waviness order q."),
    "waviness_outer_amplitude_um": Option("number", 0.0, "Outer-race waviness amplitude [um]."),
    "waviness_inner_order": Option("integer", None, "Inner-race waviness order q."),
    "waviness_inner_amplitude_um": Option("number", 0.0, "Inner-race waviness amplitude [um]."),
    "waviness_ball_order": Option("integer", None, "Waviness order of every ball."),
    "waviness_ball_amplitude_um": Option("number", 0.0, "Ball waviness amplitude [um]."),
    "ball_size_error_um": Option(
        "number",
        0.0,
        "Band of random ball diameter errors [um] (uniform in +-band/2, drawn from the case seed).",
        seeded=True,
    ),
}


def imperfections_of(case: dict, bearing, seed: int):
    """Imperfections from the form options (None when there are none)."""
    from ..imperfections import BallSizeErrors, Imperfections, Waviness

    waves = []
    for race in ("outer", "inner", "ball"):
        amplitude = case.get(f"waviness_{race}_amplitude_um") or 0.0
        order = case.get(f"waviness_{race}_order")
        if amplitude:
            if order is None:
                raise InputError(
                    f"waviness_{race}_order",
                    None,
                    f"a waviness order >= 1 with waviness_{race}_amplitude_um",
                )
            waves.append(Waviness(race, int(order), amplitude * 1e-6))
    band = case.get("ball_size_error_um") or 0.0
    errors = BallSizeErrors.random(bearing.ball_count, band * 1e-6, seed=seed) if band else None
    if not waves and errors is None:
        return None
    return Imperfections(waves, ball_size_errors=errors)
