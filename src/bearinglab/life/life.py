"""Rating life of ball bearings: basic L10 = (C/P)^3, modified L_nm = a_1 a_ISO L10
(ISO 281:2007 sections 7 and 9), or the reference life of ISO/TS 16281 from the internal
load distribution (:mod:`bearinglab.life.iso16281`).

Layer 1: :func:`reliability_factor` (a_1, Table 12), :func:`rated_viscosity` (nu_1),
:func:`contamination_factor` (e_C, Table 13 guide values), :func:`life_modification_factor`
(a_ISO of radial ball bearings). Layer 3: :func:`rating_life` returns a
:class:`LifeResult`.

a_ISO = 0.1 [1 - (2.5671 - c / kappa^p)^0.83 (e_C C_u / P)^(1/3)]^-9.3, capped at 50, with
(c, p) = (2.2649, 0.054381) for 0.1 <= kappa < 0.4, (1.9987, 0.19087) for 0.4 <= kappa < 1
and (1.9987, 0.071739) for 1 <= kappa <= 4; kappa = nu / nu_1 above 4 counts as 4, below
0.1 the standard gives no value. nu_1 = 45000 n^-0.83 D_pw^-0.5 (n < 1000 r/min) or
4500 n^-0.5 D_pw^-0.5 [mm^2/s, r/min, mm]. Sources: :mod:`bearinglab.ratings.tables`.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError, positive_number
from ..geometry import BallBearing
from ..operating import OperatingCondition, speed_error
from ..ratings import tables as T
from ..ratings.basic import load_ratings
from ..ratings.equivalent import equivalent_dynamic_load, equivalent_static_load
from ..units import rad_s_to_rpm, rpm_to_rad_s  # noqa: F401 - rpm_to_rad_s: doctests
from .result import LifeResult

METHODS = ("iso281", "iso16281")
_MM = 1e-3
_CONTAMINATION_ALLOWED = "a number in [0, 1] or one of " + ", ".join(
    [*T.CONTAMINATION_LEVELS, *T.CONTAMINATION_ALIASES]
)


class ViscosityTooLow(InputError):
    """The viscosity gives kappa = nu/nu_1 below ISO 281's 0.1, where a_ISO is not defined;
    ``minimum`` is the least viscosity allowed at this speed and size [m^2/s] (so that an
    interface can state it in its own unit)."""

    def __init__(self, viscosity: float, minimum: float, kappa: float) -> None:
        super().__init__(
            "viscosity",
            viscosity,
            f"at least {minimum:.3g} m^2/s at this speed and size",
            f"kappa = nu/nu_1 = {kappa:.3g} is below 0.1, where ISO 281 gives no a_ISO",
        )
        self.minimum = minimum


def reliability_factor(reliability_percent: float) -> float:
    """Life modification factor for reliability a_1, ISO 281:2007 Table 12, interpolated
    linearly between the tabulated reliabilities 90 ... 99.95 %.

    Parameters
    ----------
    reliability_percent : float
        Reliability (probability of survival) [%].

    Examples
    --------
    >>> reliability_factor(90), reliability_factor(99), reliability_factor(99.95)
    (1.0, 0.25, 0.077)
    """
    r = reliability_percent
    if not (
        isinstance(r, (int, float, np.floating))
        and math.isfinite(r)
        and T.A1_RELIABILITY[0] <= r <= T.A1_RELIABILITY[-1]
    ):
        raise InputError(
            "reliability_percent", r, "a reliability in [90, 99.95] %", "ISO 281 Table 12"
        )
    return float(np.interp(r, T.A1_RELIABILITY, T.A1_FACTOR))


def rated_viscosity(shaft_speed: float, pitch_diameter: float) -> float:
    """Rated (reference) kinematic viscosity nu_1 of ISO 281:2007 [m^2/s]:
    45000 n^-0.83 D_pw^-0.5 for n < 1000 r/min, else 4500 n^-0.5 D_pw^-0.5 (mm^2/s with n
    in r/min and D_pw in mm).

    Parameters
    ----------
    shaft_speed : float
        Speed of the rotating ring [rad/s], > 0.
    pitch_diameter : float
        D_pw [m].

    Examples
    --------
    >>> round(rated_viscosity(rpm_to_rad_s(3000), 0.039) * 1e6, 2)   # mm^2/s
    13.16
    """
    for name, value in (("shaft_speed", shaft_speed), ("pitch_diameter", pitch_diameter)):
        if not (
            isinstance(value, (int, float, np.floating)) and math.isfinite(value) and value > 0
        ):
            raise InputError(name, value, "a value > 0")
    n = rad_s_to_rpm(shaft_speed)
    d_pw = pitch_diameter / _MM
    if n < T.NU1_SWITCH_RPM:
        nu1 = 45000.0 * n**-0.83 * d_pw**-0.5
    else:
        nu1 = 4500.0 * n**-0.5 * d_pw**-0.5
    return nu1 * 1e-6


def contamination_factor(contamination, pitch_diameter: float) -> tuple[float, str]:
    """Contamination factor e_C: a number in [0, 1], or a level of ISO 281:2007 Table 13
    (extreme-cleanliness, high-cleanliness, normal-cleanliness, slight-contamination,
    typical-contamination, severe-contamination, very-severe-contamination; the
    contamination levels also by their first word: slight, typical, severe, very-severe),
    which gives the middle of the table's range for the bearing size (D_pw below or from
    100 mm). The cleanliness levels need their whole name: "extreme", "high" and "normal"
    alone are refused (extreme cleanliness is e_C = 1, not extreme contamination).

    Parameters
    ----------
    contamination : float or str
        e_C, or a level name [-].
    pitch_diameter : float
        D_pw [m].

    Returns
    -------
    tuple
        (e_C [-], description of where it came from).

    >>> contamination_factor("normal-cleanliness", 0.039)[0], contamination_factor(0.3, 0.039)[0]
    (0.55, 0.3)

    Raises
    ------
    InputError
        Named ``contamination``, for anything else; for "extreme", "high" or "normal" the
        hint names the level's new name ("'extreme' now reads 'extreme-cleanliness'").
    """
    if isinstance(contamination, str):
        key = contamination.strip().lower().replace("_", "-").replace(" ", "-")
        if key in T.CONTAMINATION_RETIRED:
            new = T.CONTAMINATION_RETIRED[key]
            raise InputError(
                "contamination", contamination, _CONTAMINATION_ALLOWED, f"'{key}' now reads '{new}'"
            )
        key = T.CONTAMINATION_ALIASES.get(key, key)
        if key not in T.CONTAMINATION_LEVELS:
            raise InputError("contamination", contamination, _CONTAMINATION_ALLOWED)
        large = pitch_diameter / _MM >= T.CONTAMINATION_SIZE_MM
        low, high = T.CONTAMINATION_LEVELS[key][1 if large else 0]
        where = (
            f"ISO 281 Table 13 '{key}', D_pw {'>=' if large else '<'} 100 mm: "
            f"{low:g}-{high:g}, middle used"
        )
        return 0.5 * (low + high), where
    if isinstance(contamination, bool) or not (
        isinstance(contamination, (int, float, np.floating))
        and math.isfinite(contamination)
        and 0.0 <= contamination <= 1.0
    ):
        raise InputError("contamination", contamination, _CONTAMINATION_ALLOWED)
    return float(contamination), "given"


def life_modification_factor(
    kappa: float,
    load_ratio: float,
    *,
    ep_additives: bool = False,
    contamination: float = 1.0,
    roller: bool = False,
) -> float:
    """Life modification factor a_ISO of radial ball (or roller) bearings, ISO 281:2007 [-].

    Balls: 0.1 [1 - (2.5671 - c/kappa^p)^0.83 (e_C C_u/P)^(1/3)]^-9.3; rollers:
    0.1 [1 - (1.5859 - c/kappa^p) (e_C C_u/P)^0.4]^-9.185 with (c, p) = (1.3993, 0.054381),
    (1.2348, 0.19087), (1.2348, 0.071739) in the three kappa bands
    (:data:`bearinglab.ratings.tables.A_ISO_ROLLER_BANDS`).

    Parameters
    ----------
    kappa : float
        Viscosity ratio nu / nu_1, >= 0.1 (values above 4 count as 4) [-].
    load_ratio : float
        e_C C_u / P, >= 0 [-].
    ep_additives : bool
        The lubricant has proven EP additives: for kappa < 1 and e_C >= 0.2, kappa = 1
        is used and a_ISO is limited to 3 (ISO 281 9.3.3.4 as quoted by bb_core).
    contamination : float
        e_C, needed only for the EP rule [-].
    roller : bool
        Radial roller bearings' constants [-].

    Returns
    -------
    float
        a_ISO in [0.1, 50].

    Examples
    --------
    >>> life_modification_factor(1.0, 0.0)
    0.1
    >>> round(life_modification_factor(2.0, 0.3), 3)
    41.752
    """
    if not (
        isinstance(kappa, (int, float, np.floating))
        and math.isfinite(kappa)
        and kappa >= T.KAPPA_MIN
    ):
        raise InputError(
            "kappa",
            kappa,
            f"a viscosity ratio >= {T.KAPPA_MIN}",
            "ISO 281 gives no a_ISO below 0.1",
        )
    positive_number("load_ratio", load_ratio, "e_C C_u / P, a finite value >= 0", zero=True)
    cap = T.A_ISO_CAP
    if ep_additives and kappa < 1.0 and contamination >= T.EP_KAPPA_EC_MIN:
        kappa, cap = 1.0, T.EP_A_ISO_CAP
    k = min(float(kappa), T.KAPPA_MAX)
    if roller:
        bands, base0, exponent, power, slope = (
            T.A_ISO_ROLLER_BANDS,
            T.A_ISO_ROLLER_BASE,
            T.A_ISO_ROLLER_EXPONENT,
            T.A_ISO_ROLLER_POWER,
            T.A_ISO_ROLLER_SLOPE,
        )
    else:
        bands, base0, exponent, power, slope = (
            T.A_ISO_BANDS,
            T.A_ISO_BASE,
            T.A_ISO_EXPONENT,
            1.0 / 3.0,
            T.A_ISO_SLOPE,
        )
    c, p = next((c, p) for low, c, p in reversed(bands) if k >= low)
    base = max(base0 - c / k**p, 0.0)  # 0 at kappa = 0.1 (rounding aside)
    bracket = 1.0 - base**exponent * load_ratio**power
    if bracket <= 0.0:
        return cap
    return float(min(0.1 * bracket**-slope, cap))


def basic_rating_life(
    dynamic_rating: float, equivalent_load: float, exponent: float = 3.0
) -> float:
    """Basic rating life L10 = (C/P)^p [million revolutions]: p = 3 for ball bearings,
    10/3 for roller bearings (ISO 281:2007 eq. 1).

    Parameters
    ----------
    dynamic_rating : float
        C [N].
    equivalent_load : float
        P > 0 [N].
    exponent : float
        p [-].

    Examples
    --------
    >>> basic_rating_life(14000.0, 1400.0)
    1000.0
    """
    for name, value in (("dynamic_rating", dynamic_rating), ("equivalent_load", equivalent_load)):
        if not (
            isinstance(value, (int, float, np.floating)) and math.isfinite(value) and value > 0
        ):
            raise InputError(name, value, "a load > 0 [N]")
    return float((dynamic_rating / equivalent_load) ** exponent)


def _check_condition(condition: OperatingCondition, method: str) -> None:
    if not isinstance(condition, OperatingCondition):
        raise InputError("condition", condition, "an OperatingCondition")
    if not condition.shaft_speed > 0:
        raise speed_error(
            condition.shaft_speed,
            "a speed > 0 rpm",
            "life in hours and the rated viscosity need it",
        )
    if method == "iso281" and (
        condition.moment is not None
        or any(condition.misalignment)
        or any(condition.outer_misalignment)
    ):
        raise InputError(
            "condition",
            "moment or misalignment",
            "none for method 'iso281' (use 'iso16281', which solves the load distribution)",
        )


def rating_life(
    bearing: BallBearing,
    condition: OperatingCondition,
    *,
    reliability_percent: float = 90.0,
    viscosity: float | None = None,
    contamination=None,
    method: str = "iso281",
    rotating: str = "inner",
    ep_additives: bool = False,
    dynamic_load_rating: float | None = None,
    static_load_rating: float | None = None,
    slices: int | None = None,
    edge_stress: bool = False,
) -> LifeResult:
    """Rating life of a single-row ball bearing (or a roller bearing), ISO 281:2007 or
    ISO/TS 16281.

    A roller bearing (``rolling_element`` "roller") has L10 = (C/P)^(10/3), the roller
    rows of ISO 281 Table 3 and a_ISO, and for ``iso16281`` the slice method
    (:func:`bearinglab.life.iso16281_roller.roller_reference_rating_life`,
    P_ref = C / L10r^(3/10)).

    ``iso281``: L10 = (C/P)^3 with P from Table 3 (normal clearance, rigid rings, no
    misalignment). ``iso16281``: the basic reference rating life L10r from the per-ball
    contact loads of :func:`bearinglab.quasistatic.solve_load_distribution` (so clearance,
    speed, moment and misalignment count), P_ref = C / L10r^(1/3) in place of P.
    With a ``viscosity`` the modified life a_1 a_ISO L10 follows. C and C_0 are ISO 281's
    and ISO 76's from the geometry unless given (the maker's, say): a given C serves both
    methods (ISO/TS 16281 splits it into the contact ratings Q_ci, Q_ce), a given C_0 sets
    s_0 and C_u (so a_ISO); the result says which were given
    (``ratings.dynamic_source``, ``static_source``).

    Parameters
    ----------
    bearing : BallBearing
        Geometry; deep-groove, angular-contact, or (``iso281`` only) thrust ball bearing.
    condition : OperatingCondition
        Loads on the inner ring and the speed of the rotating ring (> 0).
    reliability_percent : float
        90 ... 99.95 [%].
    viscosity : float, optional
        Operating kinematic viscosity of the lubricant [m^2/s].
    contamination : float or str, optional
        e_C or a Table 13 level; with a viscosity and no contamination, normal
        cleanliness is assumed (and said).
    method : {"iso281", "iso16281"}
    rotating : {"inner", "outer"}
        The rotating ring (``iso16281``: which ring's equivalent load has exponent 3).
    ep_additives : bool
        Apply ISO 281's EP-additive rule to a_ISO.
    dynamic_load_rating, static_load_rating : float, optional
        C and C_0 given [N] (see :func:`bearinglab.life.load_ratings`).
    slices : int, optional
        Roller bearings, ``iso16281``: slices per contact (None: 30) [-].
    edge_stress : bool
        Roller bearings, ``iso16281``: weight the slice loads by ISO/TS 16281's edge-stress
        factors of an unprofiled roller [-].

    Returns
    -------
    LifeResult

    Raises
    ------
    InputError
        Bad inputs: unsupported bearing type, no load, zero speed, kappa below 0.1
        (:class:`ViscosityTooLow`), a moment or misalignment with ``iso281``, a given
        rating not > 0, ...

    Examples
    --------
    >>> from bearinglab.catalog import bearing_from_designation
    >>> b, _ = bearing_from_designation("6205")
    >>> r = rating_life(b, OperatingCondition(radial_load=1400.0, shaft_speed=rpm_to_rad_s(1500)))
    >>> round(r.l10), round(r.l10_hours)
    (1006, 11176)
    """
    if method not in METHODS:
        raise InputError("method", method, "one of " + ", ".join(METHODS))
    if rotating not in ("inner", "outer"):
        raise InputError("rotating", rotating, "'inner' or 'outer'")
    _check_condition(condition, method)
    roller = getattr(bearing, "rolling_element", "ball") == "roller"
    if not roller:
        for name, value in (("slices", slices), ("edge_stress", edge_stress or None)):
            if value is not None:
                raise InputError(
                    name, value, "its default for a ball bearing", "roller bearings only"
                )
    a1 = reliability_factor(reliability_percent)
    ratings = load_ratings(
        bearing, dynamic_load_rating=dynamic_load_rating, static_load_rating=static_load_rating
    )
    warnings = list(ratings.warnings)
    radial, axial = condition.radial_load, condition.axial_load
    p, factors = equivalent_dynamic_load(bearing, radial, axial)
    if factors.clamped:
        warnings.append(
            "the relative axial load F_a/(Z D_w^2) is beyond ISO 281 Table 3: "
            "its last X, Y, e were used"
        )
    p0 = equivalent_static_load(bearing, radial, axial)
    reference = None
    iso281_p = None
    if method == "iso16281":
        if roller:
            from .iso16281_roller import roller_reference_rating_life

            ref = roller_reference_rating_life(
                bearing,
                condition,
                ratings.dynamic,
                rotating=rotating,
                slices=slices,
                edge_stress=edge_stress,
            )
        else:
            from .iso16281 import reference_rating_life

            ref = reference_rating_life(bearing, condition, ratings.dynamic, rotating=rotating)
        l10 = ref["l10r"]
        iso281_p, p = p, ref["reference_load"]
        reference = ref
        warnings.extend(ref["warnings"])
    else:
        l10 = basic_rating_life(ratings.dynamic, p, 10.0 / 3.0 if roller else 3.0)
    if ratings.static / p0 < 1.0:
        warnings.append(
            f"static safety factor s0 = {ratings.static / p0:.3g} < 1: the most "
            f"loaded contact exceeds {4000 if roller else 4200} MPa (ISO 76 permanent "
            "deformation)"
        )
    kwargs = {}
    if viscosity is not None:
        if not (
            isinstance(viscosity, (int, float, np.floating))
            and math.isfinite(viscosity)
            and viscosity > 0
        ):
            raise InputError("viscosity", viscosity, "a kinematic viscosity > 0 [m^2/s]")
        nu1 = rated_viscosity(condition.shaft_speed, bearing.pitch_diameter)
        kappa = viscosity / nu1
        if kappa < T.KAPPA_MIN:
            raise ViscosityTooLow(viscosity, T.KAPPA_MIN * nu1, kappa)
        if contamination is None:
            contamination = "normal-cleanliness"
            warnings.append(
                "contamination not given: normal cleanliness (ISO 281 Table 13) assumed"
            )
        e_c, e_source = contamination_factor(contamination, bearing.pitch_diameter)
        if bearing.is_thrust:
            warnings.append(
                "a_ISO of thrust ball bearings (ISO 281 uses 3 P_a there) is not "
                "implemented: no modified life"
            )
            a_iso = lnm = None
        else:
            a_iso = life_modification_factor(
                kappa,
                e_c * ratings.fatigue_limit / p,
                ep_additives=ep_additives,
                contamination=e_c,
                roller=roller,
            )
            lnm = a1 * a_iso * l10
            if a_iso >= T.A_ISO_CAP:
                warnings.append("a_ISO reached ISO 281's limit of 50")
        kwargs = {
            "viscosity": float(viscosity),
            "rated_viscosity": nu1,
            "kappa": kappa,
            "contamination": e_c,
            "contamination_source": e_source,
            "a_iso": a_iso,
            "lnm": lnm,
        }
    elif contamination is not None:
        contamination_factor(contamination, bearing.pitch_diameter)  # validate it anyway
        warnings.append("contamination given without a viscosity: a_ISO needs both")
    else:
        warnings.append("no viscosity given: kappa, a_ISO and the modified life are not computed")
    # inputs that this method or the missing viscosity leaves without effect
    unused = ("rotating",) if rotating == "outer" and method == "iso281" else ()
    unused += ("ep_additives",) if ep_additives and viscosity is None else ()
    return LifeResult(
        bearing=bearing,
        condition=condition,
        method=method,
        ratings=ratings,
        equivalent_load=float(p),
        factors=factors,
        static_equivalent_load=p0,
        l10=l10,
        reliability_percent=float(reliability_percent),
        a1=a1,
        iso281_equivalent_load=iso281_p,
        reference=reference,
        warnings=tuple(warnings),
        unused=unused,
        **kwargs,
    )
