"""Model objects of the noise model: the medium and the field point (layer 2).

Seed 003 part 4 (noise model assumptions (b)-(d), seed file line 769: air is an ideal,
still, uniform medium of constant properties; point A is 10 mm from the bearing centre,
line 771). Seed 003's point A lies inside most bearings (a 608's outer ring has a radius
of 11 mm), so the default point of a bearing (:func:`default_field_point`) lies
:data:`FIELD_POINT_GAP` outside its outside diameter instead; :data:`SEED003_POINT_A` is
the seed's point, for reproducing the paper.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, positive_number
from .sources import AIR_DENSITY, AIR_SOUND_SPEED

#: Distance of the default field point outside the bearing's outside diameter [m] (the
#: report's rule since issue 5; 10 mm, seed 003's distance of point A, now from the
#: outside surface rather than the centre).
FIELD_POINT_GAP = 0.010


@dataclass(frozen=True)
class Air:
    """The medium: density rho_0 [kg/m^3] and speed of sound c_0 [m/s] (defaults: dry air
    at 20 deg C, 101.325 kPa). Seed 003's assumptions (b)-(d): an ideal, still, uniform
    medium of constant properties."""

    density: float = AIR_DENSITY
    sound_speed: float = AIR_SOUND_SPEED

    def __post_init__(self) -> None:
        for name, unit in (("density", "[kg/m^3]"), ("sound_speed", "[m/s]")):
            v = positive_number(name, getattr(self, name), f"a finite number > 0 {unit}")
            object.__setattr__(self, name, v)


@dataclass(frozen=True)
class FieldPoint:
    """Where the pressure is computed, in the bearing's radial plane: ``distance`` from the
    bearing centre [m] (seed 003: point A, 10 mm) and ``angle`` from +x towards +y [rad]
    (docs/conventions.md; default +y, above the bearing, on the line of a downward load:
    the seed's figure 6 is not in the text, so the direction is a choice)."""

    distance: float = 0.010
    angle: float = 0.5 * math.pi

    def __post_init__(self) -> None:
        for name, positive in (("distance", True), ("angle", False)):
            v = getattr(self, name)
            if (
                isinstance(v, bool)
                or not isinstance(v, (int, float, np.integer, np.floating))
                or not math.isfinite(v)
                or (positive and v <= 0)
            ):
                raise InputError(
                    name, v, "a finite distance > 0 [m]" if positive else "a finite angle [rad]"
                )
            object.__setattr__(self, name, float(v))

    @property
    def position(self) -> np.ndarray:
        """(x, y) of the point [m]."""
        return self.distance * np.array([math.cos(self.angle), math.sin(self.angle)])


#: Seed 003's point A: 10 mm from the bearing centre (seed file line 771), straight up
#: (the direction, the seed's fig. 6, is not in the text: a choice).
SEED003_POINT_A = FieldPoint(0.010, 0.5 * math.pi)


def as_field_point(point) -> FieldPoint:
    """``point`` as a FieldPoint: one already, or (distance [m], angle [rad])."""
    if isinstance(point, FieldPoint):
        return point
    try:
        return FieldPoint(*point)
    except TypeError:
        raise InputError("point", point, "a FieldPoint or (distance [m], angle [rad])") from None


def outer_radius(bearing) -> tuple[float, str]:
    """Outside radius of the bearing [m] and where it comes from: D / 2, or, without an
    outside diameter, d_m / 2 + D_w (the outer raceway's radius plus half a ball: 11.4 mm
    for a 608 whose D / 2 is 11 mm, 27.2 mm for a 6205 whose D / 2 is 26 mm)."""
    if bearing.outside_diameter is not None:
        return 0.5 * bearing.outside_diameter, "D / 2"
    return 0.5 * bearing.pitch_diameter + bearing.ball_diameter, "d_m / 2 + D_w (no D given)"


def default_field_point(bearing, angle: float | None = None) -> tuple[FieldPoint, str]:
    """The field point used when none is given: :data:`FIELD_POINT_GAP` (10 mm) outside
    the outside radius of ``bearing`` (:func:`outer_radius`), in the direction ``angle`` [rad]
    from +x towards +y (default straight up, +y: above the bearing, against a downward
    load), and the rule in words.

    Parameters
    ----------
    bearing : BallBearing
        The bearing that radiates; its outside radius places the point.
    angle : float or None
        Direction of the point from +x towards +y [rad]; None: straight up (+y).

    Returns
    -------
    (FieldPoint, str)
        The point and the rule that placed it, in words.

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=7, ball_diameter=3.85e-3, pitch_diameter=15e-3,
    ...                 bore=8e-3, outside_diameter=22e-3, width=7e-3)
    >>> point, rule = default_field_point(b)
    >>> round(point.distance * 1e3, 6), rule
    (21.0, 'default: 10 mm outside the outside radius D / 2 = 11 mm, straight up')
    """
    radius, how = outer_radius(bearing)
    up = 0.5 * math.pi
    angle = up if angle is None else angle
    point = FieldPoint(radius + FIELD_POINT_GAP, angle)
    where = (
        "straight up"
        if math.isclose(point.angle, up, abs_tol=1e-12)
        else f"at {math.degrees(point.angle):.4g} deg from +x"
    )
    rule = (
        f"default: {FIELD_POINT_GAP * 1e3:g} mm outside the outside radius {how} = "
        f"{radius * 1e3:.4g} mm, {where}"
    )
    return point, rule


def least_field_distance(bearing) -> float:
    """Least distance of a field point from the centre of ``bearing`` [m]: (d_m + D_w) / 2,
    just outside the balls' path. Inside it the point would lie in the inner-ring cylinder, in
    a ball's path (the sources of seed 003's eqs. 19 and 23) or in the thin gap between
    them, inside the bearing.

    Parameters
    ----------
    bearing : BallBearing
        The bearing (pitch diameter d_m and ball diameter D_w [m]).
    """
    return 0.5 * (bearing.pitch_diameter + bearing.ball_diameter)


def check_field_point(bearing, point: FieldPoint) -> list[str]:
    """Refuse a ``point`` inside the balls' path of ``bearing``
    (:func:`least_field_distance`); warn when it lies inside the bearing's outside radius.

    Parameters
    ----------
    bearing : BallBearing
        The bearing that radiates.
    point : FieldPoint
        The field point (its distance from the bearing's centre [m] and angle [rad]); its
        distance must exceed :func:`least_field_distance`.

    Returns
    -------
    list of str
        A warning when the point lies inside the bearing's outside radius, else none.

    Raises
    ------
    InputError
        Named ``point`` (value: its distance [m]).
    """
    least = least_field_distance(bearing)
    radius, how = outer_radius(bearing)
    if point.distance <= least:
        raise InputError(
            "point",
            point.distance,
            f"a distance > {least:.6g} m from the centre (outside the inner ring "
            "and the balls' path)",
            f"the bearing's outside radius {how} is {radius:.6g} m",
        )
    if point.distance < radius:
        return [
            f"the field point ({point.distance * 1e3:.4g} mm from the centre) lies inside "
            f"the bearing's outside radius ({how} = {radius * 1e3:.4g} mm): the model, like "
            "seed 003's, radiates into free air and ignores the outer ring"
        ]
    return []
