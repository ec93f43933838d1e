"""Basic load ratings of ball bearings: dynamic C (ISO 281:2007 section 6.1), static C_0
(ISO 76:2006) and the fatigue load limit C_u (ISO 281 Annex B, simplified method).

Layer 1 holds the pure functions (table factors and the rating formulas, SI in and out);
:func:`load_ratings` applies them to a :class:`~bearinglab.geometry.BallBearing` and
returns a :class:`LoadRatings` with the factors used and what the user must know.

Equations (lengths of the standard in mm, forces in N; the functions take metres):

- radial and angular contact, D_w <= 25.4 mm: C_r = b_m f_c (i cos a)^0.7 Z^(2/3) D_w^1.8,
  above: C_r = 3.647 b_m f_c (i cos a)^0.7 Z^(2/3) D_w^1.4; thrust, a = 90 deg:
  C_a = b_m f_c Z^(2/3) D_w^1.8 (3.647 ... D_w^1.4 above 25.4 mm); b_m = 1.3;
- f_c from ISO 281 Tables 2 / 4 by gamma = D_w cos(a) / D_pw, interpolated linearly;
- C_0r = f_0 i Z D_w^2 cos a, C_0a = f_0 Z D_w^2 (a = 90 deg), f_0 from ISO 76 Table 1;
- C_u = C_0 / 22, times (100 / D_pw)^0.5 for D_pw > 100 mm.

Sources and checks of every coefficient: :mod:`bearinglab.ratings.tables` and
docs/capabilities/life.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError, positive_number
from ..geometry import BallBearing
from . import tables as T

_MM = 1e-3

#: Bearing types these ratings apply to.
RATED_TYPES = ("radial_ball", "angular_contact_ball", "thrust_ball")


def _table(name: str, gamma: float, grid: np.ndarray, values: np.ndarray, what: str) -> float:
    if not (isinstance(gamma, (int, float, np.floating)) and math.isfinite(gamma)):
        raise InputError(name, gamma, "a finite ratio")
    low, high = float(grid[0]), float(grid[-1])
    if not (low - 1e-12 <= gamma <= high + 1e-12):
        raise InputError(
            name,
            gamma,
            f"a value in [{low:g}, {high:g}]",
            f"{what} gives no value outside; it is not extrapolated",
        )
    return float(np.interp(gamma, grid, values))


def fc_factor(gamma: float, thrust: bool = False) -> float:
    """Factor f_c of ISO 281:2007 Table 2 (radial / angular contact) or Table 4
    (thrust, contact angle 90 deg), interpolated linearly as the standard allows.

    Parameters
    ----------
    gamma : float
        D_w cos(alpha) / D_pw (D_w / D_pw for thrust bearings) [-].
    thrust : bool
        Use the thrust-bearing (alpha = 90 deg) column [-].

    Returns
    -------
    float
        f_c for D_w in mm and C in N [N/mm^1.8].

    Examples
    --------
    >>> fc_factor(0.19), round(fc_factor(0.2034), 3)
    (60.0, 59.866)
    """
    if thrust:
        return _table("gamma", gamma, T.FC_THRUST_GAMMA, T.FC_THRUST_90, "ISO 281 Table 4")
    return _table("gamma", gamma, T.FC_GAMMA, T.FC_RADIAL, "ISO 281 Table 2")


def f0_factor(gamma: float, thrust: bool = False) -> float:
    """Factor f_0 of ISO 76:2006 Table 1 (radial and angular-contact groove ball bearings,
    or thrust ball bearings), interpolated linearly.

    Parameters
    ----------
    gamma : float
        D_w cos(alpha) / D_pw [-].
    thrust : bool
        Use the thrust ball bearing column [-].

    Returns
    -------
    float
        f_0 for D_w in mm and C_0 in N [N/mm^2].

    Examples
    --------
    >>> f0_factor(0.09), f0_factor(0.095)
    (16.5, 16.45)
    """
    if thrust:
        return _table("gamma", gamma, T.F0_THRUST_GAMMA, T.F0_THRUST, "ISO 76 Table 1")
    return _table("gamma", gamma, T.F0_GAMMA, T.F0_RADIAL, "ISO 76 Table 1")


def _check_set(ball_count, ball_diameter, pitch_diameter, contact_angle, rows) -> bool:
    """Check one set of rating inputs; True for a thrust ball bearing (alpha = 90 deg, which
    has a single row)."""
    if (
        isinstance(ball_count, bool)
        or not isinstance(ball_count, (int, np.integer))
        or ball_count < 3
    ):
        raise InputError("ball_count", ball_count, "an integer >= 3")
    for name, value in (("ball_diameter", ball_diameter), ("pitch_diameter", pitch_diameter)):
        if not (
            isinstance(value, (int, float, np.floating)) and math.isfinite(value) and value > 0
        ):
            raise InputError(name, value, "a length > 0 [m]")
    if pitch_diameter <= ball_diameter:
        raise InputError(
            "pitch_diameter", pitch_diameter, f"more than the ball diameter {ball_diameter:.6g} m"
        )
    if not (
        isinstance(contact_angle, (int, float, np.floating))
        and 0.0 <= contact_angle <= 0.5 * math.pi
    ):
        raise InputError("contact_angle", contact_angle, "an angle in [0, 90] degrees")
    if isinstance(rows, bool) or not isinstance(rows, (int, np.integer)) or rows < 1:
        raise InputError("rows", rows, "an integer >= 1")
    thrust = math.isclose(contact_angle, 0.5 * math.pi, abs_tol=1e-12)
    if thrust and rows != 1:
        raise InputError(
            "rows",
            rows,
            "1 for a thrust ball bearing",
            "multi-row thrust ratings are not implemented",
        )
    return thrust


def dynamic_load_rating(
    ball_count: int,
    ball_diameter: float,
    pitch_diameter: float,
    contact_angle: float = 0.0,
    rows: int = 1,
) -> float:
    """Basic dynamic load rating C of a ball bearing, ISO 281:2007 section 6.1 [N].

    Radial and angular-contact bearings (contact angle below 90 deg) get the radial rating
    C_r (Table 2); a contact angle of exactly 90 deg gives the thrust rating C_a of a thrust
    ball bearing (Table 4, single stored copy -- see :mod:`bearinglab.ratings.tables`).

    Parameters
    ----------
    ball_count : int
        Balls per row Z [-].
    ball_diameter : float
        D_w [m].
    pitch_diameter : float
        D_pw [m].
    contact_angle : float
        Nominal contact angle alpha [rad].
    rows : int
        Rows of balls i [-].

    Returns
    -------
    float
        C_r or C_a [N].

    Examples
    --------
    >>> round(dynamic_load_rating(9, 7.94004e-3, 39.0398e-3))  # SKF 6205 (CWRU), ISO 281
    14027
    """
    thrust = _check_set(ball_count, ball_diameter, pitch_diameter, contact_angle, rows)
    d_w = ball_diameter / _MM
    if thrust:
        gamma = ball_diameter / pitch_diameter
        front = T.B_M_BALL * fc_factor(gamma, thrust=True) * ball_count ** (2.0 / 3.0)
    else:
        gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
        front = (
            T.B_M_BALL
            * fc_factor(gamma)
            * (rows * math.cos(contact_angle)) ** 0.7
            * ball_count ** (2.0 / 3.0)
        )
    if d_w <= T.LARGE_BALL_MM:
        return front * d_w**1.8
    return T.LARGE_BALL_COEFFICIENT * front * d_w**1.4


def static_load_rating(
    ball_count: int,
    ball_diameter: float,
    pitch_diameter: float,
    contact_angle: float = 0.0,
    rows: int = 1,
) -> float:
    """Basic static load rating C_0 of a ball bearing, ISO 76:2006 [N].

    C_0r = f_0 i Z D_w^2 cos(alpha) for radial and angular-contact bearings; for a
    thrust ball bearing (alpha = 90 deg) C_0a = f_0 Z D_w^2 with the thrust column of f_0.
    Both are the loads at which the most loaded contact reaches 4200 MPa.

    Parameters
    ----------
    ball_count, ball_diameter, pitch_diameter, contact_angle, rows
        The ball set, as in :func:`dynamic_load_rating`.

    Returns
    -------
    float
        C_0r or C_0a [N].

    Examples
    --------
    >>> round(static_load_rating(8, 7.92e-3, 34.55e-3))  # XJTU-SY LDK UER204
    6635
    """
    thrust = _check_set(ball_count, ball_diameter, pitch_diameter, contact_angle, rows)
    d_w = ball_diameter / _MM
    if thrust:
        return f0_factor(ball_diameter / pitch_diameter, thrust=True) * ball_count * d_w**2
    gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
    return f0_factor(gamma) * rows * ball_count * d_w**2 * math.cos(contact_angle)


def fatigue_load_limit(static_rating: float, pitch_diameter: float) -> float:
    """Fatigue load limit C_u of a ball bearing, simplified method of ISO 281 Annex B [N]:
    C_0 / 22, times (100 mm / D_pw)^0.5 when D_pw > 100 mm.

    Parameters
    ----------
    static_rating : float
        C_0 [N].
    pitch_diameter : float
        D_pw [m].

    Examples
    --------
    >>> round(fatigue_load_limit(22000.0, 0.05)), round(fatigue_load_limit(22000.0, 0.4))
    (1000, 500)
    """
    for name, value in (("static_rating", static_rating), ("pitch_diameter", pitch_diameter)):
        if not (
            isinstance(value, (int, float, np.floating)) and math.isfinite(value) and value > 0
        ):
            raise InputError(name, value, "a value > 0")
    c_u = static_rating / T.CU_DIVISOR
    d_pw = pitch_diameter / _MM
    if d_pw > T.CU_SIZE_MM:
        c_u *= math.sqrt(T.CU_SIZE_MM / d_pw)
    return c_u


#: A given rating more than this factor away from the computed one is flagged [-]. Makers'
#: ratings differ from ISO 281's by percents (SKF Explorer: +4-5 %, docs/capabilities/
#: life.md), better steels by tens of percents; a factor of 2 is another bearing, or a
#: rating typed in the wrong unit.
GIVEN_RATING_FACTOR = 2.0
#: How each rating is computed when it is not given.
DYNAMIC_SOURCE = "ISO 281:2007 from the internal geometry"
STATIC_SOURCE = "ISO 76:2006 from the internal geometry"
FATIGUE_SOURCE = "ISO 281 Annex B (simplified) from C0"
ROLLER_FATIGUE_SOURCE = "ISO 281 Annex B (simplified, roller bearings: C0/8.2) from C0"


@dataclass(frozen=True)
class LoadRatings:
    """The load ratings of one bearing and the factors they came from.

    Attributes
    ----------
    dynamic : float
        Basic dynamic load rating C (C_r, or C_a for a thrust bearing) [N].
    static : float
        Basic static load rating C_0 [N].
    fatigue_limit : float
        Fatigue load limit C_u [N].
    fc, f0 : float or None
        Table factors used [N/mm^1.8, N/mm^2]; None when both ratings were given and the
        geometry has no ISO rating.
    gamma : float or None
        D_w cos(alpha) / D_pw [-].
    thrust : bool
        Thrust (axial) ratings.
    warnings : tuple of str
        What limits the ratings (groove radii beyond ISO's, single-source table).
    dynamic_source, static_source, fatigue_limit_source : str
        Where C, C_0 and C_u come from: computed (how), or ``"given"`` with the value the
        geometry would give [-].
    """

    dynamic: float
    static: float
    fatigue_limit: float
    fc: float | None
    f0: float | None
    gamma: float | None
    thrust: bool = False
    warnings: tuple[str, ...] = field(default=())
    dynamic_source: str = DYNAMIC_SOURCE
    static_source: str = STATIC_SOURCE
    fatigue_limit_source: str = FATIGUE_SOURCE
    rating_factor: float = T.B_M_BALL

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units."""
        return {
            "dynamic_rating_n": self.dynamic,
            "dynamic_rating_source": self.dynamic_source,
            "static_rating_n": self.static,
            "static_rating_source": self.static_source,
            "fatigue_load_limit_n": self.fatigue_limit,
            "fatigue_load_limit_source": self.fatigue_limit_source,
            "fc": self.fc,
            "f0": self.f0,
            "gamma": self.gamma,
            "rating_kind": "axial" if self.thrust else "radial",
            "rating_factor_bm": self.rating_factor,
        }


def _given(name: str, value) -> float | None:
    if value is None:
        return None
    return positive_number(name, value, "a rating > 0 [N]")


def load_ratings(
    bearing: BallBearing,
    *,
    dynamic_load_rating: float | None = None,
    static_load_rating: float | None = None,
) -> LoadRatings:
    """C, C_0 and C_u of a single-row ball bearing from its internal geometry, or as given.

    Deep-groove and angular-contact bearings get radial ratings; a thrust ball bearing
    with a 90 deg contact angle gets axial ratings. The f_c values hold for groove radii
    r_i <= 0.52 D_w and r_e <= 0.53 D_w (the conformity ISO 281 assumes); a bearing with
    looser grooves keeps the table value and a warning, because the correction ISO 281
    asks for is not verified here (docs/capabilities/life.md).

    A rating given (the maker's, say) replaces the computed one, and says so with the
    value the geometry gives beside it; C_u then follows from the given C_0. With both
    given, a geometry that ISO 281/76 cannot rate is no obstacle (its factors are None).

    Parameters
    ----------
    bearing : BallBearing
        Geometry (ball_count, ball_diameter, pitch_diameter, contact_angle, groove
        factors, bearing_type).
    dynamic_load_rating, static_load_rating : float or None
        C and C_0 given [N].

    Returns
    -------
    LoadRatings

    Raises
    ------
    InputError
        Four-point or other bearing types, a thrust bearing whose contact angle is not
        90 deg, or a gamma outside the ISO tables (unless both ratings are given); a given
        rating that is not > 0.

    Examples
    --------
    >>> from bearinglab.catalog import bearing_from_designation
    >>> r = load_ratings(bearing_from_designation("6203")[0])
    >>> round(r.dynamic), round(r.static)
    (9548, 4757)
    >>> r = load_ratings(bearing_from_designation("6203")[0], static_load_rating=4750.0)
    >>> r.static_source, round(r.fatigue_limit, 1)
    ('given (ISO 76:2006 from the internal geometry: 4757 N)', 215.9)
    """
    c = _given("dynamic_load_rating", dynamic_load_rating)
    c0 = _given("static_load_rating", static_load_rating)
    try:
        computed = _computed_ratings(bearing)
    except InputError:
        if c is None or c0 is None:
            raise
        computed = None
    if c is None and c0 is None:
        return computed
    # the computed warnings all concern f_c, so C: moot when C is given
    warnings = () if computed is None or c is not None else computed.warnings
    if computed is None:
        warnings = ("ISO 281/76 cannot rate this geometry; the given C and C0 are used",)
        thrust = bearing.is_thrust
        fc = f0 = gamma = None
    else:
        thrust, fc, f0, gamma = computed.thrust, computed.fc, computed.f0, computed.gamma

    def source(given, value, how):
        if given is None:
            return value, how
        if computed is None:
            return given, "given"
        return given, f"given ({how}: {value:.0f} N)"

    if computed is not None:
        warnings += _far_from_computed("C", c, computed.dynamic, "ISO 281")
        warnings += _far_from_computed("C0", c0, computed.static, "ISO 76")

    dynamic, dynamic_source = source(c, getattr(computed, "dynamic", None), DYNAMIC_SOURCE)
    static, static_source = source(c0, getattr(computed, "static", None), STATIC_SOURCE)
    roller = getattr(bearing, "rolling_element", "ball") == "roller"
    if roller:
        from .roller import roller_fatigue_load_limit

        limit = roller_fatigue_load_limit(static, bearing.pitch_diameter)
        limit_source = ROLLER_FATIGUE_SOURCE
    else:
        limit = fatigue_load_limit(static, bearing.pitch_diameter)
        limit_source = FATIGUE_SOURCE
    return LoadRatings(
        dynamic=dynamic,
        static=static,
        fatigue_limit=limit,
        fc=fc,
        f0=f0,
        gamma=gamma,
        thrust=thrust,
        warnings=warnings,
        dynamic_source=dynamic_source,
        static_source=static_source,
        fatigue_limit_source=limit_source + (" (given)" if c0 is not None else ""),
        rating_factor=computed.rating_factor if computed is not None else T.B_M_BALL,
    )


def _far_from_computed(name: str, given, value: float, standard: str) -> tuple[str, ...]:
    """A warning when the ``given`` rating [N] is more than :data:`GIVEN_RATING_FACTOR`
    away from the ``value`` computed from the geometry [N], in kN as catalogues print them."""
    if given is None or 1.0 / GIVEN_RATING_FACTOR <= given / value <= GIVEN_RATING_FACTOR:
        return ()
    return (
        f"the given {name} = {given * 1e-3:.4g} kN is {given / value:.3g} times {standard}'s "
        f"{value * 1e-3:.4g} kN for this geometry: beyond a factor of "
        f"{GIVEN_RATING_FACTOR:g}, check the value, its unit (kN) and the bearing",
    )


def _roller_ratings(bearing) -> LoadRatings:
    """C, C_0 and C_u of a roller bearing from its internal geometry (ISO 281, ISO 76;
    :mod:`bearinglab.ratings.roller`)."""
    from . import roller as R

    btype = bearing.bearing_type
    if btype not in R.B_M_ROLLER:
        raise InputError(
            "bearing_type",
            btype,
            "one of " + ", ".join(R.B_M_ROLLER),
            "ISO 281/76 ratings of this type are not implemented",
        )
    args = (
        int(bearing.roller_count),
        bearing.roller_diameter,
        bearing.roller_length,
        bearing.pitch_diameter,
        bearing.contact_angle,
        int(bearing.rows),
    )
    b_m = R.B_M_ROLLER[btype]
    dynamic = R.roller_dynamic_load_rating(*args, rating_factor=b_m)
    static = R.roller_static_load_rating(*args)
    gamma = bearing.gamma
    warnings = ()
    if btype == "needle_roller":
        warnings = (
            "needle roller bearing rated with b_m = 1.1 (machined rings; ISO 281 "
            "gives 1.0 for drawn cups)",
        )
    return LoadRatings(
        dynamic=dynamic,
        static=static,
        fatigue_limit=R.roller_fatigue_load_limit(static, bearing.pitch_diameter),
        fc=R.roller_fc_factor(gamma),
        f0=R.F0_ROLLER,
        gamma=gamma,
        thrust=False,
        warnings=warnings,
        dynamic_source=DYNAMIC_SOURCE,
        static_source=STATIC_SOURCE,
        fatigue_limit_source=ROLLER_FATIGUE_SOURCE,
        rating_factor=b_m,
    )


def _computed_ratings(bearing: BallBearing) -> LoadRatings:
    """C, C_0 and C_u from the internal geometry (ISO 281, ISO 76)."""
    if getattr(bearing, "rolling_element", "ball") == "roller":
        return _roller_ratings(bearing)
    btype = bearing.bearing_type
    if btype not in RATED_TYPES:
        raise InputError(
            "bearing_type",
            btype,
            "one of " + ", ".join(RATED_TYPES),
            "ISO 281/76 ratings of this type are not implemented",
        )
    alpha = bearing.contact_angle
    thrust = bearing.is_thrust
    if thrust and not math.isclose(alpha, 0.5 * math.pi, abs_tol=1e-9):
        raise InputError(
            "contact_angle",
            alpha,
            "90 degrees for a thrust ball bearing",
            "ISO 281 thrust factors for other angles are not implemented",
        )
    if not thrust and alpha >= 0.5 * math.pi - 1e-9:
        raise InputError("contact_angle", alpha, "less than 90 degrees for a radial bearing")
    if thrust:
        alpha = 0.5 * math.pi
    args = (bearing.ball_count, bearing.ball_diameter, bearing.pitch_diameter, alpha)
    dynamic = dynamic_load_rating(*args)
    static = static_load_rating(*args)
    gamma = (
        bearing.ball_diameter / bearing.pitch_diameter
        if thrust
        else bearing.ball_diameter * math.cos(alpha) / bearing.pitch_diameter
    )
    warnings = []
    if thrust:
        warnings.append(
            "the ISO 281 f_c table of thrust ball bearings comes from a single "
            "stored copy (its shape is checked, its values are not cross-checked)"
        )
    elif (
        bearing.inner_groove_factor > T.FC_MAX_INNER_GROOVE_FACTOR + 1e-12
        or bearing.outer_groove_factor > T.FC_MAX_OUTER_GROOVE_FACTOR + 1e-12
    ):
        warnings.append(
            f"groove factors f_i = {bearing.inner_groove_factor:g}, f_o = "
            f"{bearing.outer_groove_factor:g} exceed the r_i <= 0.52 D_w, r_e <= 0.53 D_w "
            "for which ISO 281 gives f_c: the dynamic rating is overestimated (no "
            "correction applied)"
        )
    return LoadRatings(
        dynamic=dynamic,
        static=static,
        fatigue_limit=fatigue_load_limit(static, bearing.pitch_diameter),
        fc=fc_factor(gamma, thrust=thrust),
        f0=f0_factor(gamma, thrust=thrust),
        gamma=gamma,
        thrust=thrust,
        warnings=tuple(warnings),
    )
