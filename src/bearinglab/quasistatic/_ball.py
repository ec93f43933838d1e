"""Compiled equilibrium of one ball (numba, ``cache=True``): its contacts, its speed forces
(centrifugal force, gyroscopic friction) and their derivatives, seating a loose ball on the
outer race, and Newton's method on the ball's position (:func:`solve_ball`). The set of
balls and the condensed ring force and stiffness are in _ball_set.py; the ring iteration in
_ring.py.

The NumPy twin is :func:`bearinglab.quasistatic._kernels.solve_balls_numpy`;
tests/unit/test_quasistatic_kernels.py checks that they agree. Notation as in _kernels.py;
the speed forces are those of :mod:`bearinglab.quasistatic.gyroscopic` (Jones's raceway
control, Harris's friction split, [Harris2007b] ch. 3).

Every function here is a module-level ``numba.njit(cache=True)`` function that calls only
other module-level compiled functions (no function arguments), so that a new process loads
them all from numba's on-disk cache.

Speed parameters ``spd`` (float array): shaft speed omega [rad/s], gamma' = D_w/d_m [-],
m d_m / 2 [kg m], ball inertia J [kg m^2], D_w [m], gyroscopic (1/0), the cage speed of
balls not driven by both races omega_c0 [rad/s], the floor of the outward force [N].
Per ball: ``control`` (0 outer, 1 inner raceway control) and ``lam_i`` (share lambda_i of
the gyroscopic friction held at the inner contact; lambda_o = 2 - lambda_i).

What stays fixed while one ball is solved travels as one argument ``ball`` (a
:class:`Ball`, made by :func:`one_ball`).
"""

from __future__ import annotations

import math
from collections import namedtuple

import numba
import numpy as np

from ..engine.compiling import watch

watch()  # the first compile after install is told, not silent

#: One ball's constants: its groove centres c_rho, c_z (C,) [m], free distances R - D_w/2
#: (C,) [m], groove radii R (C,) [m], arch sides (C,) and z0 (C,) [m], K polynomials (C, P),
#: film (C,) [m], ring of each contact (C,) (0 inner, 1 outer), its raceway control and
#: lambda_i, and the speed parameters spd (see the module docstring and _kernels.py).
Ball = namedtuple("Ball", "c_rho c_z free radius side z0 k_poly film ring control lam_i spd")

#: Relative finite-difference step of the speed-force derivatives (times R - D_w/2).
FD_STEP = 1e-6
#: A full Newton step is accepted unless it multiplies the ball's residual by this.
NONMONOTONE_FACTOR = 1000.0


@numba.njit(cache=True)
def _contact(v_rho, v_z, free, radius, side, z0, kp, film, out):
    """One contact: out = (q, n_rho, n_z, delta, s00, s01, s10, s11)."""
    npoly = kp.shape[0]
    dist = math.sqrt(v_rho * v_rho + v_z * v_z)
    n_r = v_rho / dist
    n_z = v_z / dist
    delta = dist - free + film
    c = abs(n_r)
    kk = 0.0
    dk = 0.0
    for p in range(npoly):
        kk = kk * c + kp[p]
        if p < npoly - 1:
            dk = dk * c + kp[p] * (npoly - 1 - p)
    valid = side == 0 or side * (z0 + radius * n_z) > 0
    out[1] = n_r
    out[2] = n_z
    out[3] = delta
    if delta > 0 and valid:
        root = math.sqrt(delta)
        qk = kk * delta * root
        sgn = 1.0 if n_r > 0 else (-1.0 if n_r < 0 else 0.0)
        dq_dn = 1.5 * kk * root
        dq_dc = dk * delta * root
        gr = dq_dn * n_r + dq_dc * sgn * (1.0 - n_r * n_r) / dist
        gz = dq_dn * n_z + dq_dc * sgn * (-n_r * n_z) / dist
        t = qk / dist
        out[0] = qk
        out[4] = n_r * gr + t * (1.0 - n_r * n_r)
        out[5] = n_r * gz - t * n_r * n_z
        out[6] = n_z * gr - t * n_z * n_r
        out[7] = n_z * gz + t * (1.0 - n_z * n_z)
    else:
        out[0] = 0.0
        out[4] = 0.0
        out[5] = 0.0
        out[6] = 0.0
        out[7] = 0.0


