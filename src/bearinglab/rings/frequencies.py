"""Natural frequencies of the outer ring of a loaded ball bearing (seed 000).

Source: Balmont V. B., Varlamov E. B., "On resonance phenomena in ball bearings" (in
Russian), 1986. A thin inextensional ring (Timoshenko) on n ball springs; mode m,
w = a sin(m phi) cos(nu t), by equating kinetic and potential energy amplitudes. Equation
numbers are the paper's. Layer 1: pure vectorised functions in Hz (the frequency equations
are homogeneous: one unit in, the same out); layer 3 (bearinglab.rings.modes):
:func:`ring_modes` -> :class:`RingModes`.
OCR, reconstructed: the energy density printed (w'' + v'')^2 is (w'' + v')^2 as in (1.2), and
(1.1) lost its time dots; redoing the integrals gives (1.5) as printed. Assumptions and the
comparison with the paper: docs/capabilities/rings.md.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

# ---------------------------------------------------------------- layer 1: functions


def _modes(mode, minimum: int = 1):
    m = np.asarray(mode)
    if (
        m.dtype.kind not in "iuf"
        or np.any(~np.isfinite(m))
        or np.any(m != np.round(m))
        or np.any(m < minimum)
    ):
        raise InputError("mode", mode, f"integers >= {minimum}")
    return m.astype(float)


def _arr(name: str, value, unit: str, positive: bool = False):
    v = np.asarray(value, dtype=float)
    if np.any(~np.isfinite(v)) or np.any(v <= 0 if positive else v < 0):
        raise InputError(name, value, f"finite values {'>' if positive else '>='} 0 {unit}")
    return v


def _lam(lam):
    v = np.asarray(lam, dtype=float)
    if np.any(~np.isfinite(v)) or np.any(v < 0) or np.any(v > 2):
        raise InputError("lam", lam, "values in [0, 2] (lambda = 1 - cos 2 m phi_0)")
    return v


def _g(m):
    """(1 + m^-2)^-1, from the kinetic energy of the inextensional mode, eq. (1.5)."""
    return 1.0 / (1.0 + m**-2.0)


def _loaded_inputs(free_frequency, rigid_body_frequency, mode, lam):
    """(m, lambda, f*_m [Hz], f_1 [Hz]) checked, for the loaded-ring formulas."""
    return (
        _modes(mode),
        _lam(lam),
        _arr("free_frequency", free_frequency, "[Hz]"),
        _arr("rigid_body_frequency", rigid_body_frequency, "[Hz]"),
    )


def free_ring_frequency(mode, elastic_modulus, density, second_moment, mean_radius, area):
    """Frequency f*_m of the m-th in-plane flexural mode of a free thin ring [Hz].

    Eq. (1.6), first term (Timoshenko): nu*_m^2 = E I (m^2-1)^2 / (rho R^4 S (1 + 1/m^2)),
    f*_m = nu*_m / (2 pi); m = 1 is the rigid-body translation (0).

    Parameters
    ----------
    mode : int or array
        Mode number m (waves round the ring), >= 1 [-].
    elastic_modulus, density : float or array
        E [Pa] and rho [kg/m^3].
    second_moment : float or array
        I of the section about its axis parallel to the bearing axis [m^4].
    mean_radius, area : float or array
        Radius R of the centroid line [m] and section area S [m^2].

    Examples
    --------
    >>> round(float(free_ring_frequency(2, 208e9, 7830, 1e-10, 0.03, 5e-5)), 1)
    3458.7
    """
    m = _modes(mode)
    e, rho = (
        _arr("elastic_modulus", elastic_modulus, "[Pa]", True),
        _arr("density", density, "[kg/m^3]", True),
    )
    i, r = (
        _arr("second_moment", second_moment, "[m^4]", True),
        _arr("mean_radius", mean_radius, "[m]", True),
    )
    s = _arr("area", area, "[m^2]", True)
    return np.sqrt(e * i * (m**2 - 1.0) ** 2 * _g(m) / (rho * r**4 * s)) / (2.0 * np.pi)


def radial_stiffness_under_axial_load(ball_count, ball_constant, axial_load, contact_angle):
    """Radial stiffness K_x = 0.75 (n k_g)^(2/3) (A / sin tau)^(1/3) cos^2 tau [N/m].

    Seed 000 sec. 1 (after eq. 1.6, citing [1] for k_g). The formula follows from
    Q = k_g delta^1.5 per ball (delta: approach of the two raceways, both contacts),
    Q = A / (n sin tau) and K_x = (n/2) cos^2(tau) dQ/d(delta) (sum cos^2 phi_i = n/2), so
    k_g is our ball constant K_n (``load_deflection_constants(...)[2]``); the paper does not
    define k_g itself, but the 0.75 = (1/2)(3/2) and the 2/3 power admit only this reading.
    tau is held fixed (no stiffness from the turning of the contact line).

    Parameters
    ----------
    ball_count : int or array
        n [-].
    ball_constant : float or array
        k_g = K_n in Q = K_n delta^1.5 [N/m^1.5].
    axial_load : float or array
        A > 0 [N].
    contact_angle : float or array
        tau, 0 < tau < pi/2 [rad].

    Examples
    --------
    >>> round(float(radial_stiffness_under_axial_load(8, 1.5e10, 200.0, 0.2)) / 1e6, 1)
    175.7
    """
    n, k = (
        _arr("ball_count", ball_count, "[-]", True),
        _arr("ball_constant", ball_constant, "[N/m^1.5]"),
    )
    a, tau = _arr("axial_load", axial_load, "[N]", True), np.asarray(contact_angle, float)
    if np.any(~np.isfinite(tau)) or np.any(tau <= 0) or np.any(tau >= 0.5 * np.pi):
        raise InputError(
            "contact_angle",
            contact_angle,
            "angles in (0, 90) degrees [rad]",
            "a pure axial load needs a contact angle > 0",
        )
    return 0.75 * (n * k) ** (2.0 / 3.0) * np.cbrt(a / np.sin(tau)) * np.cos(tau) ** 2


def rigid_body_frequency(radial_stiffness, ring_mass):
    """f_1 = sqrt(K_x / m_h) / (2 pi): the ring as a rigid body on the balls, eq. (1.7) [Hz].

    Parameters
    ----------
    radial_stiffness : float or array
        K_x [N/m].
    ring_mass : float or array
        Vibrating mass m_h of the ring and what is attached to it [kg].

    Examples
    --------
    >>> round(float(rigid_body_frequency(150e6, 0.6)), 1)  # seed 000, 310: "2.5 kHz"
    2516.5
    """
    k = _arr("radial_stiffness", radial_stiffness, "[N/m]")
    return np.sqrt(k / _arr("ring_mass", ring_mass, "[kg]", True)) / (2.0 * np.pi)


def split_mode(mode, ball_count):
    """True where 2m is a multiple of n (mu_n^2m = 1, eq. 1.5): the mode splits [-].

    Parameters
    ----------
    mode, ball_count : int or array
        m [-] and n [-].
    """
    m, n = _modes(mode).astype(int), np.asarray(ball_count)
    if n.dtype.kind not in "iu" or np.any(n < 1):
        raise InputError("ball_count", ball_count, "integers >= 1")
    return (2 * m) % n == 0


def loaded_ring_frequency(free_frequency, rigid_body_frequency, mode, lam=1.0):
    """Ring on massless ball springs, eq. (1.9): f^2 = f*^2 + 2 lam f_1^2 / (1 + m^-2) [Hz].

    lam = 1 when 2m is not a multiple of n; when 2m = l n, lam = 1 - cos(2 m phi_0) (eq.
    1.8), whose extremes 0 (balls at the nodes, f = f*) and 2 (at the antinodes) are the
    two frequencies. m = 1 with f* = 0 gives f_1 itself (the paper's "first mode").

    Parameters
    ----------
    free_frequency, rigid_body_frequency : float or array
        f*_m and f_1 [Hz].
    mode : int or array
        m >= 1 [-].
    lam : float or array
        lambda in [0, 2] [-].

    Examples
    --------
    >>> round(float(loaded_ring_frequency(3.50, 5.07, 2)), 2)  # seed 000, 106: 7.31 kHz
    7.31
    """
    m, lam, fs, f1 = _loaded_inputs(free_frequency, rigid_body_frequency, mode, lam)
    return np.sqrt(fs**2 + 2.0 * lam * f1**2 * _g(m))


def loaded_ring_frequencies(free_frequency, rigid_body_frequency, mode, ball_count):
    """(lower, upper) of eq. (1.9) with lambda from m and n [Hz]: both lam = 1 if 2m != l n,
    else lam = 0 (balls at the nodes, = f*) and lam = 2 (at the antinodes).

    Parameters
    ----------
    free_frequency, rigid_body_frequency : float or array
        f*_m and f_1 [Hz].
    mode, ball_count : int or array
        m >= 1 [-] and n [-].

    Examples
    --------
    >>> [round(float(f), 2) for f in loaded_ring_frequencies(10.0, 2.5, 4, 8)]  # 310
    [10.0, 11.11]
    """
    split = split_mode(mode, ball_count)
    return tuple(
        loaded_ring_frequency(free_frequency, rigid_body_frequency, mode, np.where(split, lam, 1.0))
        for lam in (0.0, 2.0)
    )


def _terms(free_frequency, rigid_body_frequency, mode, kappa, ratio, lam):
    """N = a + lam (b2 e^2 + b1 (1-e)^2), D = 1 + lam c e^2 of eq. (3.3)/(3.6)."""
    m, lam, fs, f1 = _loaded_inputs(free_frequency, rigid_body_frequency, mode, lam)
    c = _arr("ball_mass_ratio", kappa, "[-]") * _g(m)
    r = _arr("stiffness_ratio", ratio, "[-]", True)
    b1 = 2.0 * _g(m) * f1**2 * (1.0 + r)  # 2 w1^2 / (1 + m^-2), w1^2 = f_1^2 (1 + r)
    b2 = 2.0 * _g(m) * f1**2 * (1.0 + 1.0 / r)  # 2 w2^2 / (1 + m^-2)
    return fs**2, b1, b2, c, r, lam


def refined_frequency(
    epsilon,
    free_frequency,
    rigid_body_frequency,
    mode,
    ball_mass_ratio,
    stiffness_ratio=1.0,
    lam=1.0,
):
    """Eq. (3.3) (lam = 1) and its 2m = l n form (lam = 1 - cos 2 m phi_0) [Hz]:

    f^2 = {f*^2 + 2 lam (1+m^-2)^-1 [e^2 w2^2 + (1-e)^2 w1^2]} / [1 + lam kappa e^2 (1+m^-2)^-1]

    with w1^2 = n K1 / (2 m_k) = f_1^2 (1 + K1/K2), w2^2 = f_1^2 (1 + K2/K1) (from
    K_x = n K / 2, 1/K = 1/K1 + 1/K2). K1 = K2 gives (3.4) and (3.9); lam = 0 gives (3.8),
    f = f*. An infinite epsilon gives the limit sqrt((b1 + b2) / c).

    Parameters
    ----------
    epsilon : float or array
        Ball motion per unit ring motion under it, s_i = epsilon w(phi_i) [-].
    free_frequency, rigid_body_frequency : float or array
        f*_m and f_1 [Hz].
    mode : int or array
        m >= 1 [-].
    ball_mass_ratio : float or array
        kappa = n m_b / m_k >= 0 [-].
    stiffness_ratio : float or array
        K1 / K2, ball-outer over ball-inner contact stiffness, > 0 [-].
    lam : float or array
        lambda in [0, 2] [-].

    Examples
    --------
    >>> round(float(refined_frequency(6.08, 16.2, 2.5, 5, 0.33)), 2)
    11.8
    """
    a, b1, b2, c, _, lam = _terms(
        free_frequency, rigid_body_frequency, mode, ball_mass_ratio, stiffness_ratio, lam
    )
    e = np.asarray(epsilon, dtype=float)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        f2 = (a + lam * (b2 * e**2 + b1 * (1.0 - e) ** 2)) / (1.0 + lam * c * e**2)
        f2 = np.where(np.isinf(e), np.where(lam * c > 0, (b1 + b2) / c, np.inf), f2)
    return np.sqrt(f2)


def refined_ring_frequencies(
    free_frequency, rigid_body_frequency, mode, ball_mass_ratio, stiffness_ratio=1.0, lam=1.0
):
    """Both stationary values of eq. (3.3)/(3.6) in epsilon: ((f_low, f_high) [Hz],
    (epsilon_low, epsilon_high) [-]).

    The paper says d(nu^2)/d(epsilon) = 0 is a quadratic but prints it only for K1 = K2
    (3.5, 3.10). From :func:`refined_frequency` (a = f*^2, c = kappa (1+m^-2)^-1,
    b_j = 2 w_j^2 (1+m^-2)^-1):  lam b1 c e^2 + [b1 + b2 - a c - lam b1 c] e - b1 = 0.
    Its roots are real and of opposite sign (the balls moving with the ring, lower, and
    against it, upper). With kappa = 0 only the static e = K1/(K1+K2) remains (the
    approximate model) and the upper solution is inf; lam = 0 gives f* twice, e = nan.

    Parameters
    ----------
    free_frequency, rigid_body_frequency : float or array
        f*_m and f_1 [Hz].
    mode : int or array
        m >= 1 [-].
    ball_mass_ratio : float or array
        kappa = n m_b / m_k >= 0 [-].
    stiffness_ratio : float or array
        K1 / K2 > 0 [-].
    lam : float or array
        1 for 2m != l n, 2 for the balls at the antinodes when 2m = l n [-].

    Examples
    --------
    >>> f, e = refined_ring_frequencies(10.0, 2.5, 4, 0.33, lam=2)  # 310, m = 4
    >>> [round(float(x), 2) for x in f + e]
    [9.46, 14.46, 1.22, -1.32]
    """
    args = (free_frequency, rigid_body_frequency, mode, ball_mass_ratio, stiffness_ratio)
    a, b1, b2, c, r, lam = _terms(*args, lam)
    qa, qb, qc = lam * b1 * c, b1 + b2 - a * c - lam * b1 * c, -b1
    with np.errstate(invalid="ignore", divide="ignore"):
        q = -0.5 * (qb + np.copysign(np.sqrt(qb**2 - 4.0 * qa * qc), qb))  # stable roots
        e_a = np.where(lam > 0, np.where(qa > 0, q / qa, np.inf), np.nan)
        e_b = np.where(lam > 0, np.where(q != 0, qc / q, r / (1.0 + r)), np.nan)
    lam1, nodes = np.where(lam > 0, lam, 1.0), np.sqrt(a)
    f_a, f_b = (
        np.where(lam > 0, refined_frequency(np.where(np.isnan(e), 0.0, e), *args, lam1), nodes)
        for e in (e_a, e_b)
    )
    low = f_b <= f_a
    return (
        (np.where(low, f_b, f_a), np.where(low, f_a, f_b)),
        (np.where(low, e_b, e_a), np.where(low, e_a, e_b)),
    )


def refined_equal_stiffness(
    free_frequency, rigid_body_frequency, mode, ball_mass_ratio, antinodes=False
):
    """K1 = K2 as printed: roots of (3.5) and frequencies by (3.4), or with ``antinodes``
    (2m = l n) roots of (3.10) and frequencies by (3.9). Returns ((f_pos, f_neg) [Hz],
    (e_pos, e_neg) [-]), the positive root first (the paper's epsilon_1):

    (3.5):  4 kappa (1+m^-2)^-1 e^2 + [8 - kappa (f*/f_1)^2 - 4 kappa (1+m^-2)^-1] e - 4 = 0
    (3.4):  f^2 = {f*^2 + 4 (1+m^-2)^-1 f_1^2 [e^2 + (1-e)^2]} [1 + kappa e^2 (1+m^-2)^-1]^-1
    (3.10): 8 kappa (1+m^-2)^-1 e^2 + [8 - kappa (f*/f_1)^2 - 8 kappa (1+m^-2)^-1] e - 4 = 0
    (3.9):  f^2 = {f*^2 + 8 (1+m^-2)^-1 f_1^2 [e^2 + (1-e)^2]} [1 + 2 kappa e^2 (1+m^-2)^-1]^-1

    Parameters
    ----------
    free_frequency, rigid_body_frequency : float or array
        f*_m [Hz] and f_1 > 0 [Hz].
    mode : int or array
        m >= 1 [-].
    ball_mass_ratio : float or array
        kappa > 0 [-].
    antinodes : bool
        Use (3.10) and (3.9) [-].

    Examples
    --------
    >>> f, e = refined_equal_stiffness(16.2, 2.5, 5, 0.33)  # seed 000, 310, m = 5
    >>> [round(float(x), 3) for x in f + e]
    [11.796, 17.287, 6.129, -0.514]
    """
    m = _modes(mode)
    fs = _arr("free_frequency", free_frequency, "[Hz]")
    f1 = _arr("rigid_body_frequency", rigid_body_frequency, "[Hz]", True)
    kappa = _arr("ball_mass_ratio", ball_mass_ratio, "[-]", True)
    lam = 2.0 if antinodes else 1.0
    k = 4.0 * lam * kappa * _g(m)
    b = 8.0 - kappa * (fs / f1) ** 2 - k
    root = np.sqrt(b**2 + 16.0 * k)
    eps = ((-b + root) / (2.0 * k), (-b - root) / (2.0 * k))
    return tuple(
        np.sqrt(
            (fs**2 + 4.0 * lam * _g(m) * f1**2 * (e**2 + (1.0 - e) ** 2))
            / (1.0 + lam * kappa * e**2 * _g(m))
        )
        for e in eps
    ), eps


def linear_stiffness_ratio(outer_constant, inner_constant):
    """K1 / K2 = (K_o / K_i)^(2/3): both contacts carry the same Q and dQ/d(delta) =
    1.5 K^(2/3) Q^(1/3), so the ratio of linearised stiffnesses is load-free [-].

    Parameters
    ----------
    outer_constant, inner_constant : float or array
        K_o and K_i in Q = K delta^1.5 [N/m^1.5].
    """
    return (
        _arr("outer_constant", outer_constant, "[N/m^1.5]", True)
        / _arr("inner_constant", inner_constant, "[N/m^1.5]", True)
    ) ** (2.0 / 3.0)


# ---------------------------------------------------------------- layer 3: the analysis
