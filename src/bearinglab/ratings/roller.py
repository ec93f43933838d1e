"""Load ratings and equivalent loads of radial roller bearings (ISO 281:2007, ISO 76:2006):
cylindrical, needle and tapered roller bearings, one row or two.

Equations (lengths in mm, forces in N as the standards write them; the functions take SI):

- basic dynamic load rating (ISO 281 sec. 6.2): C_r = b_m f_c (i L_we cos a)^(7/9)
  Z^(3/4) D_we^(29/27), b_m = 1.1 for cylindrical, tapered and machined-ring needle
  roller bearings (ISO 281 Table 1);
- f_c from the Lundberg-Palmgren form behind ISO 281 Table 7 (ISO/TR 1281-1):
  f_c = 207.9 lambda nu gamma^(2/9) (1 - gamma)^(29/27) / (1 + gamma)^(1/4)
  [1 + (1.04 ((1 - gamma)/(1 + gamma))^(143/108))^(9/2)]^(-2/9), lambda nu = 0.83 (the
  reduction for edge stresses and uneven loading), gamma = D_we cos(a)/D_pw. The printed
  table was not available as a stored copy; the form is checked through Harris's 209
  cylindrical roller bearing (C = 48.4 kN, tests/literature/test_roller_harris209.py);
- basic static load rating (ISO 76 sec. 6.1, 4000 MPa at the most loaded contact):
  C_0r = 44 (1 - D_we cos a / D_pw) i Z L_we D_we cos a;
- dynamic equivalent load (ISO 281 Table 3, radial roller bearings): a = 0: P = F_r;
  a != 0, one row: P = F_r for F_a/F_r <= e, else 0.4 F_r + 0.4 cot(a) F_a; two rows
  (a pair or a double-row bearing): F_r + 0.45 cot(a) F_a for F_a/F_r <= e, else
  0.67 F_r + 0.67 cot(a) F_a; e = 1.5 tan(a);
- static equivalent load (ISO 76 Table 2): a = 0: P_0 = F_r; one row:
  max(F_r, 0.5 F_r + 0.22 cot(a) F_a); two rows: F_r + 0.44 cot(a) F_a;
- fatigue load limit (ISO 281 Annex B, simplified): C_u = C_0 / 8.2, times
  (100 / D_pw)^0.3 for D_pw > 100 mm (as quoted by the mecapy ISO 281 module, which marks
  8.2 a manufacturers' rule; docs/capabilities/roller_bearings.md).

These are the catalogue relations of tapered bearings, e = 1.5 tan(a) and Y = 0.4 cot(a)
(SKF 30205 J2/Q: e = 0.37, Y = 1.6, a = 13.9 deg).
"""

from __future__ import annotations

import math

from ..errors import InputError, positive_number

_MM = 1e-3
#: b_m of ISO 281 Table 1 by roller bearing type [-].
B_M_ROLLER = {"cylindrical_roller": 1.1, "tapered_roller": 1.1, "needle_roller": 1.1}
#: lambda nu of the roller f_c form (reduction for edge stresses and uneven loading) [-].
LAMBDA_NU = 0.83
#: The constants of the roller f_c form (ISO/TR 1281-1) [-].
FC_ROLLER_CONSTANT = 207.9
FC_ROLLER_CONFORMITY = 1.04
#: ISO 76 roller constant: C_0r = 44 (1 - gamma) i Z L_we D_we cos(a) [N/mm^2].
F0_ROLLER = 44.0
#: Contact stress that defines C_0 of roller bearings (ISO 76) [Pa].
STATIC_CONTACT_STRESS_ROLLER = 4.0e9
#: ISO 281 Annex B simplified: C_u = C_0 / 8.2, times (100/D_pw)^0.3 beyond 100 mm.
CU_DIVISOR_ROLLER = 8.2
CU_EXPONENT_ROLLER = 0.3
#: ISO 281 Table 3 factors of radial roller bearings with a != 0.
X_SINGLE, Y_SINGLE = 0.4, 0.4
Y_DOUBLE_LOW, X_DOUBLE, Y_DOUBLE = 0.45, 0.67, 0.67
E_FACTOR = 1.5
#: ISO 76 Table 2: single row X_0 = 0.5, Y_0 = 0.22 cot(a); double row X_0 = 1, 0.44 cot(a).
X0_SINGLE, Y0_SINGLE, Y0_DOUBLE = 0.5, 0.22, 0.44


