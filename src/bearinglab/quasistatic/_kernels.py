"""Per-ball contact forces and their derivatives (the hot loop of the quasi-static model):
the NumPy twin of the compiled kernels in _ball.py and _ball_set.py.

Vectorised NumPy over balls j (first axis) and contacts k (second axis). Notation in a
ball's plane: v = b - c (ball centre minus groove centre), n = v/|v|,
delta = |v| - (R - D_w/2) + h (the film is a layer between the surfaces: for given
centres it adds to the elastic approach, seed 001 eq. 2), c = |n_rho| = |cos alpha|,
Q = K(c) max(delta, 0)^1.5,
force on the ball G = -Q n, and S = -dG/dv = n (dQ/dv)^T + Q (I - n n^T)/|v| with
dQ/dv = 1.5 K delta^0.5 n + delta^1.5 K'(c) sign(n_rho) (e_rho - n_rho n)/|v|.

Speed forces (centrifugal force and gyroscopic friction, gyroscopic.py) depend on the
ball's contact angles; their derivatives D_l (total) and E_l (inner friction) with respect
to each contact vector v_l are taken by central differences. With P_l = -S_l + D_l (how
the ball's total force changes with v_l) and Phi'_l = [l inner] (-T_l^T S_l) +
Tbar^T E_l (how the ball's push on the inner ring changes; Tbar the load-weighted T of
the inner contacts, where the inner friction's reaction acts), the condensed stiffness of
ball j is K_j = (sum_l Phi'_l) (sum_l P_l)^-1 (sum_in P_l T_l) - sum_in Phi'_l T_l,
which without speed forces is sum T^T S T - (sum T^T S)(sum S)^-1 (sum S T).
"""

from __future__ import annotations

from typing import NamedTuple

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
    for p in range(degree + 1):  # Horner for K and K'
        k = k * c + k_poly[:, p]
        if p < degree:
            dk = dk * c + k_poly[:, p] * (degree - p)
    valid = (side == 0) | (side * (z0 + radius * n_z) > 0)
    active = (delta > 0) & valid
    dpos = np.where(active, delta, 0.0)
    root = np.sqrt(dpos)
    q = k * dpos * root
    sgn = np.sign(n_rho)
    dq_dn = 1.5 * k * root  # dQ/ddelta
    dq_dc = dk * dpos * root  # dQ/dc
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


class BallSet(NamedTuple):
    """What stays fixed while the balls and the inner ring move (one solve), handed to the
    ball and ring kernels, compiled and NumPy, as one argument (numba takes a named tuple
    of arrays); built by :meth:`bearinglab.quasistatic.solver._Problem.ball_set`.

    Attributes
    ----------
    t : array (Z, C, 2, 5)
        Ring kinematics T (:func:`ring_jacobian`).
    c0_rho, c0_z : arrays (Z, C)
        Groove centres with the inner ring centred (the outer ring's misalignment in) [m].
    inner : bool array (C,)
        Inner-ring contacts.
    free : array (Z, C)
        R - D_w/2 of each ball and contact [m] (the ball's diameter error in).
    radius, side, z0, k_poly, film
        As in :func:`contact_state`.
    ring : int array (C,)
        Ring of each contact (0 inner, 1 outer).
    control, lam_i : arrays (Z,)
        Raceway control (0 outer, 1 inner) and lambda_i of each ball (see _ball.py).
    spd : array (8,)
        Speed parameters (see _ball.py).
    k_seat : float
        Load-deflection constant sizing the seat of a loose ball [N/m^1.5].
    """

    t: np.ndarray
    c0_rho: np.ndarray
    c0_z: np.ndarray
    inner: np.ndarray
    free: np.ndarray
    radius: np.ndarray
    side: np.ndarray
    z0: np.ndarray
    k_poly: np.ndarray
    film: np.ndarray
    ring: np.ndarray
    control: np.ndarray
    lam_i: np.ndarray
    spd: np.ndarray
    k_seat: float

    def rows(self, balls) -> BallSet:
        """The set of the balls selected by ``balls`` (an index or mask over Z)."""
        return self._replace(**{name: getattr(self, name)[balls] for name in _PER_BALL})


#: The fields of a BallSet with one row per ball.
_PER_BALL = ("t", "c0_rho", "c0_z", "free", "film", "control", "lam_i")