#: A ball is driven by the races (Jones's kinematics) once its lighter contact carries this
#: share of the centrifugal force at the cage speed; below, it blends smoothly into the
#: cage's speed, so that a ball entering the load zone changes its speed forces
#: continuously (an abrupt switch stalls Newton's method at the edge of the load zone).
DRIVE_SHARE = 0.05


@numba.njit(cache=True)
def drive(qi, qo, fc0):
    """0 (carried by the cage) ... 1 (driven by both races): smoothstep of the lighter
    contact load over DRIVE_SHARE of the cage-speed centrifugal force."""
    if qi <= 0 or qo <= 0:
        return 0.0
    x = min(qi, qo) / max(DRIVE_SHARE * fc0, 1e-300)
    if x >= 1.0:
        return 1.0
    return x * x * (3.0 - 2.0 * x)


@numba.njit(cache=True)
def speed_force(q, nr, nz, ring, control, lam_i, spd, out):
    """Speed forces on one ball from its contacts (see gyroscopic.py):
    out = (F_rho, F_z total, inner-friction F_rho, F_z, omega_m, M_g, F_c)."""
    omega, g, hmd, inertia, dw, gyro, wm0, floor = (
        spd[0],
        spd[1],
        spd[2],
        spd[3],
        spd[4],
        spd[5],
        spd[6],
        spd[7],
    )
    qi = 0.0
    qo = 0.0
    ai = 0.0
    ao = 0.0
    for k in range(q.shape[0]):
        if q[k] > 0:
            if ring[k] == 0:
                qi += q[k]
                ai += q[k] * math.atan2(-nz[k], abs(nr[k]))
            else:
                qo += q[k]
                ao += q[k] * math.atan2(nz[k], abs(nr[k]))
    wm = wm0
    mg = 0.0
    fir = 0.0
    fiz = 0.0
    for_r = 0.0
    for_z = 0.0
    ramp = drive(qi, qo, hmd * wm0 * wm0)
    if ramp > 0 and omega > 0:
        ai /= qi
        ao /= qo
        s = 1.0 if ao > 0 else (-1.0 if ao < 0 else (1.0 if ai >= 0 else -1.0))
        a_i = s * ai
        a_o = s * ao
        if control == 0:
            beta = math.atan2(math.sin(a_o), math.cos(a_o) + g)
        else:
            beta = math.atan2(math.sin(a_i), math.cos(a_i) - g)
        big_a = math.cos(a_o - beta) / (1.0 + g * math.cos(a_o))
        big_b = math.cos(a_i - beta) / (1.0 - g * math.cos(a_i))
        wm = wm0 + ramp * (omega * big_a / (big_a + big_b) - wm0)
        if gyro > 0:
            spin = omega / (g * (big_a + big_b))
            mg = ramp * inertia * spin * omega * big_a / (big_a + big_b) * math.sin(beta)
            lo = 2.0 - lam_i
            for_r = lo * mg / dw * math.sin(a_o)
            for_z = -s * lo * mg / dw * math.cos(a_o)
            fir = -lam_i * mg / dw * math.sin(a_i)
            fiz = s * lam_i * mg / dw * math.cos(a_i)
    fc = max(hmd * wm * wm, floor)
    out[0] = fc + for_r + fir
    out[1] = for_z + fiz
    out[2] = fir
    out[3] = fiz
    out[4] = wm
    out[5] = mg
    out[6] = fc


