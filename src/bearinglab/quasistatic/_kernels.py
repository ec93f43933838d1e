"""Per-ball contact forces and their derivatives (the hot loop of the quasi-static model).

Vectorised NumPy over balls j (first axis) and contacts k (second axis). Notation in a
ball's plane: v = b - c (ball centre minus groove centre), n = v/|v|,
delta = |v| - (R - D_w/2) + h (the film is a layer between the surfaces: for given
centres it adds to the elastic approach, seed 001 eq. 2), c = |n_rho| = |cos alpha|, Q = K(c) max(delta, 0)^1.5,
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
        EHL film thickness between the surfaces, added to the approach [m].

    Returns
    -------
    q, n_rho, n_z, delta, s : arrays (Z, C), (Z, C), (Z, C), (Z, C), (Z, C, 2, 2)
        Contact loads [N], unit normals [-], approaches [m] and S [N/m].
    """
    v_rho = b_rho[:, None] - c_rho
    v_z = b_z[:, None] - c_z
    dist = np.hypot(v_rho, v_z)
    n_rho, n_z = v_rho / dist, v_z / dist
    delta = dist - free + film
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


# ------------------------------------------------------------------ ball equilibrium

#: A full Newton step is accepted unless it multiplies the ball's residual by more than this.
NONMONOTONE_FACTOR = 1000.0
# The NumPy solver iterates all balls together; the compiled twin below iterates each
# ball on its own. tests/unit/test_quasistatic_kernels.py checks that they agree.


def seat_loose_balls(b, c_rho, c_z, free, outer, q, fc, k_seat):
    """Move balls with no loaded outer contact radially out onto the outer race.

    Parameters
    ----------
    b : array (Z, 2)
        Ball centres (rho, z) [m].
    c_rho, c_z, free : arrays (Z, C)
        Groove centres and free distances [m].
    outer : bool array (C,)
        Outer-ring contacts.
    q : array (Z, C)
        Contact loads [N].
    fc : float
        Outward force on a ball [N].
    k_seat : float
        Load-deflection constant used to size the seating approach [N/m^1.5].
    """
    loose = ~np.any(q[:, outer] > 0, axis=1)
    if not np.any(loose):
        return b
    target = free[:, outer] + (fc / k_seat) ** (2.0 / 3.0)
    dz = np.clip(b[:, 1:2] - c_z[:, outer], -0.9 * target, 0.9 * target)
    rho = c_rho[:, outer] + np.sqrt(target**2 - dz**2)
    b = b.copy()
    b[loose, 0] = np.max(rho, axis=1)[loose]
    return b


