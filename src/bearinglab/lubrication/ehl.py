"""Elastohydrodynamic (EHL) film thickness of elliptical point contacts.

Layer 1: pure, vectorised functions, SI in and out; :func:`film_thickness` at the end is
a convenience that evaluates them for a :class:`~bearinglab.geometry.BallBearing` and a
:class:`~bearinglab.lubrication.lubricant.Lubricant`.

Sources:

- Hamrock B. J., Dowson D., "Isothermal elastohydrodynamic lubrication of point
  contacts, Part III -- Fully flooded results", *J. Lubr. Technol.* 99 (1977) 264-276
  (the minimum-film fit, as stated in its abstract):
  H_min = h_min / R_x = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)),
  with the simplified ellipticity k = 1.03 (R_y / R_x)^0.64.
- Hamrock B. J., Dowson D., "Isothermal elastohydrodynamic lubrication of point
  contacts, Part IV -- Starvation results", *J. Lubr. Technol.* 99 (1977) 15-23 (the
  fully flooded central-film fit):
  H_c = h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)).
  The constants and exponents of both fits were checked against the Part III abstract
  (ASME digital collection) and the tribonet.org point-contact calculator page, which
  cites Hamrock & Dowson; we could not see the papers' equation numbers, so none are
  quoted here.
- Dimensionless groups (both papers): U = eta_0 u / (E' R_x), G = alpha E',
  W = w / (E' R_x^2), with u the mean entrainment (rolling) speed (u_a + u_b)/2,
  E' = 2 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b), R_x the effective radius in the
  rolling direction and R_y across it (R_y >= R_x: entrainment along the minor axis).
  The fits cover 1 <= k <= 8; ball-raceway contacts (R_y/R_x ~ 20-40, k ~ 7-11) are at
  or just past that edge, where the ellipticity factors are within 1 % of 1.
- Entrainment speed of a ball-raceway contact in pure rolling (Harris T. A., Kotzalas
  M. N., *Essential Concepts of Bearing Technology*, 5th ed., 2007, ch. 7 kinematics:
  cage speed omega_c = [omega_i (1 - gamma) + omega_o (1 + gamma)] / 2):
  u = (d_m / 4) (1 - gamma^2) |omega_i - omega_o|, the same at both raceways.
- Seed 004 (Hou et al., *J. Mech. Electr. Eng.* 41 (2024) 271-279), eq. (6), as printed:
  h = 3.06 R_y^0.956 E_eff^-0.117 (eta_0 u)^0.68 alpha^0.49 N^-0.073
  {1 - exp[-3.36 (R_x / R_y)]}, where the seed's R_y is the radius in the entrainment
  direction (our R_x) and its R_x the transverse one (our R_y). See
  :func:`seed004_film_thickness` for why this is not dimensionally consistent.

Assumptions: isothermal, fully flooded inlet, Newtonian lubricant with Barus'
pressure-viscosity law, smooth surfaces, steady pure rolling. The Hamrock-Dowson
starvation and the thermal (inlet shear heating) corrections are not implemented: the
seed-004 dynamics and the load-distribution models use the isothermal, fully flooded
film only.
"""

from __future__ import annotations

from typing import Literal, NamedTuple

import numpy as np

from ..contact import hertz
from ..errors import InputError
from ..materials import effective_modulus as _effective_modulus

Kind = Literal["central", "minimum"]
KINDS = ("central", "minimum")
EllipticityMethod = Literal["hamrock_dowson", "exact", "hamrock_brewe"]
ELLIPTICITY_METHODS = ("hamrock_dowson", "exact", "hamrock_brewe")


class DimensionlessGroups(NamedTuple):
    """Hamrock-Dowson groups: speed U, materials G, load W [-]."""

    speed: np.ndarray
    materials: np.ndarray
    load: np.ndarray


# ---------------------------------------------------------------- validation helpers


def _array(name: str, value, allowed: str, *, zero_ok: bool = False):
    x = np.asarray(value, dtype=float)
    bad = np.any(~np.isfinite(x)) or (np.any(x < 0) if zero_ok else np.any(x <= 0))
    if bad:
        raise InputError(name, value, allowed)
    return x


