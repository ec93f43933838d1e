"""Estimate the internal geometry of a ball bearing from its boundary dimensions.

Method: the design rules for single-row deep-groove ball bearings of the Chinese bearing
industry, "深沟球轴承设计方法" (Design method of deep-groove ball bearings), sections 2
and 3, Tables 1 and 2 (boundary dimensions per GB/T 273.3 = ISO 15; reproduced at
xiaomilidoc.com/p-10044630.html):

* ball diameter (sec. 2.1, Table 1): D_w = K_w (D - d), K_w from a range that depends on
  the diameter series and the bore (d <= 35 mm, 35 < d <= 120 mm, d > 120 mm); this module
  takes the middle of the range (the rules leave the choice inside it to the designer);
* pitch diameter (sec. 2.2): d_m = 0.5 (D + d);
* ball count (sec. 2.3, Table 2): Z = psi / (2 asin(D_w / d_m)) + 1 with the ball filling
  angle psi = 190 deg for diameter series 8, 9 and 0 ("8, 9, 1" in the old Chinese
  numbering, where 1 is ISO 0) and 186 deg for diameter series 2, 3, 4, rounded to a
  whole number;
* the real filling angle psi = 2 (Z - 1) asin(D_w / d_m) (sec. 2.6; the same relation is
  Harris & Kotzalas's assembly angle of a Conrad bearing) must lie between 180 deg and
  195 / 194 / 193 / 192 deg for diameter series 8-9-0 / 2 / 3 / 4; to keep it there the
  pitch diameter may be enlarged by up to 3 % (sec. 2.5.4), otherwise Z changes by one;
* groove radii (sec. 3.1, 3.2): R_i = 0.515 D_w, R_e = 0.525 D_w, so f_i = 0.515 and
  f_o = 0.525.

The K_w ranges agree with the bounds Gupta, Tiwari & Nair (Mech. Mach. Theory 42 (2007)
1418-1443, constraints on 2 D_b / (D - d) between K_Dmin = 0.4-0.5 and K_Dmax = 0.6-0.7)
place on real bearings.  Not done here: rounding D_w to a standard ball size (sec. 2.1.2,
GB/T 308), which moves D_w by at most half the spacing of standard sizes (about 0.1-0.4 mm).
Against the bearings with published geometry (tests/literature/test_catalog_dimensions.py)
the estimate gets the ball count exactly for 6203, 6205, 6209 and 6310, D_w within 2.5 %
and d_m within 2.5 %; it gives 11 balls for the 106 (30 x 55 mm) of Balmont & Varlamov,
who report 14.  With K_w fixed at the middle of its range the filling-angle limits cannot
always be met (6209: 178.8 deg; 6308, where Table 1 fixes K_w = 0.32: 7 balls and
171 deg); the result then carries a note instead of a searched K_w.

Angular-contact and four-point bearings are not Conrad-assembled (a counterbored or split
ring admits more balls): the same rule gives a lower bound of their ball count, and the
contact angle comes from the designation or the family default.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from numbers import Real

from ..errors import InputError, bore_below_outside

#: Citation attached to every estimated value (``Source("estimated", ESTIMATE_METHOD)``).
ESTIMATE_METHOD = (
    "deep-groove ball bearing design rules (Chinese bearing industry, "
    "'深沟球轴承设计方法', sec. 2-3, Tables 1-2): D_w = K_w (D - d) with K_w the "
    "middle of the Table 1 range, d_m = (D + d)/2, Z from the ball filling angle, "
    "f_i = 0.515, f_o = 0.525"
)

#: Table 1: K_w ranges (low, high) by bore range and diameter-series group.
KW_TABLE: tuple[tuple[float, dict[str, tuple[float, float]]], ...] = (
    (35.0, {"0": (0.24, 0.31), "2": (0.29, 0.31), "3": (0.28, 0.32), "4": (0.25, 0.31)}),
    (120.0, {"0": (0.25, 0.32), "2": (0.31, 0.32), "3": (0.32, 0.32), "4": (0.25, 0.32)}),
    (math.inf, {"0": (0.24, 0.30), "2": (0.26, 0.31), "3": (0.29, 0.31), "4": (0.25, 0.30)}),
)
#: Table 2: design ball filling angle psi by diameter-series group [deg].
DESIGN_FILL_ANGLE_DEG = {"0": 190.0, "2": 186.0, "3": 186.0, "4": 186.0}
#: Sec. 2.6: largest real filling angle by diameter-series group [deg].
MAX_FILL_ANGLE_DEG = {"0": 195.0, "2": 194.0, "3": 193.0, "4": 192.0}
#: Sec. 2.6: smallest real filling angle [deg].
MIN_FILL_ANGLE_DEG = 180.0
#: Sec. 2.5.4: the pitch diameter may grow by at most this fraction.
MAX_PITCH_ENLARGEMENT = 0.03
#: Sec. 3.1 and 3.2: groove radius / ball diameter of the inner and outer ring [-].
INNER_GROOVE_FACTOR = 0.515
OUTER_GROOVE_FACTOR = 0.525

BALL_TYPES = ("radial_ball", "angular_contact_ball", "four_point_contact_ball")


def diameter_series_group(dimension_series: str) -> str:
    """Group of the ISO diameter series used by Tables 1 and 2: ``"0"``, ``"2"``, ``"3"``
    or ``"4"``.

    Diameter series 7, 8, 9, 0 and 1 (the light sections) form group ``"0"``.

    Parameters
    ----------
    dimension_series : str
        ISO two-digit dimension series; its last digit is the diameter series [-].

    Examples
    --------
    >>> diameter_series_group("02"), diameter_series_group("18"), diameter_series_group("10")
    ('2', '0', '0')
    """
    text = str(dimension_series).strip()
    if not text or text[-1] not in "0123456789":
        raise InputError(
            "dimension_series",
            dimension_series,
            "an ISO dimension series such as '02', '10' or '18'",
        )
    digit = text[-1]
    if digit in "78901":
        return "0"
    if digit in "234":
        return digit
    raise InputError(
        "dimension_series",
        dimension_series,
        "diameter series 7, 8, 9, 0, 1, 2, 3 or 4",
        "no Table 1 values for it",
    )


def ball_diameter_factor(bore: float, dimension_series: str) -> float:
    """K_w = D_w / (D - d), the middle of the Table 1 range [-].

    Parameters
    ----------
    bore : float
        Bore diameter d [m].
    dimension_series : str
        ISO two-digit dimension series [-].

    Examples
    --------
    >>> ball_diameter_factor(0.025, "02"), ball_diameter_factor(0.05, "03")
    (0.3, 0.32)
    """
    low, high = kw_range(bore, dimension_series)
    return round(0.5 * (low + high), 6)


@dataclass(frozen=True)
class EstimatedGeometry:
    """Internal geometry estimated from boundary dimensions (SI units).

    Parameters
    ----------
    ball_count : int
        Number of balls Z [-].
    ball_diameter : float
        Ball diameter D_w [m].
    pitch_diameter : float
        Pitch diameter d_m, (D + d)/2 or up to 3 % more [m].
    inner_groove_factor, outer_groove_factor : float
        f_i, f_o [-].
    contact_angle : float
        Nominal contact angle [rad].
    fill_angle : float
        Real ball filling angle 2 (Z - 1) asin(D_w / d_m) [rad].
    ball_diameter_factor : float
        K_w = D_w / (D - d) used [-].
    method : str
        Citation of the method [-].
    notes : tuple of str
        Caveats (filling angle outside the limits, ball count a lower bound) [-].
    """

    ball_count: int
    ball_diameter: float
    pitch_diameter: float
    inner_groove_factor: float
    outer_groove_factor: float
    contact_angle: float
    fill_angle: float
    ball_diameter_factor: float
    method: str = ESTIMATE_METHOD
    notes: tuple[str, ...] = ()

    def as_kwargs(self) -> dict:
        """The values as :class:`~bearinglab.geometry.BallBearing` keywords."""
        return {
            "ball_count": self.ball_count,
            "ball_diameter": self.ball_diameter,
            "pitch_diameter": self.pitch_diameter,
            "inner_groove_factor": self.inner_groove_factor,
            "outer_groove_factor": self.outer_groove_factor,
            "contact_angle": self.contact_angle,
        }


def _fill(count: int, ball_diameter: float, pitch: float) -> float:
    return 2.0 * (count - 1) * math.asin(ball_diameter / pitch)


def _pitch_for(count: int, ball_diameter: float, fill_angle: float) -> float:
    """Pitch diameter at which Z balls fill exactly ``fill_angle`` [m]."""
    return ball_diameter / math.sin(fill_angle / (2.0 * (count - 1)))


def ball_count_and_pitch(
    ball_diameter: float,
    pitch_diameter: float,
    dimension_series: str,
) -> tuple[int, float, tuple[str, ...]]:
    """Ball count and (possibly enlarged) pitch diameter by the filling-angle rule.

    Z = round(psi_design / (2 asin(D_w/d_m)) + 1); if the real filling angle exceeds the
    limit of the diameter series, d_m grows (at most 3 %) until it does not, else Z drops
    by one; if it is below 180 deg, one more ball is tried the same way.

    Parameters
    ----------
    ball_diameter : float
        D_w [m].
    pitch_diameter : float
        Starting pitch diameter (D + d)/2 [m].
    dimension_series : str
        ISO two-digit dimension series [-].

    Returns
    -------
    tuple
        (Z [-], d_m [m], notes [-]).

    Examples
    --------
    >>> z, dm, _ = ball_count_and_pitch(8.1e-3, 38.5e-3, "02")
    >>> z, round(dm * 1e3, 2)
    (9, 38.56)
    """
    group = diameter_series_group(dimension_series)
    if not 0.0 < ball_diameter < pitch_diameter:
        raise InputError(
            "ball_diameter",
            ball_diameter,
            f"a length between 0 and the pitch diameter {pitch_diameter:.6g} m",
        )
    psi_max = math.radians(MAX_FILL_ANGLE_DEG[group])
    psi_min = math.radians(MIN_FILL_ANGLE_DEG)
    limit = pitch_diameter * (1.0 + MAX_PITCH_ENLARGEMENT)
    step = 2.0 * math.asin(ball_diameter / pitch_diameter)
    count = max(3, round(math.radians(DESIGN_FILL_ANGLE_DEG[group]) / step + 1.0))
    pitch = pitch_diameter
    notes: list[str] = []
    if _fill(count, ball_diameter, pitch) > psi_max:
        wider = _pitch_for(count, ball_diameter, psi_max)
        if wider <= limit:
            pitch = wider
        else:
            count -= 1
    if _fill(count, ball_diameter, pitch) < psi_min:
        wider = max(pitch, _pitch_for(count + 1, ball_diameter, psi_max))
        if wider <= limit:
            count, pitch = count + 1, wider
        else:
            notes.append(
                f"filling angle {math.degrees(_fill(count, ball_diameter, pitch)):.1f} "
                "deg is below the 180 deg of the design rules; one more ball would "
                "need more than 3 % larger pitch diameter"
            )
    return count, pitch, tuple(notes)


def kw_range(bore: float, dimension_series: str) -> tuple[float, float]:
    """The Table 1 range (low, high) of K_w = D_w / (D - d) [-].

    Parameters
    ----------
    bore : float
        Bore diameter d [m].
    dimension_series : str
        ISO two-digit dimension series [-].

    Examples
    --------
    >>> kw_range(0.025, "02")
    (0.29, 0.31)
    """
    group = diameter_series_group(dimension_series)
    for limit, ranges in KW_TABLE:
        if bore * 1e3 <= limit:
            return ranges[group]
    raise AssertionError("unreachable: the last bore limit is infinite")


def estimate_internal_geometry(
    bore: float,
    outside_diameter: float,
    dimension_series: str,
    bearing_type: str = "radial_ball",
    contact_angle: float | None = None,
) -> EstimatedGeometry:
    """Estimate Z, D_w, d_m, f_i, f_o and the contact angle of a ball bearing.

    See the module docstring for the method and its source.

    Parameters
    ----------
    bore : float
        Bore diameter d [m].
    outside_diameter : float
        Outside diameter D [m].
    dimension_series : str
        ISO two-digit dimension series, e.g. ``"02"`` for 62xx and 72xx [-].
    bearing_type : str
        ``"radial_ball"``, ``"angular_contact_ball"`` or ``"four_point_contact_ball"`` [-].
    contact_angle : float or None
        Nominal contact angle; None gives 0 for a radial bearing [rad].

    Examples
    --------
    >>> g = estimate_internal_geometry(0.025, 0.052, "02")   # 6205
    >>> g.ball_count, round(g.ball_diameter * 1e3, 2), round(g.pitch_diameter * 1e3, 2)
    (9, 8.1, 38.56)
    """
    if bearing_type not in BALL_TYPES:
        raise InputError(
            "bearing_type",
            bearing_type,
            f"one of {BALL_TYPES}",
            "the design rules are for single-row ball bearings",
        )
    for name, value in (("bore", bore), ("outside_diameter", outside_diameter)):
        if not (isinstance(value, Real) and math.isfinite(value) and value > 0):
            raise InputError(name, value, "a positive length [m]")
    bore_below_outside(bore, outside_diameter)
    if contact_angle is None:
        if bearing_type != "radial_ball":
            raise InputError(
                "contact_angle",
                contact_angle,
                "a nominal contact angle [rad] for an angular-contact bearing",
            )
        contact_angle = 0.0
    if not 0.0 <= contact_angle < 0.5 * math.pi:
        raise InputError("contact_angle", contact_angle, "an angle in [0, pi/2) rad")
    kw = ball_diameter_factor(bore, dimension_series)
    ball = kw * (outside_diameter - bore)
    count, pitch, notes = ball_count_and_pitch(
        ball, 0.5 * (outside_diameter + bore), dimension_series
    )
    if bearing_type != "radial_ball":
        notes += (
            (
                "the Conrad filling-angle rule gives a lower bound of the ball count of an "
                "angular-contact or four-point bearing"
            ),
        )
    return EstimatedGeometry(
        ball_count=count,
        ball_diameter=ball,
        pitch_diameter=pitch,
        inner_groove_factor=INNER_GROOVE_FACTOR,
        outer_groove_factor=OUTER_GROOVE_FACTOR,
        contact_angle=float(contact_angle),
        fill_angle=_fill(count, ball, pitch),
        ball_diameter_factor=kw,
        notes=notes,
    )
