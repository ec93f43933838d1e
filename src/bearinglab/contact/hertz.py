"""Hertz theory of elliptical point contact (layer 1: pure, vectorised functions).

Sources:
- Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*, 5th ed., 2007,
  ch. 6: curvature difference F(rho) = ((k^2 + 1) E - 2 K) / ((k^2 - 1) E) (eq. 6.9 there,
  K, E the complete elliptic integrals of the first and second kind of modulus
  e = sqrt(1 - 1/k^2)); semi-axes a = a* (3 Q / (2 Sum rho) eta)^(1/3),
  b = b* (...)^(1/3) with a* = (2 k^2 E / pi)^(1/3), b* = (2 E / (pi k))^(1/3); approach
  delta = delta* (3 Q / (2 Sum rho) eta)^(2/3) Sum rho / 2, delta* = (2 K / pi)
  (pi / (2 k^2 E))^(1/3); eta = (1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b.
- Hamrock B. J., Brewe D. E., "Simplified solution for stresses and deformations",
  J. Lubr. Technol. 105 (1983) 171-177: k = 1.0339 (R_y/R_x)^0.6360,
  E = 1.0003 + 0.5968 R_x/R_y, K = 1.5277 + 0.6023 ln(R_y/R_x) (the ``hamrock_brewe``
  method), and the same contact in the form a = (6 k^2 E W R / (pi E'))^(1/3),
  b = (6 E W R / (pi k E'))^(1/3), delta = K (9 / (2 E R) (W / (pi k E'))^2)^(1/3),
  p_max = 3 W / (2 pi a b), with 1/R = 1/R_x + 1/R_y.
The elliptic integrals (argument m = e^2) come from the arithmetic-geometric mean
(:mod:`.elliptic`; the same values as SciPy's ``ellipk``/``ellipe`` to a few ulp).

The exact and Hertz-form expressions above are algebraically identical; this module
uses the Hamrock form throughout and only swaps how k, K and E are obtained.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import ConvergenceError, InputError
from .elliptic import complete_elliptic, ellipk_ellipe

Method = Literal["exact", "hamrock_brewe"]
METHODS = ("exact", "hamrock_brewe")


#: Range of R_y/R_x over which :func:`ellipticity` is tested (``exact``); it usually
#: converges beyond it, and reports a :class:`ConvergenceError` where it does not.
RATIO_RANGE = (1.0, 1e8)


def _log_ratio(u):
    """ln(R_y/R_x) of the exact relation as a function of u = ln k (k = a/b > 1).

    R_y/R_x = (k^2 E - K)/(K - E) = (m K - (K - E)) / (p (K - E)), m = 1 - 1/k^2,
    p = 1/k^2 = 1 - m, with K and K - E from the AGM given both m and p
    (:func:`.elliptic.complete_elliptic`), so that neither k -> 1 nor k -> infinity loses
    precision.
    """
    u = np.asarray(u, dtype=float)
    p = np.exp(-2.0 * u)
    m = -np.expm1(-2.0 * u)
    kk, diff = complete_elliptic(p, m)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.log(m * kk - diff) - np.log(p) - np.log(diff)


def _solve_log_k(target, iterations: int = 60):
    """u = ln k with _log_ratio(u) = target (array, target > 0): secant iterations from
    the Hamrock-Brewe start, then SciPy's brentq on [target/2, target] per element for
    any that did not converge (the exact k lies between sqrt(R_y/R_x) and R_y/R_x)."""
    u_prev = np.log(1.0339) + 0.6360 * target
    g_prev = _log_ratio(u_prev) - target
    u = np.maximum(u_prev - g_prev / 1.6, 0.5 * target)
    done = np.zeros(target.shape, dtype=bool)
    for _ in range(iterations):
        g = _log_ratio(u) - target
        done |= np.abs(g) <= 1e-15 * np.maximum(1.0, target)
        if np.all(done):
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            step = g * (u - u_prev) / (g - g_prev)
        step = np.where(done | ~np.isfinite(step), 0.0, step)
        u_prev, g_prev = u, g
        u = np.clip(u - step, 0.5 * target, target)
    g = _log_ratio(u) - target
    bad = ~(np.abs(g) <= 1e-13 * np.maximum(1.0, target))
    for i in zip(*np.nonzero(bad), strict=False):
        t = float(target[i])
        try:
            from scipy import optimize  # the rare fallback; costs ~0.2 s to import

            u[i] = optimize.brentq(
                lambda x, t=t: float(_log_ratio(x)) - t,
                0.5 * t,
                t,
                xtol=1e-15 * t,
                rtol=4 * np.finfo(float).eps,
                maxiter=200,
            )
        except (ValueError, RuntimeError) as exc:
            raise ConvergenceError(
                f"ellipticity: no solution for R_y/R_x = {np.exp(t)!r} ({exc})"
            ) from None
    return u


def ellipticity(radius_ratio, method: Method = "exact"):
    """Ellipticity k = a/b of the contact ellipse from alpha_r = R_y/R_x >= 1.

    ``exact`` solves R_y/R_x = (k^2 E(m) - K(m)) / (K(m) - E(m)), m = 1 - 1/k^2 (the
    exact relation of Harris & Kotzalas eq. 6.9 rewritten) for u = ln k by secant steps
    started from the Hamrock-Brewe value, with a bracketed Brent search as fallback;
    the relative residual in R_y/R_x is below 1e-12 for 1 <= R_y/R_x <= 1e8 (tested).
    ``hamrock_brewe`` returns the fit 1.0339 alpha_r^0.6360 (1.0339 at alpha_r = 1, as
    the fit is used consistently with :func:`elliptic_integrals`).

    Parameters
    ----------
    radius_ratio : float or array
        alpha_r = R_y / R_x [-], >= 1 (the larger radius over the smaller).
    method : {"exact", "hamrock_brewe"}
        How k is obtained.

    Raises
    ------
    ConvergenceError
        If the exact relation cannot be solved to a relative residual of 1e-10.

    Examples
    --------
    >>> round(float(ellipticity(1.0)), 6)
    1.0
    >>> round(float(ellipticity(15.0)), 3), round(float(ellipticity(15.0, "hamrock_brewe")), 3)
    (5.8, 5.787)
    >>> round(float(ellipticity(1.0, "hamrock_brewe")), 4)
    1.0339
    """
    ratio = np.asarray(radius_ratio, dtype=float)
    if np.any(~np.isfinite(ratio)) or np.any(ratio < 1.0):
        raise InputError("radius_ratio", radius_ratio, "finite values >= 1 (R_y/R_x)")
    if method == "hamrock_brewe":
        return (1.0339 * ratio**0.6360)[()]
    if method != "exact":
        raise InputError("method", method, f"one of {METHODS}")
    near_circle = ratio < 1.0 + 1e-14  # k - 1 < 1e-14: the circle to double precision
    target = np.atleast_1d(np.log(np.where(near_circle, 2.0, ratio)))
    u = _solve_log_k(target).reshape(ratio.shape)
    k = np.exp(u)
    residual = np.abs(np.expm1(_log_ratio(u) - target.reshape(ratio.shape)))
    if np.any(~np.isfinite(k)) or np.any(~(residual <= 1e-10)):
        raise ConvergenceError(
            f"ellipticity: no solution for R_y/R_x = {ratio!r} "
            f"(relative residual {np.nanmax(residual):.2e})"
        )
    return np.where(near_circle, 1.0, k)[()]


def elliptic_integrals(k, radius_ratio=None, method: Method = "exact"):
    """Complete elliptic integrals (K, E) of the first and second kind for ellipticity k.

    ``exact`` uses the AGM (:mod:`.elliptic`, as scipy.special.ellipk/ellipe) with
    m = 1 - 1/k^2; ``hamrock_brewe``
    uses K = 1.5277 + 0.6023 ln(alpha_r), E = 1.0003 + 0.5968 / alpha_r.

    Parameters
    ----------
    k : float or array
        Ellipticity a/b [-].
    radius_ratio : float or array, optional
        alpha_r = R_y/R_x [-]; needed for ``hamrock_brewe``.
    method : {"exact", "hamrock_brewe"}
        Which formulas.
    """
    if method == "hamrock_brewe":
        ratio = np.asarray(radius_ratio, dtype=float)
        return 1.5277 + 0.6023 * np.log(ratio), 1.0003 + 0.5968 / ratio
    m = 1.0 - 1.0 / np.asarray(k, dtype=float) ** 2
    return ellipk_ellipe(m)


@dataclass(frozen=True)
class PointContact:
    """Results of one (or an array of) Hertz point contacts, SI units.

    Attributes: load Q [N], semi_major a and semi_minor b [m] (a across the rolling
    direction when R_y >= R_x), ellipticity k = a/b [-], max_pressure [Pa],
    approach delta [m], stiffness dQ/d(delta) = 1.5 Q / delta [N/m], the elliptic
    integrals first_kind K and second_kind E [-], and the reduced radius R [m].
    """

    load: np.ndarray
    semi_major: np.ndarray
    semi_minor: np.ndarray
    ellipticity: np.ndarray
    max_pressure: np.ndarray
    approach: np.ndarray
    stiffness: np.ndarray
    first_kind: np.ndarray
    second_kind: np.ndarray
    reduced_radius: np.ndarray

    @property
    def mean_pressure(self):
        """Mean contact pressure Q / (pi a b) = 2/3 p_max [Pa]."""
        return self.load / (np.pi * self.semi_major * self.semi_minor)


def _radii(rx, ry):
    rx, ry = np.asarray(rx, dtype=float), np.asarray(ry, dtype=float)
    if np.any(~np.isfinite(rx)) or np.any(rx <= 0) or np.any(~np.isfinite(ry)) or np.any(ry <= 0):
        raise InputError(
            "rx, ry",
            (rx, ry),
            "positive effective radii [m] (convex-equivalent contact: 1/R_x > 0 and 1/R_y > 0)",
        )
    return rx, ry


def _shape(rx, ry, method: Method):
    """k, K, E and the reduced radius R for effective radii R_x, R_y."""
    rx, ry = _radii(rx, ry)
    ratio = np.maximum(rx, ry) / np.minimum(rx, ry)
    k = ellipticity(ratio, method)
    first, second = elliptic_integrals(k, ratio, method)
    return k, first, second, 1.0 / (1.0 / rx + 1.0 / ry)


def _check_load(load):
    q = np.asarray(load, dtype=float)
    if np.any(~np.isfinite(q)) or np.any(q < 0):
        raise InputError("load", load, "finite contact loads >= 0 [N]")
    return q


def point_contact(load, rx, ry, effective_modulus, method: Method = "exact") -> PointContact:
    """Hertz point contact for contact loads Q between bodies of effective radii R_x, R_y.

    Vectorised over ``load`` (and the radii, which broadcast with it).

    Parameters
    ----------
    load : float or array
        Normal contact load Q [N], >= 0.
    rx, ry : float or array
        Effective radii in the rolling (x) and transverse (y) directions [m], > 0.
    effective_modulus : float
        E' = 2 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b) [Pa].
    method : {"exact", "hamrock_brewe"}
        Ellipticity and elliptic integrals exact (SciPy) or by Hamrock-Brewe.

    Examples
    --------
    >>> c = point_contact(1000.0, 3.23e-3, 0.165, 228.6e9)
    >>> round(float(c.max_pressure) / 1e9, 2)
    2.32
    """
    q = _check_load(load)
    if not (np.isfinite(effective_modulus) and effective_modulus > 0):
        raise InputError("effective_modulus", effective_modulus, "a positive modulus [Pa]")
    k, first, second, r = _shape(rx, ry, method)
    e_prime = float(effective_modulus)
    a = np.cbrt(6.0 * k**2 * second * q * r / (np.pi * e_prime))
    b = np.cbrt(6.0 * second * q * r / (np.pi * k * e_prime))
    delta = first * np.cbrt(9.0 / (2.0 * second * r)) * np.cbrt(q / (np.pi * k * e_prime)) ** 2
    with np.errstate(invalid="ignore", divide="ignore"):
        p_max = np.where(q > 0, 1.5 * q / (np.pi * a * b), 0.0)
        # dQ/d(delta) = 1.5 K delta^0.5 = 1.5 Q / delta (Q = K delta^1.5); 0 at zero load
        stiffness = np.where(delta > 0, 1.5 * q / delta, 0.0)
    return PointContact(
        *(
            np.asarray(v)[()]
            for v in (
                q,
                a,
                b,
                np.broadcast_to(k, np.shape(a)),
                p_max,
                delta,
                stiffness,
                np.broadcast_to(first, np.shape(a)),
                np.broadcast_to(second, np.shape(a)),
                np.broadcast_to(r, np.shape(a)),
            )
        )
    )


def load_deflection_constant(rx, ry, effective_modulus, method: Method = "exact"):
    """K in Q = K delta^1.5 for one point contact [N/m^1.5].

    From the approach formula: K = pi k E' sqrt(2 E R / 9) / K_1^1.5, with K_1, E the
    elliptic integrals of the first and second kind (Hamrock & Brewe 1983).

    Parameters
    ----------
    rx, ry : float or array
        Effective radii [m].
    effective_modulus : float
        E' [Pa].
    method : {"exact", "hamrock_brewe"}
        How k, K_1 and E are obtained.
    """
    k, first, second, r = _shape(rx, ry, method)
    return np.pi * k * effective_modulus * np.sqrt(2.0 * second * r / 9.0) / first**1.5


def approach(load, rx, ry, effective_modulus, method: Method = "exact"):
    """Mutual approach delta = (Q / K)^(2/3) of the two bodies [m].

    Parameters
    ----------
    load : float or array
        Q [N], >= 0.
    rx, ry, effective_modulus, method
        As in :func:`load_deflection_constant`.
    """
    q = _check_load(load)
    return (q / load_deflection_constant(rx, ry, effective_modulus, method)) ** (2.0 / 3.0)


def load_from_approach(delta, rx, ry, effective_modulus, method: Method = "exact"):
    """Contact load Q = K max(delta, 0)^1.5 for an approach delta [N] (inverse of
    :func:`approach`; no tension, so a negative approach gives 0).

    Parameters
    ----------
    delta : float or array
        Mutual approach [m].
    rx, ry, effective_modulus, method
        As in :func:`load_deflection_constant`.
    """
    d = np.asarray(delta, dtype=float)
    if np.any(~np.isfinite(d)):
        raise InputError("delta", delta, "finite approaches [m]")
    return load_deflection_constant(rx, ry, effective_modulus, method) * np.maximum(d, 0.0) ** 1.5


def series_constant(inner_constant, outer_constant):
    """Load-deflection constant of a ball between both races [N/m^1.5].

    Two Hertz contacts in series carry the same load, so the approaches add:
    K_n = (K_i^(-2/3) + K_o^(-2/3))^(-3/2) (Harris & Kotzalas, eq. for K_n).

    Parameters
    ----------
    inner_constant, outer_constant : float or array
        K_i and K_o [N/m^1.5].

    Examples
    --------
    >>> round(float(series_constant(8.0, 8.0)), 6)  # equal springs: K / 2^1.5
    2.828427
    """
    return (
        np.asarray(inner_constant, float) ** (-2.0 / 3.0)
        + np.asarray(outer_constant, float) ** (-2.0 / 3.0)
    ) ** -1.5
