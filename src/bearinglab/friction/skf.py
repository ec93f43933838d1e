"""The SKF four-component model of the frictional moment (layer 1).

Source: SKF, *Rolling bearings* (catalogue 10000 EN), chapter "Friction", section "The SKF
model for calculating the frictional moment" (the same model, introduced as "the new SKF
model", is in the SKF General Catalogue 6000 EN and on skf.com):

    M = phi_ish phi_rs M_rr + M_sl + M_seal + M_drag

- rolling:  M_rr = G_rr (nu n)^0.6
- sliding:  M_sl = G_sl mu_sl,  mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,
  phi_bl = 1 / e^(2.6e-8 (n nu)^1.4 d_m), mu_bl ~ 0.15 (additive package), mu_EHL = 0.05
  (mineral oil), 0.04 (synthetic oil), 0.1 (transmission fluid) for ball bearings
  (0.02 cylindrical, 0.002 tapered roller bearings).
- geometric and load variables G_rr, G_sl by bearing type (catalogue Table 2a, radial
  bearings): :mod:`.skf_loads`.
- inlet shear heating: phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64).
- kinematic replenishment / starvation: phi_rs = 1 / e^(K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))),
  K_rs = 3e-8 (low-level oil bath, oil jet), 6e-8 (grease, oil-air); K_Z = 3.1 (deep-groove),
  4.4 (single-row angular-contact ball bearings).
- seals: M_seal = K_S1 d_s^beta + K_S2 (d_s the seal counterface diameter).

The constants (mu, K_rs, K_Z, the per-series geometry constants) and the checks that turn
SI inputs into SKF's units are in :mod:`.skf_constants`. The model works in SKF's
engineering units: n [r/min], nu [mm^2/s] (operating viscosity of the oil or the grease's
base oil), d, D, d_m = 0.5 (d + D) [mm] (the bearing MEAN diameter, not the ball pitch
diameter), F [N], M [N mm]. The functions here take SI (rad/s, m^2/s, m, N) and return
N m; they convert at the edge.

What was checked against stored copies of the source, and what was not
(see docs/capabilities/friction.md):

- checked: the total-moment structure (catalogue 10000 EN, as stored at yumpu.com,
  document 55668573 page 106); M_sl, mu_sl, phi_bl, mu_bl = 0.15 and the mu_EHL values
  (same document, page 105); d_m = 0.5 (d + D) and the symbols of phi_ish (skf.com,
  "Inlet shear heating reduction factor").
- not checked against a stored primary copy (the pages with these numbers are images or
  were not stored): the constants of phi_ish (1.84e-9, 1.28, 0.64) and of phi_rs, and
  those of :mod:`.skf_constants` it names; every result says so
  (``SkfGeometryConstants.verified``).
- not shipped: the seal constants K_S1, K_S2, beta (catalogue tables not available in
  stored sources): the caller supplies them. Drag losses in an oil bath (M_drag) need the
  catalogue's diagram of the oil-level variable V_M, which is not available as numbers:
  M_drag is a caller-supplied moment, zero by default.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..errors import InputError, bore_below_outside
from ..units import rpm_to_rad_s  # noqa: F401 - used by the doctests
from .skf_constants import (  # noqa: F401 - deep_groove_constants: doctests
    K_RS,
    K_Z,
    MM2_S_PER_M2_S,
    MU_BL,
    MU_EHL,
    SKF_BEARING_TYPES,
    SkfGeometryConstants,
    _array,
    _mm,
    _mm2_s,
    _out,
    _rpm,
    deep_groove_constants,
)
from .skf_loads import (
    angular_contact_load_variables,
    cylindrical_roller_load_variables,
    deep_groove_load_variables,
    tapered_roller_load_variables,
)


# ------------------------------------------------------------------ lubrication condition
def viscosity_ratio(viscosity, shaft_speed, mean_diameter) -> float:
    """Viscosity ratio kappa = nu / nu_1 (ISO 281) [-].

    nu_1 is ISO 281's rated viscosity, :func:`bearinglab.life.rated_viscosity`
    (45000 n^-0.83 d_m^-0.5 below 1000 r/min, else 4500 n^-0.5 d_m^-0.5, in mm^2/s with n
    in r/min and d_m in mm), here with SKF's mean diameter d_m = 0.5 (d + D).

    Parameters
    ----------
    viscosity : float
        Operating kinematic viscosity nu [m^2/s].
    shaft_speed : float
        [rad/s], > 0.
    mean_diameter : float
        d_m = 0.5 (d + D) [m].

    Examples
    --------
    >>> round(viscosity_ratio(20e-6, rpm_to_rad_s(3000), 0.0385), 3)
    1.51
    """
    from ..life import rated_viscosity

    nu = float(_mm2_s(viscosity)) / MM2_S_PER_M2_S
    return nu / rated_viscosity(float(shaft_speed), float(mean_diameter))


def inlet_shear_heating_factor(shaft_speed, mean_diameter, viscosity):
    """phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64) [-] (n r/min, d_m mm, nu mm^2/s).

    Parameters
    ----------
    shaft_speed : float or array
        [rad/s].
    mean_diameter : float or array
        d_m = 0.5 (d + D) [m].
    viscosity : float or array
        Operating viscosity nu [m^2/s].

    Examples
    --------
    >>> round(float(inlet_shear_heating_factor(rpm_to_rad_s(3000), 0.0385, 20e-6)), 4)
    0.9636
    """
    n = _rpm(shaft_speed)
    dm = _mm("mean_diameter", mean_diameter)
    nu = _mm2_s(viscosity)
    return _out(1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64))


def replenishment_factor(shaft_speed, viscosity, bore, outside_diameter, k_rs, k_z):
    """phi_rs = 1 / e^(K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))) [-] (SKF units inside).

    Parameters
    ----------
    shaft_speed : float or array
        [rad/s].
    viscosity : float or array
        Operating viscosity nu [m^2/s].
    bore, outside_diameter : float or array
        d, D [m], D > d.
    k_rs : float
        Replenishment/starvation constant K_rs [-] (:data:`K_RS`).
    k_z : float
        Bearing-type geometry constant K_Z [-] (:data:`K_Z`).

    Examples
    --------
    >>> round(float(replenishment_factor(rpm_to_rad_s(3000), 20e-6, 0.025, 0.052,
    ...                                  6e-8, 3.1)), 4)
    0.9357
    """
    n = _rpm(shaft_speed)
    nu = _mm2_s(viscosity)
    d = _mm("bore", bore)
    big_d = _mm("outside_diameter", outside_diameter)
    if np.any(big_d <= d):
        raise InputError("outside_diameter", outside_diameter, "more than the bore [m]")
    krs = float(_array("k_rs", k_rs, "-", positive=True))
    kz = float(_array("k_z", k_z, "-", positive=True))
    return _out(np.exp(-krs * nu * n * (d + big_d) * np.sqrt(kz / (2.0 * (big_d - d)))))


def sliding_weighting_factor(shaft_speed, viscosity, mean_diameter):
    """phi_bl = 1 / e^(2.6e-8 (n nu)^1.4 d_m) [-]: 1 at rest (boundary), -> 0 in full film.

    Parameters
    ----------
    shaft_speed : float or array
        [rad/s].
    viscosity : float or array
        [m^2/s].
    mean_diameter : float or array
        d_m = 0.5 (d + D) [m].

    Examples
    --------
    >>> sliding_weighting_factor(0.0, 20e-6, 0.0385)
    1.0
    """
    n = _rpm(shaft_speed)
    nu = _mm2_s(viscosity)
    dm = _mm("mean_diameter", mean_diameter)
    return _out(np.exp(-2.6e-8 * (n * nu) ** 1.4 * dm))


def sliding_friction_coefficient(weighting_factor, mu_bl=MU_BL, mu_ehl=MU_EHL["mineral"]):
    """mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL [-].

    Parameters
    ----------
    weighting_factor : float or array
        phi_bl [-], in [0, 1].
    mu_bl : float
        Boundary coefficient [-] (0.15 generally).
    mu_ehl : float
        Full-film coefficient [-] (:data:`MU_EHL`).

    Examples
    --------
    >>> sliding_friction_coefficient(1.0)
    0.15
    """
    w = _array("weighting_factor", weighting_factor, "-")
    if np.any(w > 1):
        raise InputError("weighting_factor", weighting_factor, "values in [0, 1]")
    bl = float(_array("mu_bl", mu_bl, "-"))
    ehl = float(_array("mu_ehl", mu_ehl, "-"))
    return _out(w * bl + (1.0 - w) * ehl)


def seal_moment(k_s1, k_s2, beta, seal_diameter):
    """M_seal = K_S1 d_s^beta + K_S2 [N m] (SKF units inside: d_s mm, M N mm).

    The constants come from the maker's table for the seal type and size (not shipped:
    see the module docstring); that table says whether the value is per bearing.

    Parameters
    ----------
    k_s1, k_s2 : float
        Seal constants [SKF units], >= 0.
    beta : float
        Exponent [-], >= 0.
    seal_diameter : float
        Seal counterface diameter d_s [m].

    Examples
    --------
    >>> round(seal_moment(0.02, 2.0, 2.25, 0.0313) * 1e3, 3)
    48.345
    """
    ks1 = float(_array("k_s1", k_s1, "SKF units"))
    ks2 = float(_array("k_s2", k_s2, "SKF units"))
    b = float(_array("beta", beta, "-"))
    ds = float(_mm("seal_diameter", seal_diameter))
    return (ks1 * ds**b + ks2) * 1e-3


class SkfMoment(NamedTuple):
    """Components of the SKF frictional moment [N m] and the factors used [-]."""

    rolling: float  # phi_ish phi_rs M_rr [N m]
    sliding: float  # M_sl [N m]
    seal: float  # M_seal [N m]
    drag: float  # M_drag [N m]
    inlet_shear_factor: float
    replenishment_factor: float
    sliding_weighting_factor: float
    sliding_friction_coefficient: float
    rolling_variable: float  # G_rr [SKF units]
    sliding_variable: float  # G_sl [SKF units]

    @property
    def total(self) -> float:
        """M = phi_ish phi_rs M_rr + M_sl + M_seal + M_drag [N m]."""
        return self.rolling + self.sliding + self.seal + self.drag


def skf_frictional_moment(
    bearing_type: str,
    bore: float,
    outside_diameter: float,
    radial_load: float,
    axial_load: float,
    shaft_speed: float,
    viscosity: float,
    constants: SkfGeometryConstants,
    *,
    static_load_rating: float | None = None,
    k_rs: float = K_RS["grease"],
    k_z: float | None = None,
    mu_bl: float = MU_BL,
    mu_ehl: float = MU_EHL["mineral"],
    seal: float = 0.0,
    drag: float = 0.0,
    axial_factor: float | None = None,
) -> SkfMoment:
    """Total frictional moment of a ball or roller bearing by the SKF model [N m,
    components].

    Parameters
    ----------
    bearing_type : str
        ``"radial_ball"`` (deep-groove), ``"angular_contact_ball"``,
        ``"four_point_contact_ball"``, ``"cylindrical_roller"`` or ``"tapered_roller"``
        [-].
    bore, outside_diameter : float
        d, D [m]; d_m = 0.5 (d + D).
    radial_load, axial_load : float
        F_r, F_a [N], >= 0.
    shaft_speed : float
        Speed of the rotating ring [rad/s], >= 0.
    viscosity : float
        Operating kinematic viscosity of the oil or the grease's base oil [m^2/s].
    constants : SkfGeometryConstants
        Geometry constants of the bearing's series.
    static_load_rating : float or None
        C_0 [N]; needed for a deep-groove bearing with F_a > 0.
    k_rs : float
        K_rs [-] (:data:`K_RS`).
    k_z : float or None
        K_Z [-]; None takes :data:`K_Z` of the type.
    mu_bl, mu_ehl : float
        Sliding friction coefficients [-].
    seal : float
        Seal moment M_seal [N m] (:func:`seal_moment`), >= 0.
    drag : float
        Drag moment M_drag [N m], >= 0 (not modelled here; 0 for grease, oil-air, oil jet).
    axial_factor : float or None
        Y of a tapered roller bearing (needed with F_a > 0) [-].

    Examples
    --------
    >>> m = skf_frictional_moment("radial_ball", 0.025, 0.052, 1000.0, 0.0,
    ...                           rpm_to_rad_s(3000), 20e-6,
    ...                           deep_groove_constants("62"))
    >>> round(m.total * 1e3, 2)
    20.16
    """
    if bearing_type not in SKF_BEARING_TYPES:
        raise InputError(
            "bearing_type",
            bearing_type,
            "one of " + ", ".join(SKF_BEARING_TYPES),
            "the SKF model is implemented for these types",
        )
    if not isinstance(constants, SkfGeometryConstants):
        raise InputError("constants", constants, "an SkfGeometryConstants")
    d = float(_array("bore", bore, "m", positive=True))
    big_d = float(_array("outside_diameter", outside_diameter, "m", positive=True))
    bore_below_outside(d, big_d)
    if k_z is None:
        if bearing_type not in K_Z:
            raise InputError(
                "k_z",
                None,
                "the geometry constant K_Z of this bearing type",
                f"no K_Z is shipped for {bearing_type}",
            )
        k_z = K_Z[bearing_type]
    seal = float(_array("seal", seal, "N m"))
    drag = float(_array("drag", drag, "N m"))
    dm = 0.5 * (d + big_d)
    if bearing_type == "radial_ball":
        g_rr, g_sl = deep_groove_load_variables(
            dm, radial_load, axial_load, constants, static_load_rating
        )
    elif bearing_type == "cylindrical_roller":
        g_rr, g_sl = cylindrical_roller_load_variables(dm, radial_load, axial_load, constants)
    elif bearing_type == "tapered_roller":
        if axial_factor is None:
            if float(_array("axial_load", axial_load, "N")) > 0:
                raise InputError(
                    "axial_factor",
                    None,
                    "the axial load factor Y of the tapered bearing when F_a > 0",
                )
            axial_factor = 0.0
        g_rr, g_sl = tapered_roller_load_variables(
            dm, radial_load, axial_load, axial_factor, constants
        )
    else:
        g_rr, g_sl = angular_contact_load_variables(
            dm, radial_load, axial_load, shaft_speed, constants
        )
    n = float(_rpm(shaft_speed))
    nu = float(_mm2_s(viscosity))
    ish = float(inlet_shear_heating_factor(shaft_speed, dm, viscosity))
    rs = float(replenishment_factor(shaft_speed, viscosity, d, big_d, k_rs, k_z))
    bl = float(sliding_weighting_factor(shaft_speed, viscosity, dm))
    mu_sl = float(sliding_friction_coefficient(bl, mu_bl, mu_ehl))
    m_rr = g_rr * (nu * n) ** 0.6 * 1e-3
    m_sl = g_sl * mu_sl * 1e-3
    return SkfMoment(ish * rs * m_rr, m_sl, seal, drag, ish, rs, bl, mu_sl, g_rr, g_sl)
