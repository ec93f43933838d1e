"""Equivalent loads of ball bearings: dynamic P = X F_r + Y F_a (ISO 281:2007 Table 3)
and static P_0 = max(F_r, X_0 F_r + Y_0 F_a) (ISO 76:2006 Table 2), single row.

ISO 281 Table 3 gives X, Y and e for F_a/F_r > e (below e: X = 1, Y = 0). For contact
angles below 20 deg they depend on the relative axial load, tabulated against
F_a / (i Z D_w^2) in N/mm^2 (= f_0 F_a / C_0r times cos alpha); between tabulated angles
and loads the values are interpolated linearly, first along the load in each angle's
block, then across the angle. Outside the tabulated loads the end values are used (and
the result says so). The values are those for a normal radial internal clearance
(group N); ISO 281 gives none for other groups.

Sources: :mod:`bearinglab.ratings.tables`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError, positive_number
from ..geometry import BallBearing
from . import tables as T

_LOW_ANGLES = np.array(sorted(T.XYE_LOW_SINGLE))  # 0, 5, 10, 15 deg
_HIGH_ANGLES = np.array(sorted(T.XYE_HIGH_SINGLE))  # 20 ... 45 deg


class LoadFactors(NamedTuple):
    """X, Y, e of ISO 281 Table 3 (X, Y apply when F_a/F_r > e) and whether the relative
    axial load lay outside the table (the end value was used)."""

    x: float
    y: float
    e: float
    clamped: bool = False


def _block(angle_deg: float, relative: float) -> tuple[float, float, float]:
    x, y, e = T.XYE_LOW_SINGLE[angle_deg]
    return x, float(np.interp(relative, T.XYE_GRID, y)), float(np.interp(relative, T.XYE_GRID, e))


def load_factors(contact_angle: float, relative_axial_load: float) -> LoadFactors:
    """X, Y, e of ISO 281 Table 3 for a single-row radial or angular-contact ball bearing.

    Parameters
    ----------
    contact_angle : float
        Nominal contact angle alpha, 0 ... 45 deg [rad].
    relative_axial_load : float
        F_a / (i Z D_w^2) [Pa]; used below 20 deg only.

    Returns
    -------
    LoadFactors

    Examples
    --------
    >>> load_factors(0.0, 1.03e6)[:3]
    (0.56, 1.55, 0.28)
    >>> tuple(round(v, 3) for v in load_factors(math.radians(22.5), 0.0)[:3])
    (0.42, 0.935, 0.625)
    """
    if not (
        isinstance(contact_angle, (int, float, np.floating))
        and 0.0 <= contact_angle <= math.radians(45.0) + 1e-12
    ):
        raise InputError(
            "contact_angle",
            contact_angle,
            "an angle in [0, 45] degrees",
            "ISO 281 Table 3 covers radial and angular-contact ball bearings up to 45 deg",
        )
    positive_number(
        "relative_axial_load", relative_axial_load, "a finite value >= 0 [Pa]", zero=True
    )
    angle = math.degrees(contact_angle)
    if angle >= 20.0:
        cols = [np.array([T.XYE_HIGH_SINGLE[a][k] for a in _HIGH_ANGLES]) for k in range(3)]
        return LoadFactors(*(float(np.interp(angle, _HIGH_ANGLES, c)) for c in cols))
    relative = relative_axial_load / 1e6  # N/mm^2, the table's unit
    clamped = relative > T.XYE_GRID[-1] * (1 + 1e-9)
    if relative < T.XYE_GRID[0]:
        relative = float(T.XYE_GRID[0])
    blocks = [_block(a, relative) for a in _LOW_ANGLES] + [T.XYE_HIGH_SINGLE[20.0]]
    grid = np.append(_LOW_ANGLES, 20.0)
    x, y, e = (float(np.interp(angle, grid, [b[k] for b in blocks])) for k in range(3))
    return LoadFactors(x, y, e, bool(clamped))


def _loads(radial_load: float, axial_load: float) -> tuple[float, float]:
    for name, value in (("radial_load", radial_load), ("axial_load", axial_load)):
        if not (isinstance(value, (int, float, np.floating)) and math.isfinite(value)):
            raise InputError(name, value, "a finite load [N]")
    if radial_load < 0:
        raise InputError("radial_load", radial_load, "a load >= 0 [N]")
    if radial_load == 0 and axial_load == 0:
        raise InputError(
            "radial_load",
            radial_load,
            "a load > 0 [N] (or an axial load)",
            "an unloaded bearing has no rating life",
        )
    return float(radial_load), abs(float(axial_load))


def _thrust_check(bearing: BallBearing, radial: float) -> None:
    if radial > 0:
        raise InputError(
            "radial_load",
            radial,
            "0 for a thrust ball bearing with a 90 deg contact angle",
            "it carries axial load only (ISO 281)",
        )


def equivalent_dynamic_load(
    bearing: BallBearing, radial_load: float, axial_load: float = 0.0
) -> tuple[float, LoadFactors]:
    """Dynamic equivalent load P of a single-row ball bearing, ISO 281:2007 [N].

    Radial and angular-contact bearings: P_r = F_r when F_a/F_r <= e, else
    X F_r + Y F_a (Table 3, normal clearance); thrust ball bearings (90 deg): P_a = F_a.
    A roller bearing (``rolling_element`` "roller") gets the roller rows of Table 3
    (:func:`bearinglab.ratings.roller.roller_equivalent_dynamic_load`).

    Parameters
    ----------
    bearing : BallBearing
        Geometry (contact angle, Z, D_w, type).
    radial_load : float
        F_r >= 0 [N].
    axial_load : float
        F_a (its sign does not matter) [N].

    Returns
    -------
    tuple
        (P [N], the LoadFactors used; X = 1, Y = 0 when F_a/F_r <= e).

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
    >>> round(equivalent_dynamic_load(b, 1000.0, 500.0)[0])
    1370
    """
    radial, axial = _loads(radial_load, axial_load)
    if getattr(bearing, "rolling_element", "ball") == "roller":
        from .roller import roller_equivalent_dynamic_load

        p, x, y, e = roller_equivalent_dynamic_load(
            bearing.contact_angle, int(bearing.rows), radial, axial
        )
        return p, LoadFactors(x, y, e)
    if bearing.is_thrust:
        _thrust_check(bearing, radial)
        return axial, LoadFactors(0.0, 1.0, 0.0)
    relative = axial / (bearing.ball_count * bearing.ball_diameter**2)
    factors = load_factors(bearing.contact_angle, relative)
    if radial > 0 and axial / radial <= factors.e:
        return radial, LoadFactors(1.0, 0.0, factors.e, factors.clamped)
    return factors.x * radial + factors.y * axial, factors


def static_load_factors(contact_angle: float) -> tuple[float, float]:
    """(X_0, Y_0) of ISO 76:2006 Table 2, single row: (0.6, 0.5) for radial contact,
    X_0 = 0.5 and Y_0 interpolated by contact angle between 5 and 45 deg.

    Parameters
    ----------
    contact_angle : float
        Nominal contact angle [rad]: 0, or 5 ... 45 deg.

    Examples
    --------
    >>> static_load_factors(0.0), static_load_factors(math.radians(37.5))
    ((0.6, 0.5), (0.5, 0.275))
    """
    angle = (
        math.degrees(contact_angle)
        if isinstance(contact_angle, (int, float, np.floating))
        else None
    )
    if angle is not None and angle == 0.0:
        return T.X0_RADIAL, T.Y0_RADIAL
    if angle is None or not (5.0 - 1e-9 <= angle <= 45.0 + 1e-9):
        raise InputError(
            "contact_angle",
            contact_angle,
            "0, or an angle in [5, 45] degrees",
            "ISO 76 Table 2 gives X_0, Y_0 for radial contact and 5-45 deg only",
        )
    return T.X0_ANGULAR, float(np.interp(angle, T.Y0_ANGLE_DEG, T.Y0_ANGULAR))


def equivalent_static_load(
    bearing: BallBearing, radial_load: float, axial_load: float = 0.0
) -> float:
    """Static equivalent load P_0 of a single-row ball bearing, ISO 76:2006 [N]:
    max(F_r, X_0 F_r + Y_0 F_a) for radial and angular-contact bearings, F_a for a thrust
    ball bearing with a 90 deg contact angle; a roller bearing, ISO 76's roller rows
    (:func:`bearinglab.ratings.roller.roller_equivalent_static_load`).

    Parameters
    ----------
    bearing : BallBearing
        Geometry (contact angle, type).
    radial_load : float
        F_r >= 0 [N].
    axial_load : float
        F_a [N].

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
    >>> equivalent_static_load(b, 1000.0, 500.0), equivalent_static_load(b, 1000.0, 1200.0)
    (1000.0, 1200.0)
    """
    radial, axial = _loads(radial_load, axial_load)
    if getattr(bearing, "rolling_element", "ball") == "roller":
        from .roller import roller_equivalent_static_load

        return roller_equivalent_static_load(
            bearing.contact_angle, int(bearing.rows), radial, axial
        )
    if bearing.is_thrust:
        _thrust_check(bearing, radial)
        return axial
    x0, y0 = static_load_factors(bearing.contact_angle)
    return max(radial, x0 * radial + y0 * axial)