@numba.njit(cache=True)
def one_ball(balls, j, c_rho, c_z, spd):
    """Ball j of a ball set (a _kernels.BallSet) with groove centres c_rho, c_z (Z, C)
    and speed parameters spd, as the kernels here take it (a :class:`Ball`)."""
    return Ball(
        c_rho[j],
        c_z[j],
        balls.free[j],
        balls.radius,
        balls.side,
        balls.z0,
        balls.k_poly,
        balls.film[j],
        balls.ring,
        balls.control[j],
        balls.lam_i[j],
        spd,
    )


@numba.njit(cache=True)
def _ball_force(br, bz, ball, q, nr, nz, dl, s, sp, tmp):
    """All contacts of ``ball`` at (br, bz) into q, nr, nz, dl, s; speed forces into sp;
    returns the total force on the ball (g_rho, g_z). ``tmp``: work array (8,)."""
    c_rho, c_z, free, radius, side, z0, k_poly, film, ring, control, lam_i, spd = ball
    ncon = c_rho.shape[0]
    g_rho = 0.0
    g_z = 0.0
    for k in range(ncon):
        _contact(
            br - c_rho[k], bz - c_z[k], free[k], radius[k], side[k], z0[k], k_poly[k], film[k], tmp
        )
        q[k] = tmp[0]
        nr[k] = tmp[1]
        nz[k] = tmp[2]
        dl[k] = tmp[3]
        s[k, 0, 0] = tmp[4]
        s[k, 0, 1] = tmp[5]
        s[k, 1, 0] = tmp[6]
        s[k, 1, 1] = tmp[7]
        g_rho -= tmp[0] * tmp[1]
        g_z -= tmp[0] * tmp[2]
    speed_force(q, nr, nz, ring, control, lam_i, spd, sp)
    return g_rho + sp[0], g_z + sp[1]


@numba.njit(cache=True)
def speed_derivatives(br, bz, ball, q, nr, nz, dmat, emat, work):
    """Central differences of the speed forces on the ball per contact vector v_l = b - c_l:
    dmat[lc] = d(total speed force)/dv_l, emat[lc] = d(inner friction)/dv_l (2 x 2 each).
    Zero for a ball not driven by both races (its speed forces do not depend on v) and for
    unloaded contacts. ``work``: (4, C + 8) work array."""
    c_rho, c_z, free, radius, side, z0, k_poly, film, ring, control, lam_i, spd = ball
    ncon = c_rho.shape[0]
    dmat[:] = 0.0
    emat[:] = 0.0
    qi = 0.0
    qo = 0.0
    for k in range(ncon):
        if ring[k] == 0:
            qi += q[k]
        else:
            qo += q[k]
    if spd[0] <= 0 or qi <= 0 or qo <= 0:
        return
    qq = work[0, :ncon]
    rr = work[1, :ncon]
    zz = work[2, :ncon]
    tmp = work[3, :8]
    sp = work[3, 8:15]
    qq[:] = q
    rr[:] = nr
    zz[:] = nz
    for lc in range(ncon):
        if q[lc] <= 0:
            continue
        h = FD_STEP * free[lc]
        for a in range(2):
            for sign in range(2):
                sg = 1.0 if sign == 0 else -1.0
                vr = br - c_rho[lc] + (sg * h if a == 0 else 0.0)
                vz = bz - c_z[lc] + (sg * h if a == 1 else 0.0)
                _contact(vr, vz, free[lc], radius[lc], side[lc], z0[lc], k_poly[lc], film[lc], tmp)
                qq[lc] = tmp[0]
                rr[lc] = tmp[1]
                zz[lc] = tmp[2]
                speed_force(qq, rr, zz, ring, control, lam_i, spd, sp)
                w = sg / (2.0 * h)
                dmat[lc, 0, a] += w * sp[0]
                dmat[lc, 1, a] += w * sp[1]
                emat[lc, 0, a] += w * sp[2]
                emat[lc, 1, a] += w * sp[3]
        qq[lc] = q[lc]
        rr[lc] = nr[lc]
        zz[lc] = nz[lc]