def _radii(rx, ry):
    rx = _array("rx", rx, "positive effective radii R_x [m]")
    ry = _array("ry", ry, "positive effective radii R_y [m]")
    if np.any(ry < rx * (1.0 - 1e-12)):
        raise InputError(
            "ry",
            ry,
            "R_y >= R_x (entrainment along the minor axis of the contact ellipse)",
            "the Hamrock-Dowson fits assume it",
        )
    return rx, ry


# ---------------------------------------------------------------- layer 1: functions


def ellipticity_hamrock_dowson(radius_ratio):
    """Hamrock & Dowson's (1977, Part III) simplified ellipticity k = 1.03 (R_y/R_x)^0.64 [-].

    Parameters
    ----------
    radius_ratio : float or array
        R_y / R_x [-], >= 1.

    Examples
    --------
    >>> round(float(ellipticity_hamrock_dowson(1.0)), 2)
    1.03
    """
    ratio = np.asarray(radius_ratio, dtype=float)
    if np.any(~np.isfinite(ratio)) or np.any(ratio < 1.0 - 1e-12):
        raise InputError("radius_ratio", radius_ratio, "finite values >= 1 (R_y/R_x)")
    return (1.03 * ratio**0.64)[()]


def contact_ellipticity(rx, ry, method: EllipticityMethod = "hamrock_dowson"):
    """Ellipticity k of the contact for the film formulas [-].

    ``hamrock_dowson`` is the fit the film formulas were published with,
    :func:`ellipticity_hamrock_dowson`; ``exact`` and ``hamrock_brewe`` are those of
    :func:`bearinglab.contact.hertz.ellipticity`.

    Parameters
    ----------
    rx, ry : float or array
        Effective radii in the rolling and transverse directions [m], R_y >= R_x.
    method : {"hamrock_dowson", "exact", "hamrock_brewe"}
        How k is obtained [-].
    """
    rx, ry = _radii(rx, ry)
    ratio = np.maximum(ry / rx, 1.0)
    if method == "hamrock_dowson":
        return ellipticity_hamrock_dowson(ratio)
    if method in ("exact", "hamrock_brewe"):
        return hertz.ellipticity(ratio, method)
    raise InputError("ellipticity_method", method, f"one of {ELLIPTICITY_METHODS}")


def dimensionless_groups(
    load, entrainment_speed, rx, effective_modulus, viscosity, pressure_viscosity_coefficient
) -> DimensionlessGroups:
    """Hamrock-Dowson speed, materials and load parameters.

    U = eta_0 u / (E' R_x), G = alpha E', W = w / (E' R_x^2).

    Parameters
    ----------
    load : float or array
        Normal contact load w [N], > 0.
    entrainment_speed : float or array
        Mean rolling speed u = (u_a + u_b)/2 [m/s], >= 0.
    rx : float or array
        Effective radius in the rolling direction R_x [m].
    effective_modulus : float or array
        E' [Pa].
    viscosity : float or array
        eta_0 at atmospheric pressure and the inlet temperature [Pa s].
    pressure_viscosity_coefficient : float or array
        alpha [1/Pa].

    Examples
    --------
    >>> g = dimensionless_groups(1000.0, 10.0, 5e-3, 2e11, 0.04, 2e-8)
    >>> [float(f"{float(v):.4g}") for v in g]
    [4e-10, 4000.0, 0.0002]
    """
    w = _array("load", load, "positive contact loads [N] (the film formulas diverge at 0)")
    u = _array(
        "entrainment_speed", entrainment_speed, "entrainment speeds >= 0 [m/s]", zero_ok=True
    )
    rx = _array("rx", rx, "positive effective radii R_x [m]")
    e = _array("effective_modulus", effective_modulus, "a positive modulus E' [Pa]")
    eta = _array("viscosity", viscosity, "a positive viscosity [Pa s]")
    alpha = _array(
        "pressure_viscosity_coefficient",
        pressure_viscosity_coefficient,
        "a positive coefficient alpha [1/Pa]",
    )
    speed = eta * u / (e * rx)
    return DimensionlessGroups(speed[()], (alpha * e)[()], (w / (e * rx**2))[()])