def solve_balls_numpy(b, c_rho, c_z, free, radius, side, z0, k_poly, film, outer, fc, k_seat,
                      tol, ext, max_iterations=100):
    """Newton's method on every ball's equilibrium (all balls at once, NumPy).

    ``fc`` is the outward (centrifugal) force and ``ext`` (Z, 2) any further force on each
    ball held fixed during the solve (the gyroscopic friction force) [N].
    Returns (b, q, n_rho, n_z, delta, s, worst residual [N], converged). A ball whose
    contact loads are all below 10 tol is loose and its residual is not required to vanish.
    """
    def state(bb):
        return contact_state(bb[:, 0], bb[:, 1], c_rho, c_z, free, radius, side, z0, k_poly,
                             film)

    def residual(q, n_rho, n_z):
        return np.stack([fc + ext[:, 0] - np.sum(q * n_rho, axis=1),
                         ext[:, 1] - np.sum(q * n_z, axis=1)], axis=1)

    q = state(b)[0]
    b = seat_loose_balls(b, c_rho, c_z, free, outer, q, fc, k_seat)
    q, n_rho, n_z, delta, s = state(b)
    g = residual(q, n_rho, n_z)
    for _ in range(max_iterations):
        norm = np.hypot(g[:, 0], g[:, 1])
        norm[np.max(q, axis=1) <= 10.0 * tol] = 0.0                          # loose balls
        # a ball on the outer race alone exerts nothing on the inner ring: 10 % of its own
        # force is close enough (it rides a tilted groove on a weak tangential stiffness)
        free_ball = ~np.any(q[:, ~outer] > 0, axis=1) & (norm <= 0.1 * (fc + q.sum(axis=1)))
        norm[free_ball] = 0.0
        if np.all(norm <= tol):
            return b, q, n_rho, n_z, delta, s, float(np.max(norm)), True
        sb = s.sum(axis=1)
        det = sb[:, 0, 0] * sb[:, 1, 1] - sb[:, 0, 1] * sb[:, 1, 0]
        ok = np.abs(det) > 0
        step = np.zeros_like(b)
        step[ok, 0] = (sb[ok, 1, 1] * g[ok, 0] - sb[ok, 0, 1] * g[ok, 1]) / det[ok]
        step[ok, 1] = (-sb[ok, 1, 0] * g[ok, 0] + sb[ok, 0, 0] * g[ok, 1]) / det[ok]
        lam = np.ones(len(b))
        for _ in range(30):                                                  # backtracking
            trial = b + lam[:, None] * step
            trial_state = state(trial)
            g_new = residual(*trial_state[:3])
            # a full Newton step may raise the residual of a Hertz contact approached from
            # the soft side before it converges: accept it unless it grows 1000-fold
            allowed = np.where(lam == 1.0, NONMONOTONE_FACTOR, 1 - 1e-4 * lam) * norm
            worse = (np.hypot(g_new[:, 0], g_new[:, 1]) > allowed) & (norm > tol) & (lam > 1e-6)
            if not np.any(worse):
                break
            lam = np.where(worse, 0.5 * lam, lam)
        b = seat_loose_balls(trial, c_rho, c_z, free, outer, trial_state[0], fc, k_seat)
        q, n_rho, n_z, delta, s = state(b)
        g = residual(q, n_rho, n_z)
        if np.max(np.abs(lam[:, None] * step)) < 1e-16 and np.all(
                np.hypot(g[:, 0], g[:, 1]) <= 1e3 * tol):                     # round-off floor
            return b, q, n_rho, n_z, delta, s, float(np.max(np.hypot(g[:, 0], g[:, 1]))), True
    return b, q, n_rho, n_z, delta, s, float(np.max(np.hypot(g[:, 0], g[:, 1]))), False


try:  # the compiled twin; the NumPy version above is the reference and the fallback
    import numba
except ImportError:  # pragma: no cover - numba is a dependency, but keep working without
    numba = None

