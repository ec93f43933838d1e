"""Compiled equilibrium of the set of balls (numba, ``cache=True``): every ball solved by
:func:`bearinglab.quasistatic._ball.solve_ball` for given groove centres, a second pass at
the cage speed for the balls not driven by both races, and the condensed force and
stiffness of the balls on the inner ring; the ring iteration is in _ring.py.

The NumPy twins are :func:`bearinglab.quasistatic._kernels.solve_balls_numpy` (ball
equilibrium, speed forces, condensation) and :func:`bearinglab.quasistatic.solver._newton`
(the ring iteration); tests/unit/test_quasistatic_kernels.py checks that they agree.
Notation and the speed parameters ``spd`` as in _kernels.py and _ball.py.

Every function here is a module-level ``numba.njit(cache=True)`` function that calls only
module-level compiled functions, those of _ball.py as attributes of the module (no
function arguments, no imported names), so that a new process loads them all from numba's
on-disk cache. Numba's on-disk cache is keyed on each file alone: after editing
``_ball.py``, delete the cached ``_ball_set.*.nbi``/``*.nbc`` files in ``__pycache__`` (or
touch this file), or the set keeps the old ball kernels.
"""

from __future__ import annotations

import numba
import numpy as np

from ..engine.compiling import watch
from . import _ball

watch()  # the first compile after install is told, not silent


@numba.njit(cache=True)
def _condense(tj, inner, s, q, nr, nz, dmat, emat, sp, force, stiff, cw):
    """Add one ball's force on the inner ring and its condensed stiffness (see
    _kernels.py; tj = T of the ball (C, 2, 5)):
    K_j = (sum_l Phi'_l) (sum_l P_l)^-1 (sum_in P_l T_l) - sum_in Phi'_l T_l.
    ``cw``: work array (5, 19)."""
    ncon = q.shape[0]
    cw[:] = 0.0
    tbar = cw[:2, 0:5]
    a5 = cw[:, 5:7]
    bm = cw[:2, 7:12]
    cm = cw[:, 12:17]
    phi = cw[:, 17:19]
    qi = 0.0
    for k in range(ncon):
        if inner[k]:
            qi += q[k]
    if qi > 0:
        for k in range(ncon):
            if inner[k] and q[k] > 0:
                w = q[k] / qi
                for a in range(2):
                    for d in range(5):
                        tbar[a, d] += w * tj[k, a, d]
    p00 = 0.0
    p01 = 0.0
    p10 = 0.0
    p11 = 0.0
    for lc in range(ncon):
        if q[lc] <= 0:
            continue  # an unloaded contact adds nothing
        l00 = dmat[lc, 0, 0] - s[lc, 0, 0]
        l01 = dmat[lc, 0, 1] - s[lc, 0, 1]
        l10 = dmat[lc, 1, 0] - s[lc, 1, 0]
        l11 = dmat[lc, 1, 1] - s[lc, 1, 1]
        p00 += l00
        p01 += l01
        p10 += l10
        p11 += l11
        for d in range(5):
            for c in range(2):
                v = tbar[0, d] * emat[lc, 0, c] + tbar[1, d] * emat[lc, 1, c]
                if inner[lc]:
                    v -= tj[lc, 0, d] * s[lc, 0, c] + tj[lc, 1, d] * s[lc, 1, c]
                phi[d, c] = v
                a5[d, c] += v
        if inner[lc]:
            for d in range(5):
                bm[0, d] += l00 * tj[lc, 0, d] + l01 * tj[lc, 1, d]
                bm[1, d] += l10 * tj[lc, 0, d] + l11 * tj[lc, 1, d]
                for e in range(5):
                    cm[d, e] += phi[d, 0] * tj[lc, 0, e] + phi[d, 1] * tj[lc, 1, e]
    det = p00 * p11 - p01 * p10
    if det != 0.0:
        i00 = p11 / det
        i01 = -p01 / det
        i10 = -p10 / det
        i11 = p00 / det
        for d in range(5):
            r0 = a5[d, 0] * i00 + a5[d, 1] * i10
            r1 = a5[d, 0] * i01 + a5[d, 1] * i11
            for e in range(5):
                stiff[d, e] += r0 * bm[0, e] + r1 * bm[1, e]
    for d in range(5):
        for e in range(5):
            stiff[d, e] -= cm[d, e]
    for k in range(ncon):
        if inner[k] and q[k] > 0:
            for d in range(5):
                force[d] += tj[k, 0, d] * q[k] * nr[k] + tj[k, 1, d] * q[k] * nz[k]
    for d in range(5):
        force[d] -= tbar[0, d] * sp[2] + tbar[1, d] * sp[3]