def _gamma(gamma) -> float:
    if not (isinstance(gamma, (int, float)) and math.isfinite(gamma) and 0.0 < gamma < 1.0):
        raise InputError("gamma", gamma, "a value in (0, 1)")
    return float(gamma)


def roller_fc_factor(gamma: float) -> float:
    """f_c of radial roller bearings (the form behind ISO 281 Table 7) [N/mm^(65/27) ...].

    Parameters
    ----------
    gamma : float
        D_we cos(alpha) / D_pw, in (0, 1) [-].

    Returns
    -------
    float
        f_c for C in N with L_we and D_we in mm.

    Examples
    --------
    >>> round(roller_fc_factor(0.15), 2), round(roller_fc_factor(10 / 65.01), 2)
    (88.21, 88.35)
    """
    g = _gamma(gamma)
    ratio = (1.0 - g) / (1.0 + g)
    conformity = (1.0 + (FC_ROLLER_CONFORMITY * ratio ** (143.0 / 108.0)) ** 4.5) ** (-2.0 / 9.0)
    return (
        FC_ROLLER_CONSTANT
        * LAMBDA_NU
        * g ** (2.0 / 9.0)
        * (1.0 - g) ** (29.0 / 27.0)
        / (1.0 + g) ** 0.25
        * conformity
    )


def _set(roller_count, roller_diameter, roller_length, pitch_diameter, contact_angle, rows):
    if isinstance(roller_count, bool) or not isinstance(roller_count, int) or roller_count < 3:
        raise InputError("roller_count", roller_count, "an integer >= 3")
    for name, value in (
        ("roller_diameter", roller_diameter),
        ("roller_length", roller_length),
        ("pitch_diameter", pitch_diameter),
    ):
        positive_number(name, value, "a length > 0 [m]")
    if pitch_diameter <= roller_diameter:
        raise InputError(
            "pitch_diameter", pitch_diameter, f"more than the roller diameter {roller_diameter} m"
        )
    if not (isinstance(contact_angle, (int, float)) and 0.0 <= contact_angle < 0.5 * math.pi):
        raise InputError("contact_angle", contact_angle, "an angle in [0, 90) degrees")
    if isinstance(rows, bool) or not isinstance(rows, int) or rows < 1:
        raise InputError("rows", rows, "an integer >= 1")
    return roller_diameter * math.cos(contact_angle) / pitch_diameter


def roller_dynamic_load_rating(
    roller_count: int,
    roller_diameter: float,
    roller_length: float,
    pitch_diameter: float,
    contact_angle: float = 0.0,
    rows: int = 1,
    rating_factor: float = 1.1,
) -> float:
    """Basic dynamic load rating C_r of a radial roller bearing, ISO 281:2007 [N].

    Parameters
    ----------
    roller_count : int
        Rollers per row Z [-].
    roller_diameter : float
        D_we [m].
    roller_length : float
        Effective length L_we [m].
    pitch_diameter : float
        D_pw [m].
    contact_angle : float
        alpha [rad].
    rows : int
        Rows i [-].
    rating_factor : float
        b_m [-].

    Examples
    --------
    >>> round(roller_dynamic_load_rating(14, 10e-3, 9.6e-3, 65.01e-3))  # Harris's 209
    48445
    """
    gamma = _set(roller_count, roller_diameter, roller_length, pitch_diameter, contact_angle, rows)
    return (
        rating_factor
        * roller_fc_factor(gamma)
        * (rows * roller_length / _MM * math.cos(contact_angle)) ** (7.0 / 9.0)
        * roller_count**0.75
        * (roller_diameter / _MM) ** (29.0 / 27.0)
    )


def roller_static_load_rating(
    roller_count: int,
    roller_diameter: float,
    roller_length: float,
    pitch_diameter: float,
    contact_angle: float = 0.0,
    rows: int = 1,
) -> float:
    """Basic static load rating C_0r of a radial roller bearing, ISO 76:2006 [N]:
    44 (1 - gamma) i Z L_we D_we cos(alpha), the load at 4000 MPa.

    Parameters
    ----------
    roller_count, roller_diameter, roller_length, pitch_diameter, contact_angle, rows
        As for :func:`roller_dynamic_load_rating`.

    Examples
    --------
    >>> round(roller_static_load_rating(14, 10e-3, 9.6e-3, 65.01e-3))  # Harris's 209
    50040
    """
    gamma = _set(roller_count, roller_diameter, roller_length, pitch_diameter, contact_angle, rows)
    return (
        F0_ROLLER
        * (1.0 - gamma)
        * rows
        * roller_count
        * (roller_length / _MM)
        * (roller_diameter / _MM)
        * math.cos(contact_angle)
    )