if numba is not None:
    @numba.njit(cache=True)
    def _one_ball(br, bz, c_rho, c_z, free, radius, side, z0, k_poly, film, q, nr, nz, dl, s):
        """Contacts of one ball (the loop body of contact_state); returns (g_rho, g_z)
        without the centrifugal force."""
        ncon, npoly = k_poly.shape
        g_rho = 0.0
        g_z = 0.0
        for k in range(ncon):
            v_rho = br - c_rho[k]
            v_z = bz - c_z[k]
            dist = np.sqrt(v_rho * v_rho + v_z * v_z)
            n_r = v_rho / dist
            n_zz = v_z / dist
            delta = dist - free[k] + film[k]
            c = abs(n_r)
            kk = 0.0
            dk = 0.0
            for p in range(npoly):
                kk = kk * c + k_poly[k, p]
                if p < npoly - 1:
                    dk = dk * c + k_poly[k, p] * (npoly - 1 - p)
            valid = side[k] == 0 or side[k] * (z0[k] + radius[k] * n_zz) > 0
            nr[k] = n_r
            nz[k] = n_zz
            dl[k] = delta
            if delta > 0 and valid:
                root = np.sqrt(delta)
                qk = kk * delta * root
                sgn = 1.0 if n_r > 0 else (-1.0 if n_r < 0 else 0.0)
                dq_dn = 1.5 * kk * root
                dq_dc = dk * delta * root
                gr = dq_dn * n_r + dq_dc * sgn * (1.0 - n_r * n_r) / dist
                gz = dq_dn * n_zz + dq_dc * sgn * (-n_r * n_zz) / dist
                t = qk / dist
                s[k, 0, 0] = n_r * gr + t * (1.0 - n_r * n_r)
                s[k, 0, 1] = n_r * gz - t * n_r * n_zz
                s[k, 1, 0] = n_zz * gr - t * n_zz * n_r
                s[k, 1, 1] = n_zz * gz + t * (1.0 - n_zz * n_zz)
                q[k] = qk
                g_rho -= qk * n_r
                g_z -= qk * n_zz
            else:
                q[k] = 0.0
                s[k, :, :] = 0.0
        return g_rho, g_z

    @numba.njit(cache=True)
    def _outer_only(q, outer):
        for k in range(len(outer)):
            if not outer[k] and q[k] > 0:
                return False
        return True

    @numba.njit(cache=True)
    def _seat(br, bz, c_rho, c_z, free, outer, q, fc, k_seat):
        for k in range(len(outer)):
            if outer[k] and q[k] > 0:
                return br
        best = -1e300
        for k in range(len(outer)):
            if outer[k]:
                target = free[k] + (fc / k_seat) ** (2.0 / 3.0)
                dz = min(max(bz - c_z[k], -0.9 * target), 0.9 * target)
                best = max(best, c_rho[k] + np.sqrt(target * target - dz * dz))
        return best

    @numba.njit(cache=True)
    def solve_balls_numba(b, c_rho, c_z, free, radius, side, z0, k_poly, film, outer, fc,
                          k_seat, tol, ext, max_iterations=100):
        """Compiled twin of :func:`solve_balls_numpy`, one ball at a time."""
        nb, ncon = c_rho.shape
        b = b.copy()
        q = np.zeros((nb, ncon))
        nr = np.zeros((nb, ncon))
        nz = np.zeros((nb, ncon))
        dl = np.zeros((nb, ncon))
        s = np.zeros((nb, ncon, 2, 2))
        tq = np.zeros(ncon)
        tr = np.zeros(ncon)
        tz = np.zeros(ncon)
        td = np.zeros(ncon)
        ts = np.zeros((ncon, 2, 2))
        worst = 0.0
        converged = True
        for j in range(nb):
            br, bz = b[j, 0], b[j, 1]
            _one_ball(br, bz, c_rho[j], c_z[j], free[j], radius, side, z0, k_poly, film[j],
                      q[j], nr[j], nz[j], dl[j], s[j])
            br = _seat(br, bz, c_rho[j], c_z[j], free[j], outer, q[j], fc, k_seat)
            gr, gz = _one_ball(br, bz, c_rho[j], c_z[j], free[j], radius, side, z0, k_poly,
                               film[j], q[j], nr[j], nz[j], dl[j], s[j])
            gr += fc + ext[j, 0]
            gz += ext[j, 1]
            done = False
            for _ in range(max_iterations):
                norm = np.sqrt(gr * gr + gz * gz)
                if norm <= tol or np.max(q[j]) <= 10.0 * tol or (
                        _outer_only(q[j], outer) and norm <= 0.1 * (fc + q[j].sum())):
                    done = True
                    break
                a = s[j, :, 0, 0].sum()
                bb = s[j, :, 0, 1].sum()
                c = s[j, :, 1, 0].sum()
                d = s[j, :, 1, 1].sum()
                det = a * d - bb * c
                if det == 0.0:
                    break
                step_r = (d * gr - bb * gz) / det
                step_z = (-c * gr + a * gz) / det
                lam = 1.0
                for _ in range(30):
                    nr_t = br + lam * step_r
                    nz_t = bz + lam * step_z
                    tgr, tgz = _one_ball(nr_t, nz_t, c_rho[j], c_z[j], free[j], radius, side,
                                         z0, k_poly, film[j], tq, tr, tz, td, ts)
                    tgr += fc + ext[j, 0]
                    tgz += ext[j, 1]
                    allowed = (NONMONOTONE_FACTOR if lam == 1.0 else 1 - 1e-4 * lam) * norm
                    if np.sqrt(tgr * tgr + tgz * tgz) <= allowed or lam <= 1e-6:
                        break
                    lam *= 0.5
                br = _seat(nr_t, nz_t, c_rho[j], c_z[j], free[j], outer, tq, fc, k_seat)
                bz = nz_t
                gr, gz = _one_ball(br, bz, c_rho[j], c_z[j], free[j], radius, side, z0, k_poly,
                                   film[j], q[j], nr[j], nz[j], dl[j], s[j])
                gr += fc + ext[j, 0]
                gz += ext[j, 1]
                moved = lam * np.sqrt(step_r * step_r + step_z * step_z)
                if moved < 1e-16 and np.sqrt(gr * gr + gz * gz) <= 1e3 * tol:
                    done = True
                    break
            b[j, 0] = br
            b[j, 1] = bz
            res = np.sqrt(gr * gr + gz * gz) if np.max(q[j]) > 10.0 * tol else 0.0
            if _outer_only(q[j], outer) and res <= 0.1 * (fc + q[j].sum()):
                res = 0.0
            worst = max(worst, res)
            converged = converged and done
        return b, q, nr, nz, dl, s, worst, converged
else:  # pragma: no cover
    solve_balls_numba = None