# ------------------------------------------------------------------ ball equilibrium

#: A full Newton step is accepted unless it multiplies the ball's residual by more than this.
NONMONOTONE_FACTOR = 1000.0
#: Relative finite-difference step of the speed-force derivatives (times R - D_w/2).
FD_STEP = 1e-6
#: Blend of a lightly loaded ball from the cage's speed to Jones's (see _ball.py).
DRIVE_SHARE = 0.05
# The NumPy solver iterates all balls together; the compiled twin (_ball.py) iterates
# each ball on its own. tests/unit/test_quasistatic_kernels.py checks that they agree.


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


def speed_forces(q, n_rho, n_z, ring, control, lam_i, spd):
    """Speed forces on every ball (Z, 7): total F_rho, F_z, inner-friction F_rho, F_z,
    omega_m [rad/s], M_g [N m], F_c [N] (gyroscopic.py; ``spd`` as in _ball.py)."""
    from .gyroscopic import raceway_control_kinematics

    omega, g, hmd, inertia, dw, gyro, wm0, floor = spd
    inner = ring == 0
    angle = np.arctan2(np.where(inner, -n_z, n_z), np.abs(n_rho))
    loaded = q > 0
    qi = np.where(loaded & inner, q, 0.0).sum(axis=1)
    qo = np.where(loaded & ~inner, q, 0.0).sum(axis=1)
    ai = np.where(loaded & inner, q * angle, 0.0).sum(axis=1) / np.where(qi > 0, qi, 1.0)
    ao = np.where(loaded & ~inner, q * angle, 0.0).sum(axis=1) / np.where(qo > 0, qo, 1.0)
    x = np.minimum(np.minimum(qi, qo) / max(DRIVE_SHARE * hmd * wm0 * wm0, 1e-300), 1.0)
    ramp = np.where((qi > 0) & (qo > 0), x * x * (3 - 2 * x), 0.0)
    both = (ramp > 0) & (omega > 0)
    s = np.where(ao > 0, 1.0, np.where(ao < 0, -1.0, np.where(ai >= 0, 1.0, -1.0)))
    a_i, a_o = s * ai, s * ao
    out = np.zeros((len(q), 7))
    wm = np.full(len(q), wm0)
    mg = np.zeros(len(q))
    for code, name in ((0, "outer"), (1, "inner")):
        sel = both & (control == code)
        if np.any(sel):
            beta, orbit, spin = raceway_control_kinematics(a_i[sel], a_o[sel], g, name)
            wm[sel] = wm0 + ramp[sel] * (omega * orbit - wm0)
            if gyro > 0:
                mg[sel] = ramp[sel] * inertia * np.abs(spin) * omega**2 * orbit * np.sin(beta)
    lo = 2.0 - lam_i
    out[:, 2] = -lam_i * mg / dw * np.sin(a_i)
    out[:, 3] = s * lam_i * mg / dw * np.cos(a_i)
    fc = np.maximum(hmd * wm * wm, floor)
    out[:, 0] = fc + lo * mg / dw * np.sin(a_o) + out[:, 2]
    out[:, 1] = -s * lo * mg / dw * np.cos(a_o) + out[:, 3]
    out[:, 4], out[:, 5], out[:, 6] = wm, mg, fc
    return out


def _speed_derivatives(b, c_rho, c_z, balls, state):
    """D (Z, C, 2, 2) and E (Z, C, 2, 2): central differences of the total speed force and
    of the inner friction with respect to each contact vector v_l = b - c_l."""
    q, n_rho, n_z = state[:3]
    nb, ncon = q.shape
    d = np.zeros((nb, ncon, 2, 2))
    e = np.zeros((nb, ncon, 2, 2))
    for col in range(ncon):
        h = FD_STEP * balls.free[:, col]
        one_contact = slice(col, col + 1)
        for a in range(2):
            for sign in (1.0, -1.0):
                shift = np.zeros((nb, 2))
                shift[:, a] = sign * h
                one = contact_state(
                    b[:, 0] + shift[:, 0],
                    b[:, 1] + shift[:, 1],
                    c_rho[:, one_contact],
                    c_z[:, one_contact],
                    balls.free[:, one_contact],
                    balls.radius[one_contact],
                    balls.side[one_contact],
                    balls.z0[one_contact],
                    balls.k_poly[one_contact],
                    balls.film[:, one_contact],
                )
                qq, rr, zz = q.copy(), n_rho.copy(), n_z.copy()
                qq[:, col], rr[:, col], zz[:, col] = one[0][:, 0], one[1][:, 0], one[2][:, 0]
                sp = speed_forces(qq, rr, zz, balls.ring, balls.control, balls.lam_i, balls.spd)
                w = (sign / (2.0 * h))[:, None]
                d[:, col, :, a] += w * sp[:, 0:2]
                e[:, col, :, a] += w * sp[:, 2:4]
    # as the compiled twin: unloaded contacts and balls not on both races add nothing
    inner = balls.ring == 0
    both = np.any(q[:, inner] > 0, axis=1) & np.any(q[:, ~inner] > 0, axis=1)
    keep = (q > 0) & both[:, None]
    d[~keep] = 0.0
    e[~keep] = 0.0
    return d, e


