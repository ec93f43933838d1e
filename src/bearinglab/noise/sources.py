"""Classical sound sources of the bearing noise model: transfer functions from a surface
velocity to the sound pressure at a point, and the sound pressure level (layer 1).

Seed 003 part 4 ("noise of a deep-groove ball bearing with raceway waviness and ball-size
error": Zhang Q., Yang J., An Q., "Noise calculation method for deep groove ball bearing
with considering raceway surface waviness and roller size error", Front. Mech. Eng. 4:13,
2018, doi:10.3389/fmech.2018.00013; seed file lines 765-835) radiates the noise of two
kinds of source, each written for a harmonic velocity u(t) = u_0 e^{j omega t},
k = omega / c_0 (time factor e^{j omega t} throughout, so outgoing waves are e^{-jkr} and,
in two dimensions, the Hankel function H^(2)):

* inner ring -> a rigid circular cylinder of radius a vibrating transversely (eq. 19, after
  Xia X. T. 2015). Eq. 19 is the small-argument (ka, kr << 1) form of the exact
  two-dimensional solution p = A H_1^(2)(kr) cos(phi) with A from the boundary condition
  u_0 cos(phi) = -(1/(j omega rho_0)) dp/dr at r = a::

      p(r, phi) = -j rho_0 c_0 u_0 H_1^(2)(kr) / H_1^(2)'(ka) cos(phi)         (exact)

  With H_1^(2)(x) ~ x/2 + j 2/(pi x) and H_1^(2)'(x) ~ 1/2 - j 2/(pi x^2), multiplying by
  the conjugate of the denominator gives the printed structure of eq. 19::

      p = -rho_0 c_0 u_0 j e^{j omega t} cos(phi) / (1/4 + (2/(pi k^2 a^2))^2)
          * [(kr/4 - 4/(pi^2 k^3 a^2 r)) + j (r/(pi k a^2) + 1/(pi k r))]       (eq. 19)

  (j e^{j omega t} = j cos(omega t) - sin(omega t) as printed). The machine-translated seed
  shows the last term as "4 pi^2 k^3 a^2 r"; the derivation gives 1/(pi k r), used here.
  phi is the angle between the vibration direction and the field point; for a vibration
  along y "the same equation" is used with phi measured from y (seed line 815).
* each ball -> a pulsating sphere of radius r_0 (eqs. 20-23): the outgoing solution of the
  spherical wave equation p = (A/r) e^{j(omega t - kr)} (eqs. 21-22; eq. 20 is printed with
  1/r dp/dr, the spherical operator has 2/r) and, from the surface velocity u at r = r_0,::

      p = rho_0 c_0 k r_0^2 u / (r sqrt(1 + (k r_0)^2)) e^{j theta},
      theta = arctan(1/(k r_0))                                                 (eq. 23)

  i.e. p = rho_0 c_0 (r_0/r) (j k r_0 / (1 + j k r_0)) e^{-jk(r - r_0)} u.
* an oscillating (translating) rigid sphere, the dipole a ball's centre motion physically
  is; not in the seed, offered as the alternative to eq. 23 for ball-centre velocities
  (Morse P. M., Ingard K. U., Theoretical Acoustics, 1968, sec. 7.2)::

      p = rho_0 c_0 (r_0/r) e^{-jk(r - r_0)} (-(k r_0)^2 + j k r_0^2 / r)
          / (2 + 2 j k r_0 - (k r_0)^2) cos(theta)

Sound pressure level (eq. 27): SPL = 20 lg(p_e / p_ref), p_ref = 2e-5 Pa, p_e the
effective (root-mean-square) pressure sqrt(1/T int_0^T p^2 dt).

Units: SI in and out (Hz, m, kg/m^3, m/s, Pa); transfer functions are complex pressure
per unit velocity amplitude [Pa/(m/s)], zero at 0 Hz (a steady translation radiates no
sound).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.special

from ..errors import InputError

#: Reference sound pressure of the SPL, eq. 27 [Pa].
REFERENCE_PRESSURE = 2e-5
#: Density of air at 20 deg C and 101.325 kPa [kg/m^3].
AIR_DENSITY = 1.21
#: Speed of sound in air at 20 deg C [m/s].
AIR_SOUND_SPEED = 343.0
#: Forms of the cylinder source: the exact 2-D solution or the seed's small-argument eq. 19.
CYLINDER_FORMS = ("exact", "seed")


def _positive(name: str, value, unit: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(name, value, f"a finite number > 0 {unit}") from None
    if not math.isfinite(v) or v <= 0:
        raise InputError(name, value, f"a finite number > 0 {unit}")
    return v


def _frequencies(frequency) -> np.ndarray:
    f = np.asarray(frequency, dtype=float)
    if not np.all(np.isfinite(f)) or np.any(f < 0):
        raise InputError(
            "frequency", "an array with negative or non-finite values", "frequencies >= 0 [Hz]"
        )
    return f


def _wavenumber(frequency, sound_speed) -> np.ndarray:
    return 2.0 * np.pi * _frequencies(frequency) / _positive("sound_speed", sound_speed, "[m/s]")


def _radius_and_distance(radius, distance, body: str) -> tuple[float, float]:
    """(r_0, r) [m]: the source's radius and a field distance outside it."""
    r0 = _positive("radius", radius, "[m]")
    r = _positive("distance", distance, "[m]")
    if r < r0:
        raise InputError("distance", distance, f"a distance >= the {body} radius {r0:g} m")
    return r0, r


