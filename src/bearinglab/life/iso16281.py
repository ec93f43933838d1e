"""Basic reference rating life of ISO/TS 16281 from the internal load distribution.

The bearing's ISO 281 rating C is split into basic dynamic load ratings of a single
contact on each raceway (conformity-dependent; ISO/TS 16281 eqs. for ball bearings):

    Q_ci = C / (0.407 i^0.7 Z cos a) [1 + T^(10/3)]^0.3,
    Q_ce = C / (0.389 i^0.7 Z cos a) [1 + T^(-10/3)]^0.3,
    T = 1.044 ((1 - g)/(1 + g))^1.72 (r_i (2 r_e - D_w) / (r_e (2 r_i - D_w)))^0.41,

and the per-ball contact loads Q_j of :func:`bearinglab.quasistatic.solve_load_distribution`
become the dynamic equivalent rolling-element loads of each raceway,

    Q_e = (sum_j Q_j^w / Z)^(1/w),  w = 3 on the rotating ring, 10/3 on the stationary ring,

so that L10r = [(Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3)]^(-9/10) million revolutions and
P_ref = C / L10r^(1/3). For a zero-clearance bearing under a radial load the ideal
distribution (Stribeck's half-zone) gives Q_ei = J_1 Q_max, Q_ee = J_2 Q_max and
L10r = (C/F_r)^3 again (0.407 = Z J_r/J_1, 0.389 = Z J_r/J_2 at epsilon = 0.5); the solver's
discrete ball set reproduces this within a few per cent (tests/unit/test_life.py).

Sources: two versions of a Python ISO/TS 16281 implementation and the bb_core Rust solver
(ISO 16281:2025 section 5.2), see :mod:`bearinglab.ratings.tables`.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from ..ratings import tables as T


def conformity_ratio(gamma: float, inner_groove_factor: float, outer_groove_factor: float) -> float:
    """T = 1.044 ((1-g)/(1+g))^1.72 (f_i (2 f_o - 1) / (f_o (2 f_i - 1)))^0.41 of ISO/TS
    16281 (r = f D_w): the ratio of the inner to the outer contact rating, times J_2/J_1.

    Parameters
    ----------
    gamma : float
        D_w cos(alpha) / D_pw [-].
    inner_groove_factor, outer_groove_factor : float
        f_i, f_o (> 0.5) [-].

    Examples
    --------
    >>> round(conformity_ratio(0.2, 0.52, 0.52), 4)
    0.5198
    """
    if not 0.0 <= gamma < 1.0:
        raise InputError("gamma", gamma, "a value in [0, 1)")
    for name, f in (
        ("inner_groove_factor", inner_groove_factor),
        ("outer_groove_factor", outer_groove_factor),
    ):
        if not f > 0.5:
            raise InputError(name, f, "a value > 0.5")
    groove = (
        inner_groove_factor
        * (2.0 * outer_groove_factor - 1.0)
        / (outer_groove_factor * (2.0 * inner_groove_factor - 1.0))
    )
    return T.QC_RATIO * ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * groove**0.41


def contact_ratings(bearing: BallBearing, dynamic_rating: float) -> tuple[float, float]:
    """Basic dynamic load ratings of a single inner and outer contact (Q_ci, Q_ce) [N].

    Parameters
    ----------
    bearing : BallBearing
        Geometry of a single-row radial or angular-contact ball bearing.
    dynamic_rating : float
        The bearing's basic dynamic load rating C (ISO 281) [N].

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3,
    ...                 outer_groove_factor=0.53)
    >>> tuple(round(q) for q in contact_ratings(b, 14000.0))
    (4021, 6991)
    """
    if bearing.is_thrust:
        raise InputError(
            "bearing_type",
            bearing.bearing_type,
            "a radial or angular-contact ball bearing",
            "the ISO/TS 16281 thrust forms are not implemented",
        )
    if not (math.isfinite(dynamic_rating) and dynamic_rating > 0):
        raise InputError("dynamic_rating", dynamic_rating, "a rating > 0 [N]")
    cos_a = math.cos(bearing.contact_angle)
    gamma = bearing.ball_diameter * cos_a / bearing.pitch_diameter
    t = conformity_ratio(gamma, bearing.inner_groove_factor, bearing.outer_groove_factor)
    base = dynamic_rating / (bearing.ball_count * cos_a)
    q_ci = base / T.QC_INNER * (1.0 + t ** (10.0 / 3.0)) ** 0.3
    q_ce = base / T.QC_OUTER * (1.0 + t ** (-10.0 / 3.0)) ** 0.3
    return q_ci, q_ce


def equivalent_ball_load(loads, exponent: float) -> float:
    """Q_e = (sum_j Q_j^w / Z)^(1/w) over all Z balls (unloaded balls count as 0) [N].

    Parameters
    ----------
    loads : array (Z,)
        Contact loads of one raceway [N].
    exponent : float
        w: 3 for the rotating ring, 10/3 for the stationary ring [-].

    Examples
    --------
    >>> round(equivalent_ball_load([100.0] * 8, 3.0), 9)
    100.0
    >>> round(equivalent_ball_load([0, 100.0], 3.0), 3)
    79.37
    """
    q = np.clip(np.asarray(loads, dtype=float), 0.0, None)
    if q.ndim != 1 or q.size == 0 or not np.all(np.isfinite(q)):
        raise InputError("loads", loads, "a non-empty list of finite contact loads [N]")
    return float(np.mean(q**exponent) ** (1.0 / exponent))


def reference_life(
    inner_rating: float, outer_rating: float, inner_equivalent: float, outer_equivalent: float
) -> float:
    """L10r = [(Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3)]^(-9/10) [million revolutions].

    Parameters
    ----------
    inner_rating, outer_rating : float
        Q_ci, Q_ce [N].
    inner_equivalent, outer_equivalent : float
        Q_ei, Q_ee [N]; at least one > 0.

    Examples
    --------
    >>> round(reference_life(1000.0, 2000.0, 100.0, 100.0), 1)
    918.4
    """
    terms = [
        (q_e / q_c) ** (10.0 / 3.0)
        for q_c, q_e in ((inner_rating, inner_equivalent), (outer_rating, outer_equivalent))
    ]
    total = sum(terms)
    if not (math.isfinite(total) and total > 0):
        raise InputError(
            "equivalent ball loads",
            (inner_equivalent, outer_equivalent),
            "at least one loaded raceway",
            "an unloaded bearing has no life",
        )
    return total**-0.9


def reference_rating_life(
    bearing: BallBearing,
    condition: OperatingCondition,
    dynamic_rating: float,
    *,
    rotating: str = "inner",
) -> dict:
    """ISO/TS 16281 basic reference rating life from the solved load distribution.

    Parameters
    ----------
    bearing : BallBearing
        Geometry, including clearance (P_d < 0: preload) and groove factors.
    condition : OperatingCondition
        Loads, moment or misalignments, speed.
    dynamic_rating : float
        C of ISO 281 [N].
    rotating : {"inner", "outer"}
        The rotating ring.

    Returns
    -------
    dict
        ``l10r`` [million revolutions], ``reference_load`` P_ref [N], ``inner_rating``,
        ``outer_rating`` (Q_ci, Q_ce), ``inner_equivalent``, ``outer_equivalent``
        (Q_ei, Q_ee) [N], ``inner_loads``, ``outer_loads`` (per ball, summed over the
        contacts of each raceway) [N], ``rotating``, ``warnings``.
    """
    from ..quasistatic import solve_load_distribution

    if rotating not in ("inner", "outer"):
        raise InputError("rotating", rotating, "'inner' or 'outer'")
    q_ci, q_ce = contact_ratings(bearing, dynamic_rating)
    result = solve_load_distribution(bearing, condition)
    inner = result.load[:, result.ring == 0].sum(axis=1)
    outer = result.load[:, result.ring == 1].sum(axis=1)
    w_inner, w_outer = (
        (T.ROTATING_EXPONENT, T.STATIONARY_EXPONENT)
        if rotating == "inner"
        else (T.STATIONARY_EXPONENT, T.ROTATING_EXPONENT)
    )
    q_ei = equivalent_ball_load(inner, w_inner)
    q_ee = equivalent_ball_load(outer, w_outer)
    l10r = reference_life(q_ci, q_ce, q_ei, q_ee)
    warnings = list(result.warnings)
    if rotating == "outer" and condition.shaft_speed > 0:
        warnings.append(
            "the load distribution takes the ball centrifugal force at the cage "
            "speed of a rotating inner ring"
        )
    return {
        "l10r": l10r,
        "reference_load": dynamic_rating / l10r ** (1.0 / 3.0),
        "inner_rating": q_ci,
        "outer_rating": q_ce,
        "inner_equivalent": q_ei,
        "outer_equivalent": q_ee,
        "inner_loads": inner,
        "outer_loads": outer,
        "rotating": rotating,
        "warnings": warnings,
    }