def hamrock_dowson_minimum(speed, materials, load, ellipticity):
    """Dimensionless minimum film H_min = h_min / R_x [-] (Hamrock & Dowson 1977, Part III).

    H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)).

    Parameters
    ----------
    speed : float or array
        U [-], >= 0.
    materials : float or array
        G [-], > 0.
    load : float or array
        W [-], > 0.
    ellipticity : float or array
        k [-], > 0.

    Examples
    --------
    >>> round(float(hamrock_dowson_minimum(1e-11, 5000.0, 1e-6, 4.0)) * 1e6, 3)
    19.99
    """
    u, g, w, k = _groups(speed, materials, load, ellipticity)
    return (3.63 * u**0.68 * g**0.49 * w**-0.073 * (1.0 - np.exp(-0.68 * k)))[()]


def hamrock_dowson_central(speed, materials, load, ellipticity):
    """Dimensionless central film H_c = h_c / R_x [-] (Hamrock & Dowson 1977, Part IV).

    H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)).

    Parameters
    ----------
    speed, materials, load, ellipticity : float or array
        U, G, W and k [-], as in :func:`hamrock_dowson_minimum`.

    Examples
    --------
    >>> round(float(hamrock_dowson_central(1e-11, 5000.0, 1e-6, 4.0)) * 1e6, 3)
    25.567
    """
    u, g, w, k = _groups(speed, materials, load, ellipticity)
    return (2.69 * u**0.67 * g**0.53 * w**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k)))[()]


def _groups(speed, materials, load, ellipticity):
    return (
        _array("speed", speed, "a speed parameter U >= 0 [-]", zero_ok=True),
        _array("materials", materials, "a materials parameter G > 0 [-]"),
        _array("load", load, "a load parameter W > 0 [-]"),
        _array("ellipticity", ellipticity, "an ellipticity k > 0 [-]"),
    )


def hamrock_dowson_film(
    load,
    entrainment_speed,
    rx,
    ry,
    effective_modulus,
    viscosity,
    pressure_viscosity_coefficient,
    kind: Kind = "central",
    ellipticity_method: EllipticityMethod = "hamrock_dowson",
):
    """Isothermal, fully flooded EHL film thickness h = H R_x of a point contact [m].

    Hamrock & Dowson (1977): ``kind="minimum"`` is Part III's H_min, ``kind="central"``
    Part IV's H_c; U, G, W as in :func:`dimensionless_groups`. Vectorised: all array
    arguments broadcast together.

    Parameters
    ----------
    load : float or array
        Normal contact load w [N], > 0.
    entrainment_speed : float or array
        Mean rolling speed u [m/s], >= 0.
    rx, ry : float or array
        Effective radii, rolling and transverse [m], R_y >= R_x.
    effective_modulus : float or array
        E' [Pa].
    viscosity : float or array
        eta_0 at the inlet temperature [Pa s].
    pressure_viscosity_coefficient : float or array
        alpha [1/Pa].
    kind : {"central", "minimum"}
        Which film thickness [-].
    ellipticity_method : {"hamrock_dowson", "exact", "hamrock_brewe"}
        How k is obtained (:func:`contact_ellipticity`) [-].

    Examples
    --------
    >>> h = hamrock_dowson_film(500.0, 5.0, 4e-3, 0.1, 2.286e11, 0.05, 2e-8, "minimum")
    >>> round(float(h) * 1e6, 3)
    0.54
    """
    if kind not in KINDS:
        raise InputError("kind", kind, "'central' or 'minimum'")
    rx, ry = _radii(rx, ry)
    k = contact_ellipticity(rx, ry, ellipticity_method)
    groups = dimensionless_groups(
        load, entrainment_speed, rx, effective_modulus, viscosity, pressure_viscosity_coefficient
    )
    fit = hamrock_dowson_minimum if kind == "minimum" else hamrock_dowson_central
    return (fit(*groups, k) * rx)[()]