def _impedance(density, sound_speed) -> float:
    """Characteristic impedance rho_0 c_0 of the medium [Pa s/m]."""
    return _positive("density", density, "[kg/m^3]") * _positive(
        "sound_speed", sound_speed, "[m/s]"
    )


def sound_pressure_level(effective_pressure):
    """SPL = 20 lg(p_e / p_ref), p_ref = 2e-5 Pa (seed 003 eq. 27) [dB].

    Parameters
    ----------
    effective_pressure : float or array_like
        Effective (RMS) sound pressure p_e >= 0 [Pa]; 0 gives -inf.

    Examples
    --------
    >>> float(sound_pressure_level(2e-5)), round(float(sound_pressure_level(1.0)), 2)
    (0.0, 93.98)
    """
    p = np.asarray(effective_pressure, dtype=float)
    if not np.all(np.isfinite(p)) or np.any(p < 0):
        raise InputError("effective_pressure", effective_pressure, "values >= 0 [Pa]")
    with np.errstate(divide="ignore"):
        level = 20.0 * np.log10(p / REFERENCE_PRESSURE)
    return float(level) if level.ndim == 0 else level


def effective_pressure(pressure) -> float:
    """p_e = sqrt(1/T int_0^T p^2 dt) of a uniformly sampled pressure record (seed 003,
    text after eq. 27) [Pa].

    Parameters
    ----------
    pressure : array_like
        Sound pressure samples [Pa].
    """
    p = np.asarray(pressure, dtype=float)
    return float(np.sqrt(np.mean(p**2)))


def cylinder_transfer(
    frequency,
    radius,
    distance,
    *,
    density=AIR_DENSITY,
    sound_speed=AIR_SOUND_SPEED,
    form: str = "exact",
) -> np.ndarray:
    """Pressure per unit velocity of a transversely vibrating rigid cylinder, on the
    vibration axis (phi = 0; multiply by cos(phi) off it) (seed 003 eq. 19).

    Parameters
    ----------
    frequency : array_like
        Frequencies f >= 0 [Hz].
    radius : float
        Cylinder radius a [m].
    distance : float
        Distance r >= a of the field point from the cylinder axis [m].
    density, sound_speed : float
        rho_0 [kg/m^3], c_0 [m/s].
    form : {"exact", "seed"}
        ``"exact"``: -j rho_0 c_0 H_1^(2)(kr) / H_1^(2)'(ka); ``"seed"``: eq. 19, the
        same with the small-argument Hankel functions (valid for ka, kr << 1).

    Returns
    -------
    numpy.ndarray (complex)
        p / u_0 [Pa/(m/s)], 0 at f = 0.

    Examples
    --------
    At low frequency both forms tend to the incompressible near field j omega rho a^2 / r:

    >>> h = cylinder_transfer([10.0], 5e-3, 1e-2)
    >>> round(float(abs(h[0]) / (2 * np.pi * 10.0 * 1.21 * 25e-6 / 1e-2)), 4)
    1.0
    """
    a, r = _radius_and_distance(radius, distance, "cylinder")
    if form not in CYLINDER_FORMS:
        raise InputError("form", form, f"one of {CYLINDER_FORMS}")
    rho = _positive("density", density, "[kg/m^3]")
    c = _positive("sound_speed", sound_speed, "[m/s]")
    k = _wavenumber(frequency, c)
    out = np.zeros(k.shape, dtype=complex)
    live = k > 0
    kk = k[live]
    if form == "exact":
        h = scipy.special.hankel2(1, kk * r)
        dh = scipy.special.h2vp(1, kk * a)
    else:
        h = kk * r / 2 + 2j / (np.pi * kk * r)
        dh = 0.5 - 2j / (np.pi * (kk * a) ** 2)
    out[live] = -1j * rho * c * h / dh
    return out