def condense(t, inner, state, sp, d, e):
    """Force of the balls on the inner ring (5,) and the condensed stiffness (5, 5)."""
    q, n_rho, n_z, _, s = state
    t_in = t[:, inner]
    qi = np.where(inner, q, 0.0).sum(axis=1)
    w = np.where(inner[None, :], q, 0.0) / np.where(qi > 0, qi, 1.0)[:, None]
    tbar = np.einsum("jk,jkab->jab", w, t)  # (Z, 2, 5)
    p = d - s  # (Z, C, 2, 2)
    phi = np.einsum("jad,jkab->jkdb", tbar, e)  # (Z, C, 5, 2)
    phi[:, inner] -= np.einsum("jkad,jkab->jkdb", t_in, s[:, inner])
    psum = p.sum(axis=1)
    det = psum[:, 0, 0] * psum[:, 1, 1] - psum[:, 0, 1] * psum[:, 1, 0]
    safe = np.where(det != 0, det, 1.0)
    inv = np.empty_like(psum)
    inv[:, 0, 0], inv[:, 1, 1] = psum[:, 1, 1] / safe, psum[:, 0, 0] / safe
    inv[:, 0, 1], inv[:, 1, 0] = -psum[:, 0, 1] / safe, -psum[:, 1, 0] / safe
    inv[det == 0] = 0.0
    a5 = phi.sum(axis=1)
    bm = np.einsum("jkab,jkbd->jad", p[:, inner], t_in)
    cm = np.einsum("jkab,jkbd->ad", phi[:, inner], t_in)
    stiffness = np.einsum("jab,jbc,jcd->ad", a5, inv, bm) - cm
    g_in = np.stack([q[:, inner] * n_rho[:, inner], q[:, inner] * n_z[:, inner]], axis=-1)
    force = np.einsum("jkab,jka->b", t_in, g_in) - np.einsum("jab,ja->b", tbar, sp[:, 2:4])
    return force, stiffness


def solve_balls_numpy(b, c_rho, c_z, balls, tol, max_iterations=100):
    """Newton's method on every ball's equilibrium (all balls at once, NumPy twin of
    _ball_set.solve_balls, same arguments and returns: b, q, n_rho, n_z, delta, speed
    (Z, 7), force (5,), stiffness (5, 5), worst residual [N], converged).

    A ball whose contact loads are all below 10 tol is loose and its residual is not
    required to vanish; every other ball must be in equilibrium to ``tol``. Balls not fully
    driven by both races orbit at the mean orbital speed of those that are (a second pass
    for them, as in the compiled twin).
    """
    spd = np.array(balls.spd, dtype=float)
    balls = balls._replace(spd=spd)  # spd[6] becomes the cage speed of the driven balls
    inner, ring, control, lam_i = balls.inner, balls.ring, balls.control, balls.lam_i
    b, st, norm, ok = _solve_all(b, c_rho, c_z, balls, tol, max_iterations)
    if spd[0] > 0:
        q = st[0]
        qi, qo = q[:, inner].sum(axis=1), q[:, ~inner].sum(axis=1)
        driven = (qi > 0) & (qo > 0) & (np.minimum(qi, qo) >= DRIVE_SHARE * spd[2] * spd[6] ** 2)
        if 0 < driven.sum() < len(b):
            spd[6] = float(np.mean(speed_forces(*st[:3], ring, control, lam_i, spd)[driven, 4]))
            rest = ~driven
            b2, st2, norm2, ok2 = _solve_all(
                b[rest], c_rho[rest], c_z[rest], balls.rows(rest), tol, max_iterations
            )
            b = b.copy()
            b[rest] = b2
            st = tuple(
                np.where(rest.reshape((-1,) + (1,) * (a.ndim - 1)), _spread(a2, rest), a)
                for a, a2 in zip(st, st2, strict=True)
            )
            norm[rest] = norm2
            ok = ok and ok2
    sp = speed_forces(*st[:3], ring, control, lam_i, spd)
    if spd[0] > 0:
        d, e = _speed_derivatives(b, c_rho, c_z, balls, st)
    else:
        d = e = np.zeros(st[4].shape)
    force, stiffness = condense(balls.t, inner, st, sp, d, e)
    return b, st[0], st[1], st[2], st[3], sp, force, stiffness, float(np.max(norm)), ok


