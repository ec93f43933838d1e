"""Groove geometry of a ball bearing in the plane of one ball (layer 1/2).

Each ring has one groove centre (circular groove) or two (gothic arch of a four-point or
split-race bearing, seed 001 figs. 1-3: arch angle alpha_T). A ball contacts a groove
half when its centre is farther than R - D_w/2 from that half's centre (R = f D_w); the
approach is delta = |b - c| - (R - D_w/2) (seed 001 eq. 2: AB = R_e + R_n - D_w + delta_e +
delta_n, summed over both rings).

Positions in a ball's plane are (rho, z): radius from the bearing axis and axial
coordinate (docs/conventions.md). With both rings centred, the groove centres sit at

- outer: rho = d_m/2 - (R_o - D_w/2) cos(alpha_To) + P_d/4,   z = +-(R_o - D_w/2) sin(alpha_To)
- inner: rho = d_m/2 + (R_i - D_w/2) cos(alpha_Ti) - P_d/4,   z = +-(R_i - D_w/2) sin(alpha_Ti)

so that their radial distance is H = (R_i - D_w/2) cos(alpha_Ti) + (R_o - D_w/2) cos(alpha_To)
- P_d/2 (seed 001 eq. 6 with g = P_d) and a centred ball on the pitch circle just touches
every half when P_d = 0. For circular grooves (alpha_T = 0) this is Harris's
A cos(alpha_0) = A - P_d/2.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..contact import hertz
from ..geometry import BallBearing
from ..materials import effective_modulus

#: Degree of the polynomial K(|cos alpha|) fitted to the exact Hertz constant.
_K_DEGREE = 6


@dataclass(frozen=True)
class ContactSet:
    """The groove halves a ball can touch, as arrays over contacts k.

    Attributes: ``ring`` (0 inner, 1 outer), ``rho0``, ``z0`` (centres with rings centred)
    [m], ``free_distance`` R - D_w/2 [m], ``groove_radius`` R [m], ``side`` (+1/-1: the
    half of an arch the contact must lie on, relative to the groove's mid-plane; 0 for a
    circular groove) and ``k_poly`` (coefficients of K(c) = sum a_n c^n, c = |cos alpha|,
    highest power first [N/m^1.5]).
    """

    ring: np.ndarray
    rho0: np.ndarray
    z0: np.ndarray
    free_distance: np.ndarray
    groove_radius: np.ndarray
    side: np.ndarray
    k_poly: np.ndarray

    @property
    def count(self) -> int:
        return len(self.ring)

    @property
    def k_radial(self) -> np.ndarray:
        """K at a zero contact angle (c = 1), per contact [N/m^1.5]."""
        return self.k_poly.sum(axis=1)


def _k_poly(bearing: BallBearing, race: str) -> np.ndarray:
    """Fit K(|cos alpha|) of one race over 0..90 deg (exact Hertz, SciPy integrals)."""
    e_prime = effective_modulus(bearing.ball_material, bearing.ring_material)
    c = np.linspace(0.0, 1.0, 41)
    f = bearing.inner_groove_factor if race == "inner" else bearing.outer_groove_factor
    from ..geometry import contact_radii

    rx, ry = contact_radii(bearing.ball_diameter, bearing.pitch_diameter, f, np.arccos(c), race)
    k = hertz.load_deflection_constant(rx, np.full_like(rx, ry), e_prime)
    coef = np.polyfit(c, k, _K_DEGREE)
    fit_error = np.max(np.abs(np.polyval(coef, c) / k - 1))
    if fit_error > 1e-6:  # pragma: no cover - guards the fit, not user input
        raise RuntimeError(f"K(cos alpha) fit error {fit_error:.1e} for the {race} race")
    return coef


@functools.lru_cache(maxsize=64)
def contact_set(bearing: BallBearing) -> ContactSet:
    """Groove halves of both rings for ``bearing`` (see the module docstring).

    Cached per bearing (the Hertz fit is the costly part of a solve).

    Parameters
    ----------
    bearing : BallBearing
        Geometry; ``diametral_clearance`` is P_d (g of seed 001) and
        ``inner_arch_angle``/``outer_arch_angle`` the gothic-arch angles alpha_T [m, rad].
    """
    inner_arch_angle, outer_arch_angle = bearing.inner_arch_angle, bearing.outer_arch_angle
    dw, dm, pd = bearing.ball_diameter, bearing.pitch_diameter, bearing.diametral_clearance
    rows = []
    for ring, race, f, arch in (
        (0, "inner", bearing.inner_groove_factor, inner_arch_angle),
        (1, "outer", bearing.outer_groove_factor, outer_arch_angle),
    ):
        radius = f * dw
        free = radius - 0.5 * dw
        sign = 1.0 if race == "inner" else -1.0  # inner centres lie outward of the ball
        rho = 0.5 * dm + sign * (free * math.cos(arch) - 0.25 * pd)
        poly = _k_poly(bearing, race)
        halves = ((0.0, 0.0),) if arch == 0.0 else ((+1.0, -1.0), (-1.0, +1.0))
        for offset_sign, side in halves:
            rows.append((ring, rho, offset_sign * free * math.sin(arch), free, radius, side, poly))
    ring, rho, z, free, radius, side, poly = zip(*rows, strict=True)
    return ContactSet(
        np.array(ring),
        np.array(rho),
        np.array(z),
        np.array(free),
        np.array(radius),
        np.array(side),
        np.array(poly),
    )