@numba.njit(cache=True)
def solve_balls(b, c_rho, c_z, balls, tol, max_iterations=100):
    """Every ball's equilibrium for given groove centres c_rho, c_z (Z, C), the force of
    the balls on the inner ring (5,) and the condensed stiffness (5, 5); ``balls`` a
    _kernels.BallSet. Returns (b, q, n_rho, n_z, delta, speed (Z, 7), force, stiffness,
    worst residual [N], converged).

    Balls not fully driven by both races orbit at the cage speed: the mean orbital speed
    of the driven balls (whose speeds do not depend on it), so the balls are solved in two
    passes when some are driven and some not."""
    nb, ncon = c_rho.shape
    b = b.copy()
    q = np.zeros((nb, ncon))
    nr = np.zeros((nb, ncon))
    nz = np.zeros((nb, ncon))
    dl = np.zeros((nb, ncon))
    sp = np.zeros((nb, 7))
    s = np.zeros((nb, ncon, 2, 2))
    dmat = np.zeros((ncon, 2, 2))
    emat = np.zeros((ncon, 2, 2))
    work = np.zeros((10, ncon + 8))
    ts = np.zeros((ncon, 2, 2))
    cw = np.zeros((5, 19))
    res = np.zeros(nb)
    ok = np.zeros(nb, dtype=np.bool_)
    driven = np.zeros(nb, dtype=np.bool_)
    inner = balls.inner
    spd = balls.spd.copy()
    # Pass 0 solves every ball; pass 1 re-solves, at the cage speed of the driven balls,
    # those that are not driven by both races (only at speed and when some are driven).
    for sweep in range(2):
        for j in range(nb):
            if sweep == 0 or not driven[j]:
                ball = _ball.one_ball(balls, j, c_rho, c_z, spd)
                res[j], ok[j] = _ball.solve_ball(
                    b[j],
                    ball,
                    balls.k_seat,
                    tol,
                    max_iterations,
                    q[j],
                    nr[j],
                    nz[j],
                    dl[j],
                    s[j],
                    sp[j],
                    dmat,
                    emat,
                    work,
                    ts,
                )
        if sweep == 1 or spd[0] <= 0:
            break
        total = 0.0
        count = 0
        for j in range(nb):
            qi = 0.0
            qo = 0.0
            for k in range(ncon):
                if inner[k]:
                    qi += q[j, k]
                else:
                    qo += q[j, k]
            driven[j] = _ball.drive(qi, qo, spd[2] * spd[6] * spd[6]) >= 1.0
            if driven[j]:
                total += sp[j, 4]
                count += 1
        if not 0 < count < nb:
            break
        spd[6] = total / count
    force = np.zeros(5)
    stiff = np.zeros((5, 5))
    for j in range(nb):
        ball = _ball.one_ball(balls, j, c_rho, c_z, spd)
        _ball.speed_derivatives(b[j, 0], b[j, 1], ball, q[j], nr[j], nz[j], dmat, emat, work)
        _condense(balls.t[j], inner, s[j], q[j], nr[j], nz[j], dmat, emat, sp[j], force, stiff, cw)
    return b, q, nr, nz, dl, sp, force, stiff, np.max(res), np.all(ok)