def _spread(values, rows):
    """Rows of a subset put back in full size (zeros elsewhere)."""
    out = np.zeros((len(rows),) + values.shape[1:])
    out[rows] = values
    return out


def _solve_all(b, c_rho, c_z, balls, tol, max_iterations):
    """The Newton iteration over all given balls at once; returns (b, state, residuals,
    converged)."""
    spd, free, outer, k_seat = balls.spd, balls.free, ~balls.inner, balls.k_seat
    fc_seat = max(spd[2] * spd[6] ** 2, spd[7])
    contacts = (free, balls.radius, balls.side, balls.z0, balls.k_poly, balls.film)

    def state(bb):
        return contact_state(bb[:, 0], bb[:, 1], c_rho, c_z, *contacts)

    def residual(st):
        sp = speed_forces(st[0], st[1], st[2], balls.ring, balls.control, balls.lam_i, spd)
        return np.stack(
            [sp[:, 0] - np.sum(st[0] * st[1], axis=1), sp[:, 1] - np.sum(st[0] * st[2], axis=1)],
            axis=1,
        )

    b = seat_loose_balls(b, c_rho, c_z, free, outer, state(b)[0], fc_seat, k_seat)
    st = state(b)
    g = residual(st)
    converged = False
    for _ in range(max_iterations):
        norm = np.hypot(g[:, 0], g[:, 1])
        norm[np.max(st[0], axis=1) <= 10.0 * tol] = 0.0  # loose balls
        if np.all(norm <= tol):
            converged = True
            break
        if spd[0] > 0:
            d = _speed_derivatives(b, c_rho, c_z, balls, st)[0]
        else:
            d = 0.0
        jb = (d - st[4]).sum(axis=1)  # sum_l P_l
        det = jb[:, 0, 0] * jb[:, 1, 1] - jb[:, 0, 1] * jb[:, 1, 0]
        ok = np.abs(det) > 0
        step = np.zeros_like(b)
        step[ok, 0] = -(jb[ok, 1, 1] * g[ok, 0] - jb[ok, 0, 1] * g[ok, 1]) / det[ok]
        step[ok, 1] = -(-jb[ok, 1, 0] * g[ok, 0] + jb[ok, 0, 0] * g[ok, 1]) / det[ok]
        lam = np.ones(len(b))
        for _ in range(30):  # backtracking
            trial = b + lam[:, None] * step
            trial_state = state(trial)
            g_new = residual(trial_state)
            # a full Newton step may raise the residual of a Hertz contact approached from
            # the soft side before it converges: accept it unless it grows 1000-fold
            allowed = np.where(lam == 1.0, NONMONOTONE_FACTOR, 1 - 1e-4 * lam) * norm
            worse = (np.hypot(g_new[:, 0], g_new[:, 1]) > allowed) & (norm > tol) & (lam > 1e-6)
            if not np.any(worse):
                break
            lam = np.where(worse, 0.5 * lam, lam)
        b = seat_loose_balls(trial, c_rho, c_z, free, outer, trial_state[0], fc_seat, k_seat)
        st = state(b)
        g = residual(st)
        if np.max(np.abs(lam[:, None] * step)) < 1e-16 and np.all(
            np.hypot(g[:, 0], g[:, 1]) <= 1e3 * tol
        ):  # round-off floor
            converged = True
            break
    norm = np.hypot(g[:, 0], g[:, 1])
    norm[np.max(st[0], axis=1) <= 10.0 * tol] = 0.0
    return b, st, norm, converged
