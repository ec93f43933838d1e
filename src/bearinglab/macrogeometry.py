"""Macrogeometry of a single-row ball bearing (layer 1): groove-bottom diameters, the free
contact angle and the clearance that gives it, contact radii, curvature sums and
differences. :class:`bearinglab.geometry.BallBearing` calls these, and
``bearinglab.geometry`` re-exports them.

Source: Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*, 5th ed.,
2007 ([Harris2007a]), ch. 2 ("Rolling bearing macrogeometry": diametral clearance
P_d = d_o - d_i - 2 D, eq. 2.1; free contact angle cos(alpha_0) = 1 - P_d / (2 A), eq. 2.5;
curvature sums and differences, eqs. 2.26-2.33). Conventions: docs/conventions.md; names:
docs/nomenclature.md.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from .errors import InputError

Race = Literal["inner", "outer"]


def raceway_diameters(pitch_diameter, ball_diameter, diametral_clearance):
    """Groove-bottom diameters (d_i, d_o) of the inner and outer raceway [m].

    Harris & Kotzalas eq. 2.1 with d_m = (d_i + d_o)/2:
    d_i = d_m - D_w - P_d/2, d_o = d_m + D_w + P_d/2.

    Parameters
    ----------
    pitch_diameter : float or array
        Pitch diameter d_m [m].
    ball_diameter : float or array
        Ball diameter D_w [m].
    diametral_clearance : float or array
        Diametral clearance P_d [m]; negative for an interference (preload).

    Examples
    --------
    >>> [round(float(x) * 1e3, 4) for x in raceway_diameters(0.065, 0.0127, 15e-6)]
    [52.2925, 77.7075]
    """
    half = ball_diameter + 0.5 * np.asarray(diametral_clearance)
    return pitch_diameter - half, pitch_diameter + half


def free_contact_angle(
    diametral_clearance, ball_diameter, inner_groove_factor, outer_groove_factor
):
    """Free (unloaded) contact angle alpha_0 from the clearance [rad].

    cos(alpha_0) = 1 - P_d / (2 A), A = (f_i + f_o - 1) D_w (Harris & Kotzalas eq. 2.5).
    An interference (P_d < 0) gives 0.

    Parameters
    ----------
    diametral_clearance : float or array
        P_d [m], at most 2 A (beyond that the balls are loose at 90 degrees).
    ball_diameter : float
        D_w [m].
    inner_groove_factor, outer_groove_factor : float
        f_i, f_o [-], each > 0.5.

    Examples
    --------
    >>> import math
    >>> round(math.degrees(free_contact_angle(15e-6, 0.0127, 0.52, 0.52)), 2)
    9.86
    """
    a = (inner_groove_factor + outer_groove_factor - 1.0) * ball_diameter
    ratio = np.clip(1.0 - np.maximum(diametral_clearance, 0.0) / (2.0 * a), -1.0, 1.0)
    return np.arccos(ratio)


def clearance_for_contact_angle(
    contact_angle, ball_diameter, inner_groove_factor, outer_groove_factor
):
    """Diametral clearance that gives the free contact angle alpha_0 [m].

    Inverse of :func:`free_contact_angle`: P_d = 2 A (1 - cos alpha_0).

    Parameters
    ----------
    contact_angle : float or array
        alpha_0 [rad].
    ball_diameter : float
        D_w [m].
    inner_groove_factor, outer_groove_factor : float
        f_i, f_o [-].
    """
    a = (inner_groove_factor + outer_groove_factor - 1.0) * ball_diameter
    return 2.0 * a * (1.0 - np.cos(contact_angle))


def contact_radii(ball_diameter, pitch_diameter, groove_factor, contact_angle, race: Race):
    """Effective radii (R_x, R_y) of a ball-raceway contact [m].

    R_x lies in the rolling direction, R_y across the groove; 1/R_x + 1/R_y is the
    curvature sum and (1/R_x - 1/R_y) / (1/R_x + 1/R_y) the curvature difference
    F(rho) of Harris & Kotzalas eqs. 2.26-2.33, with gamma = D_w cos(alpha) / d_m:

    inner: R_x = D_w (1 - gamma) / 2, outer: R_x = D_w (1 + gamma) / 2,
    both: R_y = f D_w / (2 f - 1).

    Parameters
    ----------
    ball_diameter : float
        D_w [m].
    pitch_diameter : float
        d_m [m].
    groove_factor : float
        f_i or f_o [-] (groove radius / D_w), > 0.5.
    contact_angle : float or array
        Operating contact angle alpha [rad].
    race : {"inner", "outer"}
        Which raceway.

    Examples
    --------
    >>> rx, ry = contact_radii(12.7e-3, 65e-3, 0.52, 0.0, "inner")
    >>> round(float(1e-3 * (1 / rx + 1 / ry)), 4)  # Harris 209 example: 0.2018 /mm
    0.2018
    """
    if race not in ("inner", "outer"):
        raise InputError("race", race, "'inner' or 'outer'")
    gamma = ball_diameter * np.cos(contact_angle) / pitch_diameter
    sign = -1.0 if race == "inner" else 1.0
    rx = 0.5 * ball_diameter * (1.0 + sign * gamma)
    ry = groove_factor * ball_diameter / (2.0 * groove_factor - 1.0)
    return rx, ry


def curvature_sum_difference(rx, ry):
    """Curvature sum Sum(rho) [1/m] and difference F(rho) [-] from the radii.

    Parameters
    ----------
    rx, ry : float or array
        Effective radii in the rolling and transverse directions [m].
    """
    sx, sy = 1.0 / np.asarray(rx, float), 1.0 / np.asarray(ry, float)
    total = sx + sy
    return total, np.abs(sx - sy) / total