def roller_fatigue_load_limit(static_rating: float, pitch_diameter: float) -> float:
    """C_u of a roller bearing, ISO 281 Annex B simplified: C_0/8.2, times
    (100 mm / D_pw)^0.3 when D_pw > 100 mm [N].

    Parameters
    ----------
    static_rating : float
        C_0 [N].
    pitch_diameter : float
        D_pw [m].

    Examples
    --------
    >>> round(roller_fatigue_load_limit(8200.0, 0.05))
    1000
    """
    c0 = positive_number("static_rating", static_rating, "a rating > 0 [N]")
    d_pw = positive_number("pitch_diameter", pitch_diameter, "a length > 0 [m]") / _MM
    c_u = c0 / CU_DIVISOR_ROLLER
    if d_pw > 100.0:
        c_u *= (100.0 / d_pw) ** CU_EXPONENT_ROLLER
    return c_u


def tapered_factors(contact_angle: float, rows: int = 1) -> tuple[float, float, float, float]:
    """(e, X, Y, Y_low) of ISO 281 Table 3 for a radial roller bearing with alpha != 0:
    X, Y apply when F_a/F_r > e, (1, Y_low) below [-].

    Parameters
    ----------
    contact_angle : float
        alpha in (0, 90) deg [rad].
    rows : int
        1, or 2 for a pair or a double-row bearing [-].

    Examples
    --------
    >>> [round(v, 3) for v in tapered_factors(math.radians(13.86))]
    [0.37, 0.4, 1.621, 0.0]
    """
    if not 0.0 < contact_angle < 0.5 * math.pi:
        raise InputError("contact_angle", contact_angle, "an angle in (0, 90) degrees")
    cot = 1.0 / math.tan(contact_angle)
    e = E_FACTOR * math.tan(contact_angle)
    if rows == 1:
        return e, X_SINGLE, Y_SINGLE * cot, 0.0
    return e, X_DOUBLE, Y_DOUBLE * cot, Y_DOUBLE_LOW * cot


def roller_equivalent_dynamic_load(
    contact_angle: float, rows: int, radial_load: float, axial_load: float
) -> tuple[float, float, float, float]:
    """P of a radial roller bearing, ISO 281:2007 Table 3 [N], with (X, Y, e) used.

    Parameters
    ----------
    contact_angle : float
        alpha [rad]: 0 for cylindrical and needle bearings (P = F_r).
    rows : int
        Rows (2: a mirrored pair or a double-row bearing) [-].
    radial_load, axial_load : float
        F_r >= 0, F_a (its sign does not matter) [N].

    Returns
    -------
    tuple
        (P [N], X, Y, e [-]).

    Examples
    --------
    >>> round(roller_equivalent_dynamic_load(math.radians(13.86), 1, 1000.0, 1000.0)[0])
    2021
    """
    radial, axial = float(radial_load), abs(float(axial_load))
    if contact_angle == 0.0:
        return radial, 1.0, 0.0, math.inf
    e, x, y, y_low = tapered_factors(contact_angle, rows)
    if radial > 0 and axial / radial <= e:
        return radial + y_low * axial, 1.0, y_low, e
    return x * radial + y * axial, x, y, e


def roller_equivalent_static_load(
    contact_angle: float, rows: int, radial_load: float, axial_load: float
) -> float:
    """P_0 of a radial roller bearing, ISO 76:2006 Table 2 [N].

    Parameters
    ----------
    contact_angle : float
        alpha [rad].
    rows : int
        Rows [-].
    radial_load, axial_load : float
        F_r, F_a [N].

    Examples
    --------
    >>> round(roller_equivalent_static_load(math.radians(13.86), 1, 1000.0, 1000.0))
    1392
    """
    radial, axial = float(radial_load), abs(float(axial_load))
    if contact_angle == 0.0:
        return radial
    cot = 1.0 / math.tan(contact_angle)
    if rows == 1:
        return max(radial, X0_SINGLE * radial + Y0_SINGLE * cot * axial)
    return radial + Y0_DOUBLE * cot * axial