def seed004_film_thickness(
    load,
    entrainment_speed,
    rx,
    ry,
    effective_modulus,
    viscosity,
    pressure_viscosity_coefficient,
    radius_exponent: float = 0.956,
):
    """Film thickness of seed 004, eq. (6), as printed [m if radius_exponent = 0.466].

    h = 3.06 R_x^p E'^-0.117 (eta_0 u)^0.68 alpha^0.49 w^-0.073 {1 - exp[-3.36 R_y/R_x]}
    in this module's notation (R_x rolling, R_y transverse; the seed calls the rolling
    radius R_y), with p = 0.956 as printed.

    Doubtful as printed: with p = 0.956 the right-hand side has the dimension
    m^1.49 (the powers of Pa cancel; those of m need p = 0.466, the value the
    Hamrock-Dowson minimum film gives in dimensional form, h = 3.63 R_x^0.466
    E'^-0.117 (eta_0 u)^0.68 alpha^0.49 w^-0.073 (1 - exp(-0.68 k))), so its value
    depends on the length unit. In SI it gives about 1/20 of the Hamrock-Dowson film
    for the seed's own 6205 case; with ``radius_exponent=0.466`` it gives 0.84 of it
    (3.06 / 3.63, the ellipticity factors being ~1 for ball-raceway contacts). Use
    :func:`hamrock_dowson_film` unless reproducing the seed.

    Parameters
    ----------
    load : float or array
        Contact force N [N], > 0.
    entrainment_speed : float or array
        u [m/s], >= 0.
    rx, ry : float or array
        Effective radii, rolling (the seed's R_y) and transverse (the seed's R_x) [m].
    effective_modulus : float or array
        E_eff, taken as E' [Pa].
    viscosity : float or array
        eta_0 [Pa s].
    pressure_viscosity_coefficient : float or array
        alpha [1/Pa].
    radius_exponent : float
        p [-]: 0.956 as printed, 0.466 for a dimensionally consistent formula.

    Examples
    --------
    >>> h = seed004_film_thickness(300.0, 2.35, 3.18e-3, 0.104, 2.286e11, 0.04, 1.48e-8,
    ...                            radius_exponent=0.466)
    >>> round(float(h) * 1e6, 3)
    0.189
    """
    rx = _array("rx", rx, "positive effective radii R_x [m]")
    ry = _array("ry", ry, "positive effective radii R_y [m]")
    w = _array("load", load, "positive contact loads [N]")
    u = _array(
        "entrainment_speed", entrainment_speed, "entrainment speeds >= 0 [m/s]", zero_ok=True
    )
    e = _array("effective_modulus", effective_modulus, "a positive modulus [Pa]")
    eta = _array("viscosity", viscosity, "a positive viscosity [Pa s]")
    alpha = _array(
        "pressure_viscosity_coefficient",
        pressure_viscosity_coefficient,
        "a positive coefficient alpha [1/Pa]",
    )
    p = float(radius_exponent)
    return (
        3.06
        * rx**p
        * e**-0.117
        * (eta * u) ** 0.68
        * alpha**0.49
        * w**-0.073
        * (1.0 - np.exp(-3.36 * ry / rx))
    )[()]


