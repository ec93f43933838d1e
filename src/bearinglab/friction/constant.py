"""Constant-coefficient friction model of seed 003 (layer 1) and its equivalent load.

Source: seed 003 (compilation of web articles), section "Расчет трения подшипника --
частота вибрации подшипника" (bearing friction), a translation of an American Roller
Bearing Company article:

- Table III (seed lines 1087-1097) lists the coefficient of friction mu by bearing type;
  :data:`SEED003_COEFFICIENTS` holds it as printed. The coefficients "are based on a
  reference lubricant viscosity of 20 cSt / 100 SUS at the bearing's operating
  temperature" (line 1101); they do not depend on speed or viscosity.
- Friction force F = P mu (line 1099). The torque formula itself is an image that the
  compilation lost, but its symbol list survives (lines 1105-1111): "P = equivalent
  bearing load, mu = coefficient of friction, d_m (дм) = pitch diameter of the bearing".
  The torque is therefore M = mu P d_m / 2 with d_m the PITCH (mean) diameter -- not the
  bore d that SKF's and Koyo's catalogue versions of this estimate use
  (M = 0.5 mu P d). bearinglab follows the seed: :func:`constant_coefficient_torque`.
- Power loss: the seed says only that it follows from the torque and the speed
  (line 1113); N = M omega (:func:`power_loss`).

Equivalent load P: the seed does not say how P is formed. The analyses
(:func:`bearinglab.friction.bearing_friction`, the ``friction`` command) use ISO 281's
dynamic equivalent load from :func:`bearinglab.ratings.equivalent_dynamic_load` for ball
bearings (P = F_r with no axial load); for other types the caller supplies P.

All functions take and return SI units (N, m, rad/s, N m, W) and broadcast over arrays.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

#: Coefficient of friction mu by bearing type, seed 003 Table III (lines 1087-1097), as
#: printed. Keys: ``radial_ball`` (радиальный шарикоподшипник), ``angular_contact_ball``
#: (радиально-упорный), ``cylindrical_roller`` (with a cage, сепаратор),
#: ``cylindrical_roller_full_complement`` (полный комп.), ``tapered_roller``,
#: ``spherical_roller``, ``thrust_ball``, ``cylindrical_roller_thrust``,
#: ``tapered_roller_thrust`` (with a cage, клетка), ``tapered_roller_thrust_full_complement``.
SEED003_COEFFICIENTS: dict[str, float] = {
    "radial_ball": 0.0015,
    "angular_contact_ball": 0.0020,
    "cylindrical_roller": 0.0010,
    "cylindrical_roller_full_complement": 0.0020,
    "tapered_roller": 0.0020,
    "spherical_roller": 0.0020,
    "thrust_ball": 0.0015,
    "cylindrical_roller_thrust": 0.0050,
    "tapered_roller_thrust": 0.0020,
    "tapered_roller_thrust_full_complement": 0.0050,
}

#: Where the coefficients and the torque formula come from.
SEED003_SOURCE = (
    "seed 003, bearing friction section: Table III (coefficients, lines "
    "1087-1097), M = mu P d_m / 2 with d_m the pitch diameter (symbols, lines "
    "1105-1111); coefficients for 20 cSt at operating temperature (line 1101)"
)

#: Cylindrical-roller design prefixes that mean a full complement (no cage): SKF/ISO NCF,
#: NJG (single row) and NNC, NNCF, NNCL (double row).
FULL_COMPLEMENT_PREFIXES = ("NCF", "NJG", "NNC", "NNCF", "NNCL")


def _out(a):
    """A 0-d result as a Python float, an array as it is."""
    a = np.asarray(a, dtype=float)
    return float(a) if a.ndim == 0 else a


def _nonnegative(name: str, value, unit: str) -> np.ndarray:
    a = np.asarray(value, dtype=float)
    if a.size == 0 or np.any(~np.isfinite(a)) or np.any(a < 0):
        raise InputError(name, value, f"finite values >= 0 [{unit}]")
    return a


def _positive(name: str, value, unit: str) -> np.ndarray:
    a = np.asarray(value, dtype=float)
    if a.size == 0 or np.any(~np.isfinite(a)) or np.any(a <= 0):
        raise InputError(name, value, f"finite values > 0 [{unit}]")
    return a


def friction_type_of(bearing_type: str, design_variant: str | None = None) -> str:
    """The seed-003 friction type (a key of :data:`SEED003_COEFFICIENTS`) of a bearing.

    ``radial_ball``, ``angular_contact_ball``, ``tapered_roller``, ``spherical_roller`` and
    ``thrust_ball`` map to themselves; ``cylindrical_roller`` maps to the full-complement
    row when the design prefix is one of :data:`FULL_COMPLEMENT_PREFIXES`, else to the row
    with a cage. Types that the seed's table does not name (self-aligning ball,
    four-point contact, needle, spiral roller, and ``thrust_roller``, which may be
    cylindrical, tapered or spherical) raise an :class:`InputError` asking for the type.

    Parameters
    ----------
    bearing_type : str
        A type of :data:`bearinglab.designation.BEARING_TYPES` [-].
    design_variant : str or None
        ISO type prefix or GOST design variant of the designation (``"NCF"``) [-].

    Examples
    --------
    >>> friction_type_of("cylindrical_roller", "NU"), friction_type_of("cylindrical_roller", "NCF")
    ('cylindrical_roller', 'cylindrical_roller_full_complement')
    """
    if bearing_type == "cylindrical_roller":
        variant = (design_variant or "").upper()
        if variant in FULL_COMPLEMENT_PREFIXES:
            return "cylindrical_roller_full_complement"
        return "cylindrical_roller"
    if bearing_type in SEED003_COEFFICIENTS:
        return bearing_type
    raise InputError(
        "bearing_type",
        bearing_type,
        "a type that seed 003's Table III names: " + ", ".join(SEED003_COEFFICIENTS),
        "give the friction type explicitly (`friction_type`)",
    )


def friction_coefficient(friction_type: str) -> float:
    """Coefficient of friction mu of seed 003's Table III [-].

    Parameters
    ----------
    friction_type : str
        A key of :data:`SEED003_COEFFICIENTS` [-].

    Examples
    --------
    >>> friction_coefficient("radial_ball")
    0.0015
    """
    if friction_type not in SEED003_COEFFICIENTS:
        raise InputError(
            "friction_type", friction_type, "one of " + ", ".join(SEED003_COEFFICIENTS)
        )
    return SEED003_COEFFICIENTS[friction_type]


def constant_coefficient_torque(coefficient, equivalent_load, pitch_diameter):
    """Friction torque M = mu P d_m / 2 of seed 003 [N m].

    Parameters
    ----------
    coefficient : float or array
        Coefficient of friction mu [-], >= 0.
    equivalent_load : float or array
        Equivalent bearing load P [N], >= 0.
    pitch_diameter : float or array
        Pitch (mean) diameter d_m [m], > 0.

    Examples
    --------
    >>> round(float(constant_coefficient_torque(0.0015, 1000.0, 0.039)), 6)
    0.02925
    """
    mu = _nonnegative("coefficient", coefficient, "-")
    p = _nonnegative("equivalent_load", equivalent_load, "N")
    dm = _positive("pitch_diameter", pitch_diameter, "m")
    return _out(0.5 * mu * p * dm)


def power_loss(torque, shaft_speed):
    """Frictional power loss N = M omega [W].

    Parameters
    ----------
    torque : float or array
        Friction torque M [N m], >= 0.
    shaft_speed : float or array
        Speed of the rotating ring omega [rad/s], >= 0.

    Examples
    --------
    >>> from bearinglab.units import rpm_to_rad_s
    >>> round(float(power_loss(0.02925, rpm_to_rad_s(1500))), 4)
    4.5946
    """
    m = _nonnegative("torque", torque, "N m")
    w = _nonnegative("shaft_speed", shaft_speed, "rad/s")
    return _out(m * w)
