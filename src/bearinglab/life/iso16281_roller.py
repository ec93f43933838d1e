"""Basic reference rating life of a roller bearing from its slice loads, ISO/TS 16281:2008.

The bearing's ISO 281 rating C is split into the basic dynamic load ratings of one roller's
contact on each raceway and then of one slice (lamina) of it (ISO/TS 16281 eqs. 47-57, as
in the stored implementations minzhun/ISO16281 ``RollerBearing.py`` and
shiva01910/BearingLifeCalculation16281 ``roller_bearing.py``):

    Q_ci = C / (lambda nu 0.378 Z cos a i^(7/9)) [1 + (1.038 r)^(9/2)]^(2/9),
    Q_ce = C / (lambda nu 0.364 Z cos a i^(7/9)) [1 + (1.038 r)^(-9/2)]^(2/9),
    r = ((1 - gamma)/(1 + gamma))^(143/108),  q_c = Q_c n_s^(-7/9),  lambda nu = 0.83,

the slice loads q_jk of :func:`bearinglab.quasistatic.solve_load_distribution` (so
clearance, tilt, misalignment, profile and speed count) become the dynamic equivalent
loads of each slice k on each raceway (eqs. 61-64),

    q_ke = (sum_j (f_k q_jk)^w / Z)^(1/w),  w = 4 on the rotating ring, 4.5 on the
    stationary ring,

and L10r = [sum_k ((q_kei/q_ci)^(9/2) + (q_kee/q_ce)^(9/2))]^(-8/9) million revolutions
(eq. 65), P_ref = C / L10r^(3/10). With two rows the sums run over both rows, each row
rated as one (C = i^(7/9) C_row). f_k = 1, or ISO/TS 16281's edge-stress factors of an
unprofiled roller (eq. 60, :func:`bearinglab.contact.line.edge_stress_factors`) when asked
for (``edge_stress``): they weight the end slice by 2.33 whatever n_s, so the life they
give depends on the slice count; they are an option, not the default.

Self-consistency: 0.378 = Z J_r/J_1 and 0.364 = Z J_r/J_2 of the line-contact load-zone
integrals at epsilon = 0.5 (Harris & Kotzalas 2007; J_r = 0.2453, J_1 = 0.6495 for the
rotating ring with exponent 4 x 10/9, J_2 = 0.6744 with 4.5 x 10/9), so an unprofiled,
aligned roller set without clearance at F_r = C lives lambda nu^(-4) = 2.11 million
revolutions: ISO 281's C carries the reduction lambda nu for edge stresses and uneven
loading that the slice ratings remove (tests/literature/test_roller_iso16281.py).
"""

from __future__ import annotations

import math

import numpy as np

from ..contact.line import edge_stress_factors
from ..errors import InputError
from ..operating import OperatingCondition

#: ISO/TS 16281 roller constants: lambda nu, the inner and outer load-zone ratios and the
#: conformity constant [-].
LAMBDA_NU = 0.83
QC_INNER_ROLLER, QC_OUTER_ROLLER, QC_CONFORMITY_ROLLER = 0.378, 0.364, 1.038
#: Exponents of the slice equivalent loads: 4 on the rotating ring, 4.5 on the stationary.
ROTATING_EXPONENT_ROLLER, STATIONARY_EXPONENT_ROLLER = 4.0, 4.5


def roller_contact_ratings(bearing, dynamic_rating: float) -> tuple[float, float]:
    """(Q_ci, Q_ce): basic dynamic load ratings of one roller's inner and outer contact
    (one row) [N].

    Parameters
    ----------
    bearing : RollerBearing
        Geometry (Z, D_we, D_pw, alpha, rows).
    dynamic_rating : float
        The bearing's C (ISO 281) [N].

    Examples
    --------
    >>> from bearinglab.roller_geometry import RollerBearing
    >>> b = RollerBearing(roller_count=14, roller_diameter=10e-3, roller_length=9.6e-3,
    ...                   pitch_diameter=65.01e-3)
    >>> [round(q) for q in roller_contact_ratings(b, 48446.0)]
    [11457, 17281]
    """
    if not (math.isfinite(dynamic_rating) and dynamic_rating > 0):
        raise InputError("dynamic_rating", dynamic_rating, "a rating > 0 [N]")
    cos_a = math.cos(bearing.contact_angle)
    gamma = bearing.roller_diameter * cos_a / bearing.pitch_diameter
    r = ((1.0 - gamma) / (1.0 + gamma)) ** (143.0 / 108.0)
    base = dynamic_rating / (LAMBDA_NU * bearing.roller_count * cos_a * bearing.rows ** (7 / 9))
    q_ci = base / QC_INNER_ROLLER * (1.0 + (QC_CONFORMITY_ROLLER * r) ** 4.5) ** (2.0 / 9.0)
    q_ce = base / QC_OUTER_ROLLER * (1.0 + (QC_CONFORMITY_ROLLER * r) ** -4.5) ** (2.0 / 9.0)
    return q_ci, q_ce


