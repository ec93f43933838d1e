"""Line contact of a roller with its raceways (layer 1: pure, vectorised functions, SI).

Sources:

- Hertz line contact (Johnson K. L., *Contact Mechanics*, Cambridge 1985, sec. 4.2,
  eqs. 4.43-4.45, two parallel cylinders; the same in Hamrock B. J., *Fundamentals of
  Fluid Film Lubrication*, 1994, ch. 17, rectangular conjunctions): for a load w' per unit
  length, effective radius 1/R = 1/R_a + 1/R_b and E' = 2 / ((1 - nu_a^2)/E_a +
  (1 - nu_b^2)/E_b), the half-width b = sqrt(8 w' R / (pi E')) and the maximum pressure
  p_0 = 2 w' / (pi b) = sqrt(w' E' / (2 pi R)) (Johnson writes it with E* = E'/2:
  p_0 = sqrt(w' E* / (pi R))); the mean pressure is pi p_0 / 4.
- The load-deflection law of a roller between both raceways, ISO/TS 16281:2008 (the
  slice method, "lamina" in the standard): Q = c_l delta^(10/9) with
  c_l = 35 948 L_we^(8/9) N/mm^(10/9) for steel rollers and rings, and a slice of n_s
  carrying q_k = (c_l / n_s) delta_k^(10/9). Two stored public implementations of the
  standard carry the same constant and slice law (minzhun/ISO16281 ``RollerBearing.py``,
  shiva01910/BearingLifeCalculation16281 ``roller_bearing.py``). For other materials the
  constant is scaled by E' / E'_steel (the law is c E' L^(8/9) with c dimensionless).
- Palmgren's empirical approach of one roller-raceway contact, delta = 3.84e-5 Q^0.9 /
  l^0.8 mm (Q in N, l in mm; Palmgren A., *Ball and Roller Bearing Engineering*, 1959,
  quoted by Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*,
  5th ed., 2007, ch. 6), kept as the independent check of c_l: two such contacts in series
  give 7.68e-5 Q^0.9 / l^0.8 mm, ISO's c_l 7.94e-5 Q^0.9 / l^0.8 mm (3.4 % more).
- Roller profiles (the radius drop of the roller generatrix against the axial position x
  from the roller's middle): ISO/TS 16281's logarithmic profile (eqs. 42-44, both stored
  implementations): P(x) = 0.00035 D_we ln(1 / (1 - (2x/L_we)^2)) for L_we <= 2.5 D_we,
  else flat in the middle and 0.0005 D_we ln(1 / (1 - ((2|x| - (L_we - 2.5 D_we)) /
  (2.5 D_we))^2)) over the last 1.25 D_we at each end; tapered rollers 0.00045 D_we
  ln(1 / (1 - (2x/L_we)^2)). A circular crown of radius R_c: R_c - sqrt(R_c^2 - x^2)
  beyond an optional flat middle. Both contacts of a roller see its profile, so the
  approach of a slice is reduced by 2 P(x) (ISO/TS 16281 eq. 39).
- The edge-stress concentration factors of unprofiled rollers, ISO/TS 16281 eq. 60 (as in
  minzhun/ISO16281): f_k = 1 - 0.01 / ln(1.985 |(2k - n_s - 1) / (2 n_s - 2)|), k = 1...n_s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, positive_number

#: ISO/TS 16281 roller constant c_l / L_we^(8/9) for steel [N/mm^(10/9) / mm^(8/9)].
ISO16281_ROLLER_CONSTANT = 35948.0
#: The same in SI: c_l = 35948 * 1000^2 * L_we[m]^(8/9) [N/m^(10/9)] (1000^(8/9) for the
#: length and 1000^(10/9) for the approach, both read in mm by the standard).
ISO16281_ROLLER_CONSTANT_SI = ISO16281_ROLLER_CONSTANT * 1.0e6
#: Exponent of the line-contact load-deflection law Q = c delta^n [-].
LINE_EXPONENT = 10.0 / 9.0
#: Palmgren's approach of one roller-raceway contact, 3.84e-5 Q^0.9 / l^0.8 mm (Q N, l mm).
PALMGREN_COEFFICIENT_MM = 3.84e-5
#: Coefficients of ISO/TS 16281's logarithmic profile (eqs. 42-44) [-].
LOG_PROFILE_SHORT = 0.00035
LOG_PROFILE_LONG = 0.0005
LOG_PROFILE_TAPERED = 0.00045
#: L_we / D_we above which the cylindrical logarithmic profile has a flat middle [-].
LOG_PROFILE_FLAT_RATIO = 2.5


@dataclass(frozen=True)
class LineContact:
    """Hertz line contact (arrays when the load is an array), SI.

    Attributes: ``load_per_length`` w' [N/m], ``reduced_radius`` R [m],
    ``effective_modulus`` E' [Pa], ``half_width`` b [m], ``max_pressure`` p_0 [Pa].
    """

    load_per_length: np.ndarray
    reduced_radius: np.ndarray
    effective_modulus: float
    half_width: np.ndarray
    max_pressure: np.ndarray

    @property
    def mean_pressure(self):
        """Mean pressure over the contact width, pi p_0 / 4 [Pa]."""
        return 0.25 * math.pi * self.max_pressure


def line_contact(load_per_length, reduced_radius, effective_modulus) -> LineContact:
    """Hertz contact of two parallel cylinders (or a cylinder on a flat).

    b = sqrt(8 w' R / (pi E')), p_0 = 2 w' / (pi b) (Johnson 1985, eqs. 4.43-4.45).

    Parameters
    ----------
    load_per_length : float or array
        Load per unit contact length w' >= 0 [N/m].
    reduced_radius : float or array
        R with 1/R = 1/R_a + 1/R_b (> 0; a flat has 1/R_b = 0) [m].
    effective_modulus : float
        E' = 2 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b) [Pa].

    Examples
    --------
    >>> c = line_contact(40e3 / 0.02, 0.01, 2 / (2 * (1 - 0.3**2) / 210e9))
    >>> round(float(c.max_pressure) / 1e6, 1), round(float(c.half_width) * 1e3, 4)
    (2710.3, 0.4698)
    """
    w = np.asarray(load_per_length, dtype=float)
    r = np.asarray(reduced_radius, dtype=float)
    if np.any(~np.isfinite(w)) or np.any(w < 0):
        raise InputError("load_per_length", load_per_length, "finite loads >= 0 [N/m]")
    if np.any(~np.isfinite(r)) or np.any(r <= 0):
        raise InputError("reduced_radius", reduced_radius, "positive radii [m]")
    e = positive_number("effective_modulus", effective_modulus, "a positive modulus [Pa]")
    b = np.sqrt(8.0 * w * r / (math.pi * e))
    p0 = np.sqrt(w * e / (2.0 * math.pi * r))
    return LineContact(w[()], r[()], e, b[()], p0[()])


def roller_raceway_radii(roller_diameter, pitch_diameter, contact_angle=0.0):
    """Effective radii (R_inner, R_outer) of a roller's contacts in the rolling direction [m].

    1/R_i = 2/D + 2 cos(a) / (d_m - D cos a), 1/R_o = 2/D - 2 cos(a) / (d_m + D cos a), i.e.
    R_i = D (1 - gamma)/2, R_o = D (1 + gamma)/2 with gamma = D cos(a)/d_m (Harris &
    Kotzalas 2007, ch. 2; for a tapered roller D is its mean diameter and a the raceway's
    angle).

    Parameters
    ----------
    roller_diameter : float or array
        D_we [m].
    pitch_diameter : float
        d_m [m].
    contact_angle : float or array
        Raceway angle alpha [rad].

    Examples
    --------
    >>> [round(float(r) * 1e3, 4) for r in roller_raceway_radii(10e-3, 65.01e-3)]
    [4.2309, 5.7691]
    """
    gamma = np.asarray(roller_diameter, float) * np.cos(contact_angle) / pitch_diameter
    half = 0.5 * np.asarray(roller_diameter, float)
    return half * (1.0 - gamma), half * (1.0 + gamma)


def iso16281_roller_constant(effective_length, effective_modulus=None, steel_modulus=None):
    """c_l in Q = c_l delta^(10/9) for a roller between both raceways, ISO/TS 16281 [N/m^(10/9)].

    c_l = 35 948 L_we^(8/9) N/mm^(10/9) for steel, i.e. 3.5948e10 L_we[m]^(8/9) in SI; for
    other materials times E' / E'_steel.

    Parameters
    ----------
    effective_length : float
        L_we [m].
    effective_modulus : float or None
        E' of the roller-ring pair [Pa]; None: steel.
    steel_modulus : float or None
        E' of the steel pair the standard's constant stands for [Pa]; needed with
        ``effective_modulus``.

    Examples
    --------
    >>> round(iso16281_roller_constant(9.6e-3) / 1e9, 4)
    0.5783
    """
    length = positive_number("effective_length", effective_length, "a positive length [m]")
    c = ISO16281_ROLLER_CONSTANT_SI * length ** (8.0 / 9.0)
    if effective_modulus is None:
        return c
    if steel_modulus is None:
        raise InputError("steel_modulus", None, "E' of steel [Pa] with an effective_modulus")
    return c * effective_modulus / steel_modulus


def iso16281_approach(load, effective_length):
    """Approach of a steel roller between both raceways, delta = (Q / c_l)^(9/10) [m].

    Parameters
    ----------
    load : float or array
        Roller load Q >= 0 [N].
    effective_length : float
        L_we [m].

    Examples
    --------
    >>> round(float(iso16281_approach(1000.0, 10e-3)) * 1e6, 3)
    6.308
    """
    q = np.asarray(load, float)
    if np.any(~np.isfinite(q)) or np.any(q < 0):
        raise InputError("load", load, "finite loads >= 0 [N]")
    return ((q / iso16281_roller_constant(effective_length)) ** 0.9)[()]


def palmgren_approach(load, length):
    """Palmgren's approach of ONE roller-raceway contact, 3.84e-5 Q^0.9 / l^0.8 mm [m].

    Parameters
    ----------
    load : float or array
        Contact load Q >= 0 [N].
    length : float
        Contact length l [m].

    Examples
    --------
    >>> round(float(palmgren_approach(1000.0, 10e-3)) * 1e6, 3)
    3.05
    """
    q = np.asarray(load, float)
    if np.any(~np.isfinite(q)) or np.any(q < 0):
        raise InputError("load", load, "finite loads >= 0 [N]")
    l_mm = positive_number("length", length, "a positive length [m]") * 1e3
    return (PALMGREN_COEFFICIENT_MM * q**0.9 / l_mm**0.8 * 1e-3)[()]


def slice_positions(effective_length: float, slices: int) -> np.ndarray:
    """Centres x_k of ``slices`` equal slices over L_we, from the roller's middle [m].

    Parameters
    ----------
    effective_length : float
        L_we [m].
    slices : int
        n_s >= 1 [-].

    Examples
    --------
    >>> (slice_positions(10e-3, 4) * 1e3).tolist()
    [-3.75, -1.25, 1.25, 3.75]
    """
    n = _slices(slices)
    length = positive_number("effective_length", effective_length, "a positive length [m]")
    return (np.arange(n) + 0.5 - 0.5 * n) * length / n


def _slices(slices) -> int:
    if isinstance(slices, bool) or not isinstance(slices, (int, np.integer)) or slices < 1:
        raise InputError("slices", slices, "an integer >= 1")
    return int(slices)


def logarithmic_profile(x, roller_diameter: float, effective_length: float, tapered=False):
    """ISO/TS 16281's logarithmic roller profile, the radius drop P(x) [m].

    See the module docstring; infinite at |x| = L_we/2 (the profile's ends).

    Parameters
    ----------
    x : float or array
        Axial positions from the roller's middle, |x| < L_we/2 [m].
    roller_diameter : float
        D_we [m].
    effective_length : float
        L_we [m].
    tapered : bool
        The tapered-roller form (0.00045 D_we ...) [-].

    Examples
    --------
    >>> round(float(logarithmic_profile(4e-3, 10e-3, 9.6e-3)) * 1e6, 3)
    4.15
    """
    x = np.abs(np.asarray(x, float))
    d, length = roller_diameter, effective_length
    with np.errstate(divide="ignore"):
        if tapered or length <= LOG_PROFILE_FLAT_RATIO * d:
            k = LOG_PROFILE_TAPERED if tapered else LOG_PROFILE_SHORT
            u = np.minimum(2.0 * x / length, 1.0)
            return (k * d * -np.log1p(-(u**2)))[()]
        flat = 0.5 * (length - LOG_PROFILE_FLAT_RATIO * d)
        u = np.clip((2.0 * x - 2.0 * flat) / (LOG_PROFILE_FLAT_RATIO * d), 0.0, 1.0)
        return (LOG_PROFILE_LONG * d * -np.log1p(-(u**2)))[()]


def crowned_profile(x, crown_radius: float, flat_length: float = 0.0):
    """Circular crown: R_c - sqrt(R_c^2 - s^2), s = max(|x| - flat_length/2, 0) [m].

    Parameters
    ----------
    x : float or array
        Axial positions from the roller's middle [m].
    crown_radius : float
        Crown radius R_c [m].
    flat_length : float
        Length of the straight middle [m].

    Examples
    --------
    >>> round(float(crowned_profile(5e-3, 1.0)) * 1e6, 3)
    12.5
    """
    s = np.maximum(np.abs(np.asarray(x, float)) - 0.5 * flat_length, 0.0)
    s = np.minimum(s, crown_radius)
    return (crown_radius - np.sqrt(crown_radius**2 - s**2))[()]


def edge_stress_factors(slices: int) -> np.ndarray:
    """ISO/TS 16281 eq. 60 edge-stress concentration factors f_k of an unprofiled roller.

    f_k = 1 - 0.01 / ln(1.985 |(2k - n_s - 1) / (2 n_s - 2)|), k = 1...n_s (1 for a middle
    slice); the end slices get 2.33 whatever n_s.

    Parameters
    ----------
    slices : int
        n_s >= 2 [-].

    Examples
    --------
    >>> [round(float(f), 3) for f in edge_stress_factors(30)[:3]]
    [2.328, 1.127, 1.064]
    """
    n = _slices(slices)
    if n < 2:
        return np.ones(n)
    k = np.arange(1, n + 1)
    u = 1.985 * np.abs((2.0 * k - n - 1.0) / (2.0 * n - 2.0))
    with np.errstate(divide="ignore"):
        return 1.0 - 0.01 / np.log(u)