@numba.njit(cache=True)
def _seat(br, bz, c_rho, c_z, free, ring, q, fc, k_seat):
    """A ball with no loaded outer contact, put radially onto the outer race."""
    for k in range(ring.shape[0]):
        if ring[k] == 1 and q[k] > 0:
            return br
    best = -1e300
    for k in range(ring.shape[0]):
        if ring[k] == 1:
            target = free[k] + (fc / k_seat) ** (2.0 / 3.0)
            dz = min(max(bz - c_z[k], -0.9 * target), 0.9 * target)
            best = max(best, c_rho[k] + math.sqrt(target * target - dz * dz))
    return best


@numba.njit(cache=True)
def solve_ball(b, ball, k_seat, tol, max_iterations, q, nr, nz, dl, s, sp, dmat, emat, work, ts):
    """Newton's method on the equilibrium of ``ball``; b (2,) is updated in place. Returns
    (residual [N], converged). A ball whose loads are all below 10 tol is loose. ``work``:
    (10, C + 8) and ts (C, 2, 2) work arrays."""
    c_rho, c_z, free, ring, spd = ball.c_rho, ball.c_z, ball.free, ball.ring, ball.spd
    ncon = c_rho.shape[0]
    tq = work[4, :ncon]
    tr = work[5, :ncon]
    tz = work[6, :ncon]
    td = work[7, :ncon]
    tmp = work[8, :8]
    tsp = work[9, :7]
    br, bz = b[0], b[1]
    fc_seat = max(spd[2] * spd[6] * spd[6], spd[7])

    def force(r, z):  # net force at (r, z), into the ball's own contact arrays (inlined)
        return _ball_force(r, z, ball, q, nr, nz, dl, s, sp, tmp)

    force(br, bz)
    br = _seat(br, bz, c_rho, c_z, free, ring, q, fc_seat, k_seat)
    gr, gz = force(br, bz)
    done = False
    for _ in range(max_iterations):
        norm = math.sqrt(gr * gr + gz * gz)
        if norm <= tol or np.max(q) <= 10.0 * tol:
            done = True
            break
        speed_derivatives(br, bz, ball, q, nr, nz, dmat, emat, work)
        a = 0.0
        bb = 0.0
        c = 0.0
        d = 0.0
        for lc in range(ncon):  # sum_l P_l = sum_l (D_l - S_l): d force / d b
            a += dmat[lc, 0, 0] - s[lc, 0, 0]
            bb += dmat[lc, 0, 1] - s[lc, 0, 1]
            c += dmat[lc, 1, 0] - s[lc, 1, 0]
            d += dmat[lc, 1, 1] - s[lc, 1, 1]
        det = a * d - bb * c
        if det == 0.0:
            break
        step_r = -(d * gr - bb * gz) / det
        step_z = -(-c * gr + a * gz) / det
        lam = 1.0
        nr_t = br
        nz_t = bz
        for _ in range(30):
            nr_t = br + lam * step_r
            nz_t = bz + lam * step_z
            tgr, tgz = _ball_force(nr_t, nz_t, ball, tq, tr, tz, td, ts, tsp, tmp)
            allowed = (NONMONOTONE_FACTOR if lam == 1.0 else 1 - 1e-4 * lam) * norm
            if math.sqrt(tgr * tgr + tgz * tgz) <= allowed or lam <= 1e-6:
                break
            lam *= 0.5
        br = _seat(nr_t, nz_t, c_rho, c_z, free, ring, tq, fc_seat, k_seat)
        bz = nz_t
        gr, gz = force(br, bz)
        moved = lam * math.sqrt(step_r * step_r + step_z * step_z)
        if moved < 1e-16 and math.sqrt(gr * gr + gz * gz) <= 1e3 * tol:
            done = True
            break
    b[0] = br
    b[1] = bz
    res = math.sqrt(gr * gr + gz * gz) if np.max(q) > 10.0 * tol else 0.0
    return res, done
