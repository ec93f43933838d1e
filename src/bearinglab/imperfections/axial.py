"""Axial shift of a ball between 3-D wavy raceways (seed 002, eqs. 7-9) (layer 1).

Seed 002 (Sun & An 2021), sec. 1.2, in the plane through the bearing axis and ball j
(Y radial, Z axial; fig. 3):

- eq. 7, the profiles touching the ball: outer raceway y_1(z) = y_o + dh_o + sqrt(r_o^2 -
  z^2), inner raceway y_2(z) = y_i + dh_i - sqrt(r_i^2 - z^2), ball surface y_3(z) =
  d_m/2 +- sqrt((D/2)^2 - (z - z_b)^2) (upper and lower halves), dh the raceway
  deviations at the ball's circumferential position (outward positive, as eq. 10);
- eq. 8, the ball touches each raceway first where the radial gap is smallest:
  z_ob = argmin [y_1(z) - y_3^+(z)], z_ib = argmin [y_3^-(z) - y_2(z)];
- eq. 9, the ball is in equilibrium only when its inner and outer contact forces are
  collinear, i.e. the contacts are symmetric about the ball centre,
  z_ib - z_b = z_b - z_ob; the seed "keeps changing z_b" until this holds.

The contact angle beta_j of eqs. 10-12 (Q' = Q cos(beta), Q'' = Q sin(beta)) is then the
angle of the line through both contacts and the ball centre: sin(beta) = (z_ob - z_b)/(D/2).
Here the root of eq. 9 is found by bisection on z_b, for all balls at once; eq. 8 is
evaluated on a fine axial grid with a parabolic refinement of the discrete minimum. The
deviation is applied radially at the same z (the seed's eq. 7 moves the groove circle by
dh along its normal, (sin(alpha), cos(alpha)); the two differ by second-order terms in
dh and the slope). Because eq. 8 is unchanged by a constant added to a gap, the radial
positions of the ball and the groove centres drop out: only their axial positions matter.
With flat raceways, circular grooves and the inner ring offset axially by s, the root is
z_b = s (r_o - D/2)/A and sin(beta) = s/A (A = r_i + r_o - D), which is the free contact
angle at s = A sin(alpha_0); s = 0 gives z_b = 0 and beta = 0 (deep-groove nominal).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, InputError
from .waviness import finite, index


@dataclass(frozen=True)
class AxialShift:
    """Where a ball settles axially between wavy raceways (seed 002 eqs. 7-9).

    Attributes (arrays over balls, or scalars)
    ------------------------------------------
    ball_shift : z_b, axial position of the ball centre from the outer groove's
        mid-plane [m].
    inner_contact_z, outer_contact_z : z_ib, z_ob, axial positions of the contacts in the
        outer ring's (bearing) frame [m].
    contact_angle : beta, positive when the line from the inner to the outer contact
        leans towards +z (docs/conventions.md) [rad].
    inner_deviation, outer_deviation : raceway deviations dh_i, dh_o at the contacts
        (radial, outward positive; seed 002 eq. 10 uses them) [m].
    residual : z_ib + z_ob - 2 z_b left at the root [m]: 0 for smooth profiles; on rough
        surfaces the contact can jump between two crests as z_b changes, and eq. 9 then
        changes sign across the jump instead of passing through zero (the ball rocks
        between two contact spots); the residual is the size of that jump.
    """

    ball_shift: np.ndarray
    inner_contact_z: np.ndarray
    outer_contact_z: np.ndarray
    contact_angle: np.ndarray
    inner_deviation: np.ndarray
    outer_deviation: np.ndarray
    residual: np.ndarray


def _flat(z):
    return np.zeros_like(z)


def _sample(profile, z, name):
    try:
        values = np.asarray(profile(z), dtype=float)
    except TypeError:
        raise InputError(name, profile, "a callable h(z) -> array (..., n) [m] or None") from None
    if values.shape[-1:] != z.shape or not np.all(np.isfinite(values)):
        raise InputError(name, profile, f"a callable returning finite values (..., {z.size}) [m]")
    return values


def _argmin_refined(gap, z):
    """z of the smallest gap along the last axis, refined by a parabola through the
    discrete minimum and its neighbours; also the fractional grid index."""
    n = z.size
    k = np.argmin(gap, axis=-1)
    kk = np.clip(k, 1, n - 2)
    g0 = np.take_along_axis(gap, kk[..., None] - 1, -1)[..., 0]
    g1 = np.take_along_axis(gap, kk[..., None], -1)[..., 0]
    g2 = np.take_along_axis(gap, kk[..., None] + 1, -1)[..., 0]
    curvature = g0 - 2.0 * g1 + g2
    ok = np.isfinite(curvature) & (curvature > 0) & (k == kk)
    offset = np.where(ok, 0.5 * (g0 - g2) / np.where(ok, curvature, 1.0), 0.0)
    position = k + np.clip(offset, -0.5, 0.5)
    return z[0] + position * (z[1] - z[0]), position


def _interpolate(values, position):
    """Linear interpolation of values (..., n) at fractional grid positions (...)."""
    n = values.shape[-1]
    k = np.clip(np.floor(position).astype(np.intp), 0, n - 2)
    f = position - k
    v0 = np.take_along_axis(values, k[..., None], -1)[..., 0]
    v1 = np.take_along_axis(values, k[..., None] + 1, -1)[..., 0]
    return v0 + f * (v1 - v0)


def ball_axial_shift(
    bearing,
    inner_height=None,
    outer_height=None,
    *,
    inner_offset: float = 0.0,
    points: int = 1201,
    tolerance: float = 1e-10,
) -> AxialShift:
    """Axial position of each ball and its contact angle between 3-D wavy raceways.

    Seed 002, eqs. 7-9 (module docstring), vectorised over balls (or any leading axes the
    profiles return).

    Parameters
    ----------
    bearing : BallBearing
        Geometry: D_w and the groove radii r_i = f_i D_w, r_o = f_o D_w (circular grooves).
    inner_height, outer_height : callable or None
        h(z) -> array (..., n): radial deviation (outward positive) of the inner / outer
        raceway along the axial coordinate z (n,) of that ring's own frame, at the balls'
        circumferential positions [m]; None for a perfect raceway.
    inner_offset : float
        Axial position s of the inner ring (its groove's mid-plane) relative to the outer
        ring's [m].
    points : int
        Axial grid points over the ball's reach for eq. 8 [-], >= 101.
    tolerance : float
        Bisection stops when the bracket on z_b is narrower than this [m].

    Returns
    -------
    AxialShift

    Raises
    ------
    ConvergenceError
        When eq. 9 has no sign change within +-D_w/4 (profiles too steep to hold the ball).

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3)
    >>> r = ball_axial_shift(b, outer_height=lambda z: 1e-3 * z)    # outer race tilted
    >>> bool(r.ball_shift > 0), bool(r.contact_angle < 0)
    (True, True)
    """
    n = index("points", points, "an integer >= 101", 101)
    s = finite("inner_offset", inner_offset, "an axial offset [m]")
    tol = finite("tolerance", tolerance, "a length > 0 [m]")
    if tol <= 0:
        raise InputError("tolerance", tolerance, "a length > 0 [m]")
    radius = 0.5 * bearing.ball_diameter
    r_i = bearing.inner_groove_factor * bearing.ball_diameter
    r_o = bearing.outer_groove_factor * bearing.ball_diameter
    if abs(s) > 0.5 * radius:
        raise InputError("inner_offset", inner_offset, f"within +-{0.5 * radius:.4g} m (D_w/4)")
    reach = 1.5 * radius + abs(s)
    z = np.linspace(-reach, reach, n)
    h_o = _sample(outer_height or _flat, z, "outer_height")
    h_i = _sample(inner_height or _flat, z - s, "inner_height")
    shape = np.broadcast_shapes(h_o.shape[:-1], h_i.shape[:-1])
    h_o = np.broadcast_to(h_o, shape + (n,))
    h_i = np.broadcast_to(h_i, shape + (n,))
    with np.errstate(invalid="ignore"):
        groove_o = np.where(np.abs(z) < r_o, np.sqrt(np.maximum(r_o**2 - z**2, 0.0)), np.nan)
        groove_i = np.where(
            np.abs(z - s) < r_i, np.sqrt(np.maximum(r_i**2 - (z - s) ** 2, 0.0)), np.nan
        )

    def contacts(z_b):
        d = z - z_b[..., None]
        inside = np.abs(d) < radius
        ball = np.sqrt(np.maximum(radius**2 - d**2, 0.0))
        gap_o = np.where(inside, groove_o + h_o - ball, np.inf)
        gap_i = np.where(inside, groove_i - h_i - ball, np.inf)
        gap_o = np.where(np.isnan(gap_o), np.inf, gap_o)
        gap_i = np.where(np.isnan(gap_i), np.inf, gap_i)
        (z_ob, p_o), (z_ib, p_i) = _argmin_refined(gap_o, z), _argmin_refined(gap_i, z)
        return z_ib, z_ob, p_i, p_o

    def balance(z_b):
        z_ib, z_ob = contacts(z_b)[:2]
        return z_ib + z_ob - 2.0 * z_b

    lo = np.full(shape, -0.5 * radius)
    hi = np.full(shape, 0.5 * radius)
    f_lo, f_hi = balance(lo), balance(hi)
    if np.any(f_lo > 0) or np.any(f_hi < 0):
        raise ConvergenceError(
            "seed 002 eq. 9: no axial ball position within +-D_w/4 makes the "
            "inner and outer contacts collinear (raceway profiles too steep)"
        )
    while np.max(hi - lo) > tol:
        mid = 0.5 * (lo + hi)
        f_mid = balance(mid)
        below = f_mid < 0
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    z_b = 0.5 * (lo + hi)
    z_ib, z_ob, p_i, p_o = contacts(z_b)
    half = 0.5 * (z_ob - z_ib)
    angle = np.arcsin(np.clip(half / radius, -1.0, 1.0))
    return AxialShift(
        ball_shift=z_b[()],
        inner_contact_z=z_ib[()],
        outer_contact_z=z_ob[()],
        contact_angle=angle[()],
        inner_deviation=_interpolate(h_i, p_i)[()],
        outer_deviation=_interpolate(h_o, p_o)[()],
        residual=(z_ib + z_ob - 2.0 * z_b)[()],
    )
