"""The geometric and load variables G_rr and G_sl of the SKF frictional-moment model, by
bearing type (layer 1).

Source: SKF, *Rolling bearings* (catalogue 10000 EN), chapter "Friction", section "The SKF
model for calculating the frictional moment", Table 2a (radial bearings). They make the
rolling moment M_rr = G_rr (nu n)^0.6 and the sliding moment M_sl = G_sl mu_sl of
:func:`bearinglab.friction.skf.skf_frictional_moment`:

- deep-groove ball bearings, F_a = 0: G_rr = R1 d_m^1.96 F_r^0.54,
  G_sl = S1 d_m^-0.26 F_r^(5/3); F_a > 0: G_rr = R1 d_m^1.96 (F_r + R2/sin(alpha_F) F_a)^0.54,
  G_sl = S1 d_m^-0.145 (F_r^5 + S2 d_m^1.5 / sin(alpha_F) F_a^4)^(1/3),
  alpha_F = 24.6 (F_a/C_0)^0.24 [deg];
- angular-contact (and four-point) ball bearings: G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54,
  F_g = R3 d_m^4 n^2; G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)), F_g = S3 d_m^4 n^2;
- cylindrical roller bearings: G_rr = R1 d_m^2.41 F_r^0.31, G_sl = S1 d_m^0.9 F_a + S2 d_m F_r;
- tapered roller bearings: G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31,
  G_sl = S1 d_m^0.82 (F_r + S2 Y F_a).

In SKF's units (d_m = 0.5 (d + D) mm, F N, n r/min); the functions take SI and convert at
the edge (:mod:`.skf_constants`). Checked against a stored copy: the deep-groove and
angular-contact forms including alpha_F (catalogue 10000 EN, Table 2a, as stored at
yumpu.com, document 55668573 page 106); the roller forms are not (see
docs/capabilities/friction.md).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .skf_constants import (  # noqa: F401 - SkfGeometryConstants, deep_groove_constants: doctests
    SkfGeometryConstants,
    _array,
    _mm,
    _out,
    _rpm,
    deep_groove_constants,
)


def _loads(mean_diameter, radial_load, axial_load) -> tuple[float, float, float]:
    """d_m [mm], F_r and F_a [N] of a load-variable function, each checked."""
    return (
        float(_mm("mean_diameter", mean_diameter)),
        float(_array("radial_load", radial_load, "N")),
        float(_array("axial_load", axial_load, "N")),
    )


def deep_groove_load_angle(axial_load, static_load_rating):
    """alpha_F = 24.6 (F_a / C_0)^0.24 [rad] (catalogue: degrees), deep-groove bearings.

    Parameters
    ----------
    axial_load : float or array
        F_a [N], >= 0.
    static_load_rating : float
        Basic static load rating C_0 [N], > 0; F_a <= C_0.

    Examples
    --------
    >>> round(math.degrees(deep_groove_load_angle(1000.0, 10000.0)), 3)
    14.156
    """
    fa = _array("axial_load", axial_load, "N")
    c0 = float(_array("static_load_rating", static_load_rating, "N", positive=True))
    if np.any(fa > c0):
        raise InputError(
            "axial_load", axial_load, f"at most the static load rating C_0 = {c0:.6g} N"
        )
    return _out(np.radians(24.6 * (fa / c0) ** 0.24))


def deep_groove_load_variables(
    mean_diameter, radial_load, axial_load, constants, static_load_rating=None
):
    """(G_rr, G_sl) of a deep-groove ball bearing, catalogue Table 2a [SKF units].

    Returned in SKF's units: M_rr [N mm] = G_rr (nu[mm^2/s] n[r/min])^0.6 and
    M_sl [N mm] = G_sl mu_sl. With F_a > 0, C_0 is needed for alpha_F. The F_a > 0 form
    does not tend to the F_a = 0 form of G_sl as F_a -> 0 (d_m^-0.145 against
    d_m^-0.26, as printed).

    Parameters
    ----------
    mean_diameter : float
        d_m = 0.5 (d + D) [m].
    radial_load, axial_load : float
        F_r, F_a [N], >= 0.
    constants : SkfGeometryConstants
        R1, R2, S1, S2 of the series.
    static_load_rating : float or None
        C_0 [N]; needed when F_a > 0.

    Examples
    --------
    >>> g = deep_groove_load_variables(0.0385, 1000.0, 0.0, deep_groove_constants("62"))
    >>> round(g[0], 5), round(g[1], 2)
    (0.02082, 125.02)
    """
    dm, fr, fa = _loads(mean_diameter, radial_load, axial_load)
    c = constants
    if fa == 0.0:
        return (c.r1 * dm**1.96 * fr**0.54, c.s1 * dm**-0.26 * fr ** (5.0 / 3.0))
    if static_load_rating is None:
        raise InputError(
            "static_load_rating",
            None,
            "the basic static load rating C_0 [N] when F_a > 0",
            "SKF's alpha_F = 24.6 (F_a/C_0)^0.24 needs it (static_load_rating)",
        )
    sin_a = math.sin(float(deep_groove_load_angle(fa, static_load_rating)))
    g_rr = c.r1 * dm**1.96 * (fr + c.r2 / sin_a * fa) ** 0.54
    g_sl = c.s1 * dm**-0.145 * (fr**5 + c.s2 * dm**1.5 / sin_a * fa**4) ** (1.0 / 3.0)
    return g_rr, g_sl


def angular_contact_load_variables(mean_diameter, radial_load, axial_load, shaft_speed, constants):
    """(G_rr, G_sl) of an angular-contact (or four-point) ball bearing [SKF units].

    G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54 with F_g = R3 d_m^4 n^2;
    G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)) with F_g = S3 d_m^4 n^2
    (catalogue Table 2a; d_m mm, n r/min, F N).

    Parameters
    ----------
    mean_diameter : float
        d_m [m].
    radial_load, axial_load : float
        F_r, F_a [N].
    shaft_speed : float
        [rad/s].
    constants : SkfGeometryConstants
        With r3 and s3 given.
    """
    c = constants
    if c.r3 is None or c.s3 is None:
        raise InputError("constants", c, "angular-contact constants with R3 and S3")
    dm, fr, fa = _loads(mean_diameter, radial_load, axial_load)
    n = float(_rpm(shaft_speed))
    g_rr = c.r1 * dm**1.97 * (fr + c.r3 * dm**4 * n**2 + c.r2 * fa) ** 0.54
    g_sl = c.s1 * dm**0.26 * ((fr + c.s3 * dm**4 * n**2) ** (4.0 / 3.0) + c.s2 * fa ** (4.0 / 3.0))
    return g_rr, g_sl


def cylindrical_roller_load_variables(mean_diameter, radial_load, axial_load, constants):
    """(G_rr, G_sl) of a cylindrical roller bearing, catalogue Table 2a [SKF units]:
    G_rr = R1 d_m^2.41 F_r^0.31, G_sl = S1 d_m^0.9 F_a + S2 d_m F_r (d_m mm, F N).

    Parameters
    ----------
    mean_diameter : float
        d_m = 0.5 (d + D) [m].
    radial_load, axial_load : float
        F_r, F_a [N], >= 0.
    constants : SkfGeometryConstants
        R1, S1, S2 of the series (R2 unused).

    Examples
    --------
    >>> g = cylindrical_roller_load_variables(0.0385, 2000.0, 0.0,
    ...                                       SkfGeometryConstants(1.09e-6, 0.0, 0.16, 0.0015))
    >>> round(g[0], 4), round(g[1], 3)
    (0.0762, 115.5)
    """
    dm, fr, fa = _loads(mean_diameter, radial_load, axial_load)
    c = constants
    return c.r1 * dm**2.41 * fr**0.31, c.s1 * dm**0.9 * fa + c.s2 * dm * fr


def tapered_roller_load_variables(mean_diameter, radial_load, axial_load, axial_factor, constants):
    """(G_rr, G_sl) of a tapered roller bearing, catalogue Table 2a [SKF units]:
    G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31, G_sl = S1 d_m^0.82 (F_r + S2 Y F_a), Y the
    axial load factor of the bearing (0.4 cot alpha for one row).

    Parameters
    ----------
    mean_diameter : float
        d_m = 0.5 (d + D) [m].
    radial_load, axial_load : float
        F_r, F_a [N], >= 0.
    axial_factor : float
        Y [-].
    constants : SkfGeometryConstants
        R1, R2, S1, S2 of the series.

    Examples
    --------
    >>> g = tapered_roller_load_variables(0.0385, 2000.0, 500.0, 1.6,
    ...                                   SkfGeometryConstants(1.76e-6, 10.9, 0.017, 2.0))
    >>> round(g[0], 4), round(g[1], 2)
    (0.1855, 1221.32)
    """
    dm, fr, fa = _loads(mean_diameter, radial_load, axial_load)
    y = float(_array("axial_factor", axial_factor, "-"))
    c = constants
    return (
        c.r1 * dm**2.38 * (fr + c.r2 * y * fa) ** 0.31,
        c.s1 * dm**0.82 * (fr + c.s2 * y * fa),
    )