def rolling_entrainment_speed(
    pitch_diameter, ball_diameter, inner_speed, outer_speed=0.0, contact_angle=0.0
):
    """Entrainment (rolling) speed of a ball-raceway contact in pure rolling [m/s].

    u = (d_m / 4) (1 - gamma^2) |omega_i - omega_o|, gamma = D_w cos(alpha) / d_m;
    the same at the inner and the outer contact (Harris & Kotzalas 2007, ch. 7: the
    race surface speed relative to the cage, (omega_i - omega_c) d_m (1 - gamma) / 2,
    equals the ball surface speed; both are u).

    Parameters
    ----------
    pitch_diameter : float or array
        d_m [m].
    ball_diameter : float or array
        D_w [m].
    inner_speed : float or array
        omega_i, inner ring [rad/s].
    outer_speed : float or array
        omega_o, outer ring [rad/s].
    contact_angle : float or array
        alpha [rad].

    Examples
    --------
    >>> round(float(rolling_entrainment_speed(39e-3, 8e-3, 2400 * np.pi / 30)), 4)
    2.3473
    """
    dm = _array("pitch_diameter", pitch_diameter, "a positive pitch diameter [m]")
    dw = _array("ball_diameter", ball_diameter, "a positive ball diameter [m]")
    if np.any(dw >= dm):
        raise InputError("ball_diameter", ball_diameter, "less than the pitch diameter [m]")
    wi = np.asarray(inner_speed, dtype=float)
    wo = np.asarray(outer_speed, dtype=float)
    if np.any(~np.isfinite(wi)) or np.any(~np.isfinite(wo)):
        raise InputError(
            "inner_speed, outer_speed", (inner_speed, outer_speed), "finite ring speeds [rad/s]"
        )
    gamma = dw * np.cos(contact_angle) / dm
    return (0.25 * dm * (1.0 - gamma**2) * np.abs(wi - wo))[()]


def entrainment_speed(bearing, shaft_speed, contact_angle=None):
    """Pure-rolling entrainment speed of the ball-raceway contacts of a bearing [m/s].

    :func:`rolling_entrainment_speed` with the bearing's d_m, D_w and contact angle; only
    the relative speed of the rings matters, so it does not matter which ring turns.

    Parameters
    ----------
    bearing : BallBearing
        The bearing geometry [-].
    shaft_speed : float or array
        Speed of the rotating ring relative to the other [rad/s].
    contact_angle : float or None
        Operating contact angle [rad]; None means the bearing's nominal one.
    """
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    return rolling_entrainment_speed(
        bearing.pitch_diameter, bearing.ball_diameter, shaft_speed, 0.0, alpha
    )


def film_thickness(
    bearing,
    lubricant,
    ball_load,
    shaft_speed,
    race,
    temperature=None,
    contact_angle=None,
    kind: Kind = "central",
    ellipticity_method: EllipticityMethod = "hamrock_dowson",
):
    """Hamrock-Dowson film thickness at one raceway contact of a ball bearing [m].

    Combines :meth:`BallBearing.contact_radii`, :func:`entrainment_speed`,
    :func:`bearinglab.materials.effective_modulus` (ball against ring material),
    :meth:`Lubricant.viscosity` at the inlet ``temperature`` (alpha held constant) and
    :func:`hamrock_dowson_film`. Vectorised over ``ball_load`` and ``shaft_speed``.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and materials [-].
    lubricant : Lubricant
        The lubricant (the base oil for a grease) [-].
    ball_load : float or array
        Normal load Q of the ball on that raceway [N], > 0.
    shaft_speed : float or array
        Speed of the rotating ring relative to the other [rad/s].
    race : {"inner", "outer"}
        Which raceway contact [-].
    temperature : float, array or None
        Inlet (bulk lubricant) temperature [K]; None means the lubricant's reference.
    contact_angle : float or None
        Operating contact angle [rad]; None means the bearing's nominal one.
    kind : {"central", "minimum"}
        Which film thickness [-].
    ellipticity_method : {"hamrock_dowson", "exact", "hamrock_brewe"}
        How k is obtained [-].

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> from bearinglab.lubrication.lubricant import ISO_VG68
    >>> b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
    >>> h = film_thickness(b, ISO_VG68, 500.0, 3000 * np.pi / 30, "inner", kind="minimum")
    >>> round(float(h) * 1e6, 3)
    0.42
    """
    if race not in ("inner", "outer"):
        raise InputError("race", race, "'inner' or 'outer'")
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    rx, ry = bearing.contact_radii(race, alpha)
    e_prime = _effective_modulus(bearing.ball_material, bearing.ring_material)
    u = entrainment_speed(bearing, shaft_speed, alpha)
    eta = lubricant.viscosity(temperature)
    return hamrock_dowson_film(
        ball_load,
        u,
        rx,
        ry,
        e_prime,
        eta,
        lubricant.pressure_viscosity_coefficient,
        kind,
        ellipticity_method,
    )
