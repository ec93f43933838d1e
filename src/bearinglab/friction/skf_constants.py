"""The constants of the SKF frictional-moment model and its units (layer 1).

Source: SKF, *Rolling bearings* (catalogue 10000 EN), chapter "Friction", section "The SKF
model for calculating the frictional moment" (:mod:`.skf` has the model itself, and
:mod:`.skf_loads` its geometric and load variables G_rr, G_sl):

- the sliding friction coefficients mu_bl ~ 0.15 (additive package) and mu_EHL = 0.05
  (mineral oil), 0.04 (synthetic oil), 0.1 (transmission fluid) for ball bearings, 0.02
  cylindrical, 0.002 tapered roller bearings (:data:`MU_BL`, :data:`MU_EHL`,
  :data:`MU_EHL_ROLLER`);
- the kinematic replenishment / starvation constants K_rs = 3e-8 (low-level oil bath, oil
  jet), 6e-8 (grease, oil-air) and K_Z = 3.1 (deep-groove), 4.4 (single-row
  angular-contact ball bearings) (:data:`K_RS`, :data:`K_Z`);
- the per-series geometry constants R1, R2, S1, S2 (R3, S3 of angular-contact bearings)
  of the G_rr and G_sl forms (:class:`SkfGeometryConstants`, the deep-groove series'
  :data:`DEEP_GROOVE_CONSTANTS`).

The model works in SKF's engineering units: n [r/min], nu [mm^2/s] (operating viscosity of
the oil or the grease's base oil), d, D, d_m = 0.5 (d + D) [mm] (the bearing MEAN
diameter, not the ball pitch diameter), F [N], M [N mm]. Its functions take SI (rad/s,
m^2/s, m, N); the checks here refuse a value out of range naming it and convert it at
the edge.

What was checked against stored copies of the source, and what was not
(see docs/capabilities/friction.md):

- checked: mu_bl = 0.15 and the mu_EHL values (catalogue 10000 EN as stored at yumpu.com,
  document 55668573 page 105).
- not checked against a stored primary copy (the pages with these numbers are images or
  were not stored): the K_rs and K_Z values, and the per-series geometry constants R1,
  R2, S1, S2 of :data:`DEEP_GROOVE_CONSTANTS`. They are SKF's published values as given
  in the task brief and as transcribed in independent public implementations of the
  model, which agree with each other; treat them as secondary until checked against the
  catalogue. Every result says so (``SkfGeometryConstants.verified``).
- not shipped: angular-contact geometry constants (R1..R3, S1..S3 by series) and the
  seal constants K_S1, K_S2, beta (catalogue tables not available in stored sources):
  the caller supplies them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, positive_number
from ..units import rad_s_to_rpm

#: Conversions: SI -> SKF engineering units.
RPM_PER_RAD_S = rad_s_to_rpm(1.0)
MM2_S_PER_M2_S = 1e6
MM_PER_M = 1e3
#: Boundary-layer sliding friction coefficient mu_bl, "generally ~ 0.15" [-].
MU_BL = 0.15
#: mu_EHL of ball bearings (catalogue: "other bearings") by lubricant kind [-].
MU_EHL = {"mineral": 0.05, "synthetic": 0.04, "transmission-fluid": 0.1}
#: K_rs by lubrication method: 3e-8 low-level oil bath and oil jet, 6e-8 grease and
#: oil-air [-] (secondary, see the module docstring).
K_RS = {"grease": 6e-8, "oil-air": 6e-8, "oil-jet": 3e-8, "low-oil-bath": 3e-8}
#: K_Z, the bearing-type geometry constant of phi_rs [-] (secondary). The roller values
#: (single-row cylindrical 5.1, single-row tapered 6) are SKF's as recalled, not checked
#: against a stored copy of the catalogue's table: results that use them say so.
K_Z = {
    "radial_ball": 3.1,
    "angular_contact_ball": 4.4,
    "cylindrical_roller": 5.1,
    "tapered_roller": 6.0,
}
#: K_Z values not checked against a stored copy (the result warns).
K_Z_UNVERIFIED = ("cylindrical_roller", "tapered_roller")
#: mu_EHL of roller bearings, whatever the oil (catalogue 10000 EN p. 105: 0.02 cylindrical,
#: 0.002 tapered roller bearings) [-].
MU_EHL_ROLLER = {"cylindrical_roller": 0.02, "tapered_roller": 0.002}
#: Types the SKF model of this module covers.
SKF_BEARING_TYPES = (
    "radial_ball",
    "angular_contact_ball",
    "four_point_contact_ball",
    "cylindrical_roller",
    "tapered_roller",
)
#: Of them, roller bearings (their G_rr, G_sl forms of catalogue Table 2a).
SKF_ROLLER_TYPES = ("cylindrical_roller", "tapered_roller")

SKF_SOURCE = (
    "SKF Rolling bearings, catalogue 10000 EN, 'The SKF model for calculating "
    "the frictional moment'"
)
_SECONDARY = (
    "SKF catalogue 10000 EN, geometry constants for deep groove ball bearings by "
    "series; transcribed from secondary public sources (not checked against a "
    "stored copy of the catalogue table)"
)


@dataclass(frozen=True)
class SkfGeometryConstants:
    """Geometry constants of the SKF model for one bearing series.

    Parameters
    ----------
    r1, r2 : float
        Rolling-moment constants R1, R2 [SKF units: M_rr in N mm with d_m in mm, F in N].
    s1, s2 : float
        Sliding-moment constants S1, S2 [SKF units].
    r3, s3 : float or None
        Centrifugal-load constants of angular-contact bearings (F_g = R3 d_m^4 n^2,
        S3 d_m^4 n^2) [SKF units]; None for deep-groove bearings.
    source : str
        Where the numbers come from [-].
    verified : bool
        True only if checked against a stored copy of the primary source [-].

    Examples
    --------
    >>> SkfGeometryConstants(3.9e-7, 1.7, 3.23e-3, 36.5).r3 is None
    True
    """

    r1: float
    r2: float
    s1: float
    s2: float
    r3: float | None = None
    s3: float | None = None
    source: str = "user"
    verified: bool = False

    def __post_init__(self) -> None:
        for name in ("r1", "r2", "s1", "s2", "r3", "s3"):
            v = getattr(self, name)
            if v is None and name in ("r3", "s3"):
                continue
            positive_number(name, v, "a finite constant >= 0 (SKF units)", zero=True)


def _dgbb(r1, r2, s1, s2):
    return SkfGeometryConstants(r1, r2, s1, s2, source=_SECONDARY, verified=False)


#: Deep-groove ball bearing geometry constants by ISO series (SKF catalogue table of
#: geometry constants; secondary transcription, see the module docstring). 42 and 43 are
#: double-row deep-groove bearings.
DEEP_GROOVE_CONSTANTS: dict[str, SkfGeometryConstants] = {
    **dict.fromkeys(("42", "43"), _dgbb(5.4e-7, 0.96, 3.00e-3, 40.0)),
    **dict.fromkeys(("60", "630"), _dgbb(4.1e-7, 1.7, 3.73e-3, 14.6)),
    **dict.fromkeys(("62", "622"), _dgbb(3.9e-7, 1.7, 3.23e-3, 36.5)),
    **dict.fromkeys(("63", "623"), _dgbb(3.7e-7, 1.7, 2.84e-3, 92.8)),
    "64": _dgbb(3.6e-7, 1.7, 2.43e-3, 198.0),
    **dict.fromkeys(("160", "161"), _dgbb(4.3e-7, 1.7, 4.63e-3, 4.25)),
    **dict.fromkeys(("617", "618", "628", "637", "638"), _dgbb(4.7e-7, 1.7, 6.50e-3, 0.78)),
    **dict.fromkeys(("619", "639"), _dgbb(4.3e-7, 1.7, 4.75e-3, 3.6)),
}


def deep_groove_constants(series: str) -> SkfGeometryConstants:
    """Geometry constants of a deep-groove ball bearing series (``"62"``, ``"618"``) [-].

    Parameters
    ----------
    series : str
        ISO series of the designation (:attr:`Designation.series`) [-].

    Examples
    --------
    >>> deep_groove_constants("62").r1
    3.9e-07
    """
    if series not in DEEP_GROOVE_CONSTANTS:
        raise InputError(
            "series",
            series,
            "a deep-groove series with SKF constants: " + ", ".join(DEEP_GROOVE_CONSTANTS),
            "give the constants R1, R2, S1, S2 (constants)",
        )
    return DEEP_GROOVE_CONSTANTS[series]


# ------------------------------------------------------------------ input checks
def _out(a):
    """A 0-d result as a Python float, an array as it is."""
    a = np.asarray(a, dtype=float)
    return float(a) if a.ndim == 0 else a


def _array(name: str, value, unit: str, positive: bool = False) -> np.ndarray:
    a = np.asarray(value, dtype=float)
    bad = (a <= 0) if positive else (a < 0)
    if a.size == 0 or np.any(~np.isfinite(a)) or np.any(bad):
        raise InputError(name, value, f"finite values {'>' if positive else '>='} 0 [{unit}]")
    return a


def _rpm(shaft_speed) -> np.ndarray:
    return _array("shaft_speed", shaft_speed, "rad/s") * RPM_PER_RAD_S


def _mm2_s(viscosity) -> np.ndarray:
    return _array("viscosity", viscosity, "m^2/s", positive=True) * MM2_S_PER_M2_S


def _mm(name: str, value) -> np.ndarray:
    return _array(name, value, "m", positive=True) * MM_PER_M