def slice_equivalent_loads(loads, exponent: float, factors=None) -> np.ndarray:
    """q_ke = (sum_j (f_k q_jk)^w / Z)^(1/w) of every slice k over the Z rollers of a row (n_s,)
    [N].

    Parameters
    ----------
    loads : array (Z, n_s)
        Slice loads of one raceway [N].
    exponent : float
        w: 4 on the rotating ring, 4.5 on the stationary ring [-].
    factors : array (n_s,) or None
        Edge-stress factors f_k (None: 1) [-].

    Examples
    --------
    >>> slice_equivalent_loads(np.full((4, 2), 10.0), 4.0).tolist()
    [10.0, 10.0]
    """
    q = np.clip(np.asarray(loads, float), 0.0, None)
    if factors is not None:
        q = q * np.asarray(factors, float)[None, :]
    return np.mean(q**exponent, axis=0) ** (1.0 / exponent)


def roller_reference_rating_life(
    bearing,
    condition: OperatingCondition,
    dynamic_rating: float,
    *,
    rotating: str = "inner",
    slices: int | None = None,
    edge_stress: bool = False,
    distribution=None,
) -> dict:
    """ISO/TS 16281 basic reference rating life of a roller bearing from its slice loads.

    Parameters
    ----------
    bearing : RollerBearing
        Geometry, clearance, profile.
    condition : OperatingCondition
        Loads, moment or misalignments, speed.
    dynamic_rating : float
        C of ISO 281 [N].
    rotating : {"inner", "outer"}
        The rotating ring [-].
    slices : int or None
        Slices per contact (None: the load distribution's default, 30) [-].
    edge_stress : bool
        Weight the slice loads by ISO/TS 16281's edge-stress factors f_k [-].
    distribution : RollerLoadDistribution or None
        A solved distribution of ``bearing`` under ``condition`` to use instead of solving
        [-].

    Returns
    -------
    dict
        ``l10r`` [million revolutions], ``reference_load`` P_ref [N], ``inner_rating``,
        ``outer_rating`` (Q_ci, Q_ce) [N], ``inner_equivalent``, ``outer_equivalent`` (the
        roller loads equivalent to the slice equivalents, sum_k q_ke, of the more loaded
        row) [N], ``inner_loads``, ``outer_loads`` (per roller) [N], ``rotating``,
        ``slices``, ``edge_stress``, ``warnings``.
    """
    from ..quasistatic import solve_load_distribution

    if rotating not in ("inner", "outer"):
        raise InputError("rotating", rotating, "'inner' or 'outer'")
    q_ci, q_ce = roller_contact_ratings(bearing, dynamic_rating)
    result = (
        distribution
        if distribution is not None
        else solve_load_distribution(bearing, condition, slices=slices)
    )
    n_s = result.slices
    q_ci_s, q_ce_s = q_ci * n_s ** (-7.0 / 9.0), q_ce * n_s ** (-7.0 / 9.0)
    factors = edge_stress_factors(n_s) if edge_stress else None
    w_in, w_out = (
        (ROTATING_EXPONENT_ROLLER, STATIONARY_EXPONENT_ROLLER)
        if rotating == "inner"
        else (STATIONARY_EXPONENT_ROLLER, ROTATING_EXPONENT_ROLLER)
    )
    total = 0.0
    equivalents = []
    for row in np.unique(result.roller_row):
        mine = result.roller_row == row
        q_ei = slice_equivalent_loads(result.inner_load[mine], w_in, factors)
        q_ee = slice_equivalent_loads(result.outer_load[mine], w_out, factors)
        total += float(np.sum((q_ei / q_ci_s) ** 4.5 + (q_ee / q_ce_s) ** 4.5))
        equivalents.append((float(q_ei.sum()), float(q_ee.sum())))
    if not (math.isfinite(total) and total > 0):
        raise InputError(
            "condition", "no load", "a loaded bearing", "an unloaded bearing has no life"
        )
    l10r = total ** (-8.0 / 9.0)
    heaviest = max(equivalents, key=lambda pair: pair[0] + pair[1])
    warnings = list(result.warnings)
    if rotating == "outer" and condition.shaft_speed > 0:
        warnings.append(
            "the load distribution takes the rollers' centrifugal force at the cage "
            "speed of a rotating inner ring"
        )
    return {
        "l10r": l10r,
        "reference_load": dynamic_rating / l10r**0.3,
        "inner_rating": q_ci,
        "outer_rating": q_ce,
        "inner_equivalent": heaviest[0],
        "outer_equivalent": heaviest[1],
        "inner_loads": result.inner_roller_load,
        "outer_loads": result.outer_roller_load,
        "rotating": rotating,
        "slices": n_s,
        "edge_stress": bool(edge_stress),
        "warnings": warnings,
    }
