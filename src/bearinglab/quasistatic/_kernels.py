"""Per-ball contact forces and their derivatives (the hot loop of the quasi-static model).

Vectorised NumPy over balls j (first axis) and contacts k (second axis). Notation in a
ball's plane: v = b - c (ball centre minus groove centre), n = v/|v|,
delta = |v| - (R - D_w/2) - h, c = |n_rho| = |cos alpha|, Q = K(c) max(delta, 0)^1.5,
force on the ball G = -Q n, and S = -dG/dv = n (dQ/dv)^T + Q (I - n n^T)/|v| with
dQ/dv = 1.5 K delta^0.5 n + delta^1.5 K'(c) sign(n_rho) (e_rho - n_rho n)/|v|.
"""

from __future__ import annotations

import numpy as np


def contact_state(b_rho, b_z, c_rho, c_z, free, radius, side, z0, k_poly, film):
    """Contact loads, normals and tangent matrices of every (ball, contact) pair.

    Parameters
    ----------
    b_rho, b_z : array (Z,)
        Ball centres [m].
    c_rho, c_z : array (Z, C)
        Groove centres, displaced with their rings [m].
    free, radius, side, z0 : array (C,)
        R - D_w/2 [m], R [m], arch side (+1/-1/0) [-], nominal axial offset of the centre
        from its groove's mid-plane [m].
    k_poly : array (C, P)
        K(c) polynomial coefficients, highest power first [N/m^1.5].
    film : array (Z, C)
        EHL film thickness subtracted from the approach [m].

    Returns
    -------
    q, n_rho, n_z, delta, s : arrays (Z, C), (Z, C), (Z, C), (Z, C), (Z, C, 2, 2)
        Contact loads [N], unit normals [-], approaches [m] and S [N/m].
    """
    v_rho = b_rho[:, None] - c_rho
    v_z = b_z[:, None] - c_z
    dist = np.hypot(v_rho, v_z)
    n_rho, n_z = v_rho / dist, v_z / dist
    delta = dist - free - film
    c = np.abs(n_rho)
    k = np.zeros_like(c)
    dk = np.zeros_like(c)
    degree = k_poly.shape[1] - 1
    for p in range(degree + 1):                 # Horner for K and K'
        k = k * c + k_poly[:, p]
        if p < degree:
            dk = dk * c + k_poly[:, p] * (degree - p)
    valid = (side == 0) | (side * (z0 + radius * n_z) > 0)
    active = (delta > 0) & valid
    dpos = np.where(active, delta, 0.0)
    root = np.sqrt(dpos)
    q = k * dpos * root
    sgn = np.sign(n_rho)
    dq_dn = 1.5 * k * root                       # dQ/ddelta
    dq_dc = dk * dpos * root                     # dQ/dc
    # dQ/dv = dq_dn n + dq_dc sgn (e_rho - n_rho n)/|v|
    g_rho = dq_dn * n_rho + dq_dc * sgn * (1.0 - n_rho * n_rho) / dist
    g_z = dq_dn * n_z + dq_dc * sgn * (-n_rho * n_z) / dist
    t = q / dist
    s = np.empty(q.shape + (2, 2))
    s[..., 0, 0] = n_rho * g_rho + t * (1.0 - n_rho * n_rho)
    s[..., 0, 1] = n_rho * g_z - t * n_rho * n_z
    s[..., 1, 0] = n_z * g_rho - t * n_z * n_rho
    s[..., 1, 1] = n_z * g_z + t * (1.0 - n_z * n_z)
    s[~active] = 0.0
    return q, n_rho, n_z, delta, s


def ring_jacobian(psi, rho, z):
    """T (Z, C, 2, 5): displacement (rho, z) of a ring point at (rho, z) of ball j's plane
    per ring displacement (x, y, z, tilt_x, tilt_y), small rotations.

    Parameters
    ----------
    psi : array (Z,)
        Ball azimuths [rad].
    rho, z : array (C,)
        Nominal position of the point in the ball's plane [m].
    """
    cs, sn = np.cos(psi)[:, None], np.sin(psi)[:, None]
    t = np.zeros((len(psi), len(rho), 2, 5))
    t[..., 0, 0] = cs
    t[..., 0, 1] = sn
    t[..., 0, 3] = -z * sn
    t[..., 0, 4] = z * cs
    t[..., 1, 2] = 1.0
    t[..., 1, 3] = rho * sn
    t[..., 1, 4] = -rho * cs
    return np.broadcast_to(t, (len(psi), len(rho), 2, 5)).copy()