def pulsating_sphere_transfer(
    frequency, radius, distance, *, density=AIR_DENSITY, sound_speed=AIR_SOUND_SPEED
) -> np.ndarray:
    """Pressure per unit surface velocity of a pulsating sphere (seed 003 eq. 23).

    p = rho_0 c_0 (r_0/r) (j k r_0 / (1 + j k r_0)) e^{-jk(r - r_0)} u, whose magnitude is
    eq. 23's rho_0 c_0 k r_0^2 u / (r sqrt(1 + (k r_0)^2)) and whose phase (at r = r_0)
    is theta = arctan(1/(k r_0)).

    Parameters
    ----------
    frequency : array_like
        Frequencies f >= 0 [Hz].
    radius : float
        Sphere radius r_0 [m].
    distance : float
        Distance r >= r_0 from the sphere's centre [m].
    density, sound_speed : float
        rho_0 [kg/m^3], c_0 [m/s].

    Returns
    -------
    numpy.ndarray (complex)
        p / u [Pa/(m/s)].

    Examples
    --------
    >>> k_r0 = 2 * np.pi * 1000.0 / 343.0 * 2e-3
    >>> h = pulsating_sphere_transfer([1000.0], 2e-3, 0.01)
    >>> round(float(abs(h[0]) * 0.01 * np.sqrt(1 + k_r0**2) / (1.21 * 343.0 * k_r0 * 2e-3)), 12)
    1.0
    """
    r0, r = _radius_and_distance(radius, distance, "sphere")
    k = _wavenumber(frequency, sound_speed)
    return (
        pulsating_sphere_source(k, r0, density=density, sound_speed=sound_speed)
        * np.exp(-1j * k * r)
        / r
    )


def pulsating_sphere_source(
    wavenumber, radius, *, density=AIR_DENSITY, sound_speed=AIR_SOUND_SPEED
) -> np.ndarray:
    """Source strength G(k) of a pulsating sphere, p = G(k) e^{-jkr} / r per unit surface
    velocity: G = rho_0 c_0 r_0 e^{j k r_0} j k r_0 / (1 + j k r_0) (eq. 23) [Pa m/(m/s)].

    Parameters
    ----------
    wavenumber : array_like
        k = omega / c_0 >= 0 [1/m].
    radius : float
        r_0 [m].
    density, sound_speed : float
        rho_0 [kg/m^3], c_0 [m/s].
    """
    r0 = _positive("radius", radius, "[m]")
    rc = _impedance(density, sound_speed)
    kr0 = np.asarray(wavenumber, dtype=float) * r0
    return rc * r0 * np.exp(1j * kr0) * 1j * kr0 / (1 + 1j * kr0)


def oscillating_sphere_source(
    wavenumber, radius, *, density=AIR_DENSITY, sound_speed=AIR_SOUND_SPEED
) -> tuple[np.ndarray, np.ndarray]:
    """Source strengths (G_1, G_2) of a rigid sphere translating with velocity u:
    p = (G_1 e^{-jkr}/r + G_2 e^{-jkr}/r^2) cos(theta) u, theta from the velocity direction
    (Morse & Ingard 1968, sec. 7.2) [Pa m/(m/s), Pa m^2/(m/s)].

    G_1 = rho_0 c_0 r_0 e^{jkr_0} (-(k r_0)^2) / D, G_2 = rho_0 c_0 r_0 e^{jkr_0} j k r_0^2 / D,
    D = 2 + 2 j k r_0 - (k r_0)^2. At low frequency p -> j omega rho_0 r_0^3 cos(theta) u /
    (2 r^2), the incompressible dipole.

    Parameters
    ----------
    wavenumber : array_like
        k >= 0 [1/m].
    radius : float
        r_0 [m].
    density, sound_speed : float
        rho_0 [kg/m^3], c_0 [m/s].
    """
    r0 = _positive("radius", radius, "[m]")
    rc = _impedance(density, sound_speed)
    k = np.asarray(wavenumber, dtype=float)
    kr0 = k * r0
    common = rc * r0 * np.exp(1j * kr0) / (2 + 2j * kr0 - kr0**2)
    return common * (-(kr0**2)), common * 1j * k * r0**2


def oscillating_sphere_transfer(
    frequency, radius, distance, *, density=AIR_DENSITY, sound_speed=AIR_SOUND_SPEED
) -> np.ndarray:
    """Pressure per unit velocity of a translating rigid sphere on its axis of motion
    (theta = 0; multiply by cos(theta) off it) [Pa/(m/s)].

    Parameters
    ----------
    frequency : array_like
        f >= 0 [Hz].
    radius : float
        r_0 [m].
    distance : float
        r >= r_0 [m].
    density, sound_speed : float
        rho_0 [kg/m^3], c_0 [m/s].
    """
    r0, r = _radius_and_distance(radius, distance, "sphere")
    k = _wavenumber(frequency, sound_speed)
    g1, g2 = oscillating_sphere_source(k, r0, density=density, sound_speed=sound_speed)
    return (g1 / r + g2 / r**2) * np.exp(-1j * k * r)
