"""The request: what a user gives, declared once (:data:`INPUTS`), and the builders that
turn it into model objects in SI, checking it in the user's units.

Every front end - the command line, the studies, the data sets, the report - takes its
inputs from :data:`INPUTS` and calls these builders; their errors name the input by its
public name (``radial_load_n``), with the value as given, and the command line words
that name as its flag (``--radial-load-n``).

>>> bearing, _ = bearing_from({"designation": "6205"})
>>> round(bearing.ball_diameter * 1e3, 2)
7.94
>>> condition_from({"radial_load_n": 1000.0, "speed_rpm": 1797.0}).radial_load
1000.0
"""

from __future__ import annotations

import math

from ..errors import InputError
from .bearing import (
    balls_only,
    bearing_from,
    bearing_warnings,
    geometry_line,
    geometry_rows,
    given_fields,
    read_geometry_file,
)
from .specs import FormErrors, check_defects, parse_defect
from .table import BEARING, FORMS, GEOMETRY_NEEDED, INPUTS, Input
from .values import check, closed, input_for, restate, si

__all__ = [
    "BEARING",
    "FORMS",
    "GEOMETRY_NEEDED",
    "INPUTS",
    "FormErrors",
    "Input",
    "balls_only",
    "bearing_from",
    "bearing_warnings",
    "check",
    "check_defects",
    "closed",
    "condition_from",
    "geometry_line",
    "geometry_rows",
    "given_fields",
    "input_for",
    "lubricant_from",
    "no_effect",
    "parse_defect",
    "read_geometry_file",
    "restate",
    "si",
    "speed_from",
]

_CONDITION = (
    "speed_rpm",
    "radial_load_n",
    "axial_load_n",
    "radial_load_angle_deg",
    "misalignment_mrad",
)


def speed_from(values: dict, *, positive: bool = True) -> float:
    """The shaft speed [rad/s] of ``speed_rpm`` in the request ``values`` (> 0 rpm, or
    >= 0 unless ``positive``).

    Parameters
    ----------
    values : dict
        The request; its ``speed_rpm`` [rpm] is required and checked against the table's
        range.
    positive : bool
        Require a speed > 0 rpm; False allows 0.

    Returns
    -------
    float
        The shaft speed [rad/s].
    """
    rpm = values.get("speed_rpm")
    if rpm is None:
        raise InputError("speed_rpm", None, "a speed in rpm")
    INPUTS["speed_rpm"].check("speed_rpm", rpm)
    if positive and rpm <= 0:
        raise InputError("speed_rpm", rpm, "a speed > 0 rpm")
    return si({"speed_rpm": rpm}, "speed_rpm")


def condition_from(values: dict, *, positive_speed: bool = False, unloaded: str = ""):
    """The OperatingCondition of the request ``values``: ``speed_rpm`` (> 0 with
    ``positive_speed``), ``radial_load_n``, ``axial_load_n``,
    ``radial_load_angle_deg`` and ``misalignment_mrad`` (a tilt about the radial-plane axis
    across the load); absent inputs take the table's defaults (speed 0). With
    ``unloaded`` (why a load is needed) a load of zero is refused.

    Parameters
    ----------
    values : dict
        The request: input name -> value in its unit (``speed_rpm`` [rpm],
        ``radial_load_n`` [N], ``axial_load_n`` [N], ``radial_load_angle_deg`` [deg],
        ``misalignment_mrad`` [mrad]; absent or None: the table's default).
    positive_speed : bool
        Refuse a speed of 0 rpm (the speed must then be > 0 rpm).
    unloaded : str
        Why the analysis needs a load; when not empty, a request with both loads zero is
        refused with this reason. Empty (the default): a zero load is allowed.

    Returns
    -------
    OperatingCondition
        In SI: loads [N], load angle [rad], misalignment [rad] and shaft speed [rad/s].
    """
    from ..operating import OperatingCondition

    v = {name: values.get(name, INPUTS[name].default) for name in _CONDITION}
    v = {name: INPUTS[name].default if x is None else x for name, x in v.items()}
    check(v)
    if unloaded and not v["radial_load_n"] and not v["axial_load_n"]:
        raise InputError(
            "radial_load_n", v["radial_load_n"], "a load > 0 N (or an `axial_load_n`)", unloaded
        )
    angle = si(v, "radial_load_angle_deg")
    tilt = si(v, "misalignment_mrad")
    speed = 0.0 if v["speed_rpm"] is None else speed_from(v, positive=positive_speed)
    return OperatingCondition(
        radial_load=float(v["radial_load_n"]),
        radial_load_angle=angle,
        axial_load=float(v["axial_load_n"]),
        misalignment=(-tilt * math.sin(angle), tilt * math.cos(angle)),
        shaft_speed=speed,
    )


def no_effect(given, why: str) -> list[str]:
    """A warning naming the inputs given (``given``: (name, given) pairs) that have no
    effect ``why``; none when none was given.

    Parameters
    ----------
    given : iterable of (str, bool)
        (input name, whether it was given) pairs; names that are identifiers are written in
        backquotes.
    why : str
        The condition under which they have no effect (e.g. "without `film` (the EHL
        film)").

    Returns
    -------
    list of str
        One warning naming the inputs given, or an empty list.
    """
    names = [f"`{name}`" if name.isidentifier() else name for name, on in given if on]
    return [f"{' and '.join(names)}: no effect {why}"] if names else []


#: The film's lubricant when none is named.
DEFAULT_LUBRICANT = "iso-vg68"


def lubricant_from(values: dict):
    """(Lubricant, temperature [K] or None, warnings) of the request ``values``:
    ``lubricant`` and
    ``temperature_c`` for the EHL ``film``: (None, None, warnings) without the film, the
    warnings naming the lubricant inputs that then have no effect.

    Parameters
    ----------
    values : dict
        The request: ``film`` (bool), ``lubricant`` (one of the built-in lubricants, default
        iso-vg68) and ``temperature_c`` [degC] (in [-60, 300]; None: the lubricant's
        reference temperature).
    """
    from ..lubrication import LUBRICANTS, ZERO_CELSIUS

    check(values, {name: INPUTS[name] for name in ("lubricant", "temperature_c")})
    name = values.get("lubricant") or DEFAULT_LUBRICANT
    temperature = values.get("temperature_c")
    if not values.get("film"):
        given = (("lubricant", values.get("lubricant") not in (None, DEFAULT_LUBRICANT)),)
        given += (("temperature_c", temperature is not None),)
        return None, None, no_effect(given, "without `film` (the EHL film)")
    kelvin = None if temperature is None else temperature + ZERO_CELSIUS
    return LUBRICANTS[name], kelvin, []
