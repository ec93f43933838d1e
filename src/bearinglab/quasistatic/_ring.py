"""Compiled ring iteration of the quasi-static solver (numba, ``cache=True``): the
twin of :func:`bearinglab.quasistatic.solver._newton`, calling the compiled ball kernels of
_ball_set.py (the set of balls, condensation) and _ball.py (one ball) as module attributes
(so that the whole chain loads from numba's on-disk cache in a new process).

Numba's on-disk cache is keyed on each file alone: after editing ``_ball.py`` or
``_ball_set.py``, delete the cached ``_ring.*.nbi``/``*.nbc`` files in ``__pycache__`` (or
touch this file), or the ring iteration keeps the old ball kernels.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..engine.compiling import watch
from . import _ball_set

watch()  # the first compile after install is told, not silent


@numba.njit(cache=True)
def _lu_solve(a, rhs, tol=1e-15):
    """x with a x = rhs by Gaussian elimination with partial pivoting (n <= 5); returns
    (x, False) for a matrix singular to ``tol`` times its largest entry, as
    np.linalg.solve would raise (the ball ring iteration 1e-15, the roller one 1e-14)."""
    n = rhs.shape[0]
    m = a.copy()
    x = rhs.copy()
    scale = 0.0
    for i in range(n):
        for k in range(n):
            scale = max(scale, abs(m[i, k]))
    for c in range(n):
        p = c
        for r in range(c + 1, n):
            if abs(m[r, c]) > abs(m[p, c]):
                p = r
        if abs(m[p, c]) <= tol * scale or scale == 0.0:
            return x, False
        if p != c:
            for k in range(n):
                m[c, k], m[p, k] = m[p, k], m[c, k]
            x[c], x[p] = x[p], x[c]
        for r in range(c + 1, n):
            f = m[r, c] / m[c, c]
            for k in range(c, n):
                m[r, k] -= f * m[c, k]
            x[r] -= f * x[c]
    for c in range(n - 1, -1, -1):
        for k in range(c + 1, n):
            x[c] -= m[c, k] * x[k]
        x[c] /= m[c, c]
    return x, True


@numba.njit(cache=True)
def _centres(u, balls):
    """Groove centres (Z, C) with the inner ring displaced by u."""
    t, inner = balls.t, balls.inner
    nb, ncon = balls.c0_rho.shape
    c_rho = balls.c0_rho.copy()
    c_z = balls.c0_z.copy()
    for j in range(nb):
        for k in range(ncon):
            if inner[k]:
                for d in range(5):
                    c_rho[j, k] += t[j, k, 0, d] * u[d]
                    c_z[j, k] += t[j, k, 1, d] * u[d]
    return c_rho, c_z


@numba.njit(cache=True)
def _at(u, b, balls, ball_tol):
    """The ball set at ring displacement u, from ball centres b (_ball_set.solve_balls)."""
    c_rho, c_z = _centres(u, balls)
    return _ball_set.solve_balls(b, c_rho, c_z, balls, ball_tol)


@numba.njit(cache=True)
def _weighted(x, free_dofs, scale, du):
    total = 0.0
    for d in range(5):
        if free_dofs[d]:
            total += x[d] * du[d] * scale[d]
    return total


@numba.njit(cache=True)
def _norm(x, free_dofs):
    total = 0.0
    for d in range(5):
        if free_dofs[d]:
            total += x[d] * x[d]
    return math.sqrt(total)


@numba.njit(cache=True)
def ring_newton(u0, b0, free_dofs, load, scale, max_step, balls, ball_tol, target, max_iterations):
    """Compiled twin of solver._newton (damped Newton with a line search on the free ring
    DOFs; ``balls`` a _kernels.BallSet). Returns (u, b, q, n_rho, n_z, delta, speed, force,
    stiffness, status, residual): status 0 converged, 1 out of iterations, 2 no admissible
    step, 3 balls not solved at the start."""

    def at(u_trial, b_trial):  # the ball set at ring displacement u_trial (inlined)
        return _at(u_trial, b_trial, balls, ball_tol)

    u = u0.copy()
    nfree = 0
    for d in range(5):
        if free_dofs[d]:
            nfree += 1
    idx = np.empty(nfree, dtype=np.int64)
    m = 0
    for d in range(5):
        if free_dofs[d]:
            idx[m] = d
            m += 1
    b, q, nr, nz, dl, sp, force, stiff, _worst, ok = at(u, b0)
    if not ok:
        return u, b, q, nr, nz, dl, sp, force, stiff, 3, math.inf
    r = (load + force) * scale
    damping = 0.0
    norm = _norm(r, free_dofs)
    for iteration in range(max_iterations + 1):
        norm = _norm(r, free_dofs)
        if norm <= target:
            return u, b, q, nr, nz, dl, sp, force, stiff, 0, norm
        if iteration == max_iterations:
            break
        k_ff = np.empty((nfree, nfree))
        rhs = np.empty(nfree)
        diag = np.empty(nfree)
        big = 0.0
        for a in range(nfree):
            big = max(big, abs(stiff[idx[a], idx[a]]))
        for a in range(nfree):
            rhs[a] = load[idx[a]] + force[idx[a]]
            diag[a] = max(abs(stiff[idx[a], idx[a]]), 1e-12 * big + 1.0)
            for c in range(nfree):
                k_ff[a, c] = stiff[idx[a], idx[c]]
            k_ff[a, a] += damping * diag[a]
        du_f, solved = _lu_solve(k_ff, rhs)
        if not solved or not np.all(np.isfinite(du_f)):
            du_f = rhs / diag
        descent = 0.0
        for a in range(nfree):
            descent += rhs[a] * du_f[a] * scale[idx[a]] ** 2
        if descent <= 0:
            du_f = rhs / diag
        limit = 0.0
        for a in range(nfree):
            limit = max(limit, abs(du_f[a]) / max_step[idx[a]])
        if limit > 1:
            du_f /= limit
        du = np.zeros(5)
        for a in range(nfree):
            du[idx[a]] = du_f[a]
        trial = u + du
        b1, q1, nr1, nz1, dl1, sp1, f1, k1, _w1, ok1 = at(trial, b)
        r1 = (load + f1) * scale
        n1 = _norm(r1, free_dofs) if ok1 else math.inf
        newton_worked = ok1 and n1 < 0.5 * norm
        if newton_worked and damping < 1e-3:
            damping = 0.0
        elif newton_worked:
            damping *= 0.1
        else:
            damping = max(1e-3, 10.0 * damping)
        if not ok1 or n1 >= norm:
            # overshoot: go to where the residual turns against the step (energy minimum)
            s1 = _weighted(r1, free_dofs, scale, du) if ok1 else -1e30
            s0 = _weighted(r, free_dofs, scale, du)
            if s1 < 0 < s0:
                lo, hi, f_lo, f_hi = 0.0, 1.0, s0, s1
                side_kept = 0
                lam = 1.0
                for _ in range(200):
                    lam = hi - f_hi * (hi - lo) / (f_hi - f_lo)  # Illinois false position
                    if not lo < lam < hi:
                        lam = 0.5 * (lo + hi)
                    mid = at(u + lam * du, b)
                    fm = (
                        _weighted((load + mid[6]) * scale, free_dofs, scale, du)
                        if mid[9]
                        else -1e30
                    )
                    if fm > 0:
                        lo, f_lo = lam, fm
                        if side_kept == 1:
                            f_hi *= 0.5
                        side_kept = 1
                    else:
                        hi, f_hi = lam, fm
                        if side_kept == -1:
                            f_lo *= 0.5
                        side_kept = -1
                    if hi - lo <= 1e-12 + 1e-10 * lam:
                        break
                for lam in (0.5 * (lo + hi), lo):  # lo: the side where the balls solved
                    trial = u + lam * du
                    b1, q1, nr1, nz1, dl1, sp1, f1, k1, _w1, ok1 = at(trial, b)
                    if ok1:
                        break
            if not ok1:
                return u, b, q, nr, nz, dl, sp, force, stiff, 2, norm
        u, b, q, nr, nz, dl, sp, force, stiff = trial, b1, q1, nr1, nz1, dl1, sp1, f1, k1
        r = (load + force) * scale
    return u, b, q, nr, nz, dl, sp, force, stiff, 1, _norm(r, free_dofs)


@numba.njit(cache=True)
def ring_newton_line(
    loads, u0, b0, free_dofs, scale, max_step, balls, tolerance, floor, max_iterations
):
    """Many load cases in one call (a stiffness-map line): each case starts from the
    previous solution (ring and balls). Stops at the first case that does not converge.
    Returns (u (N, 5), stiffness (N, 5, 5), largest contact load (N,), status (N,): 0
    solved, else the ring_newton status; -1 not attempted; ball centres of the last case
    solved (Z, 2))."""
    n = loads.shape[0]
    nb = b0.shape[0]
    us = np.zeros((n, 5))
    ks = np.zeros((n, 5, 5))
    qmax = np.zeros(n)
    status = np.full(n, -1, dtype=np.int64)
    u = u0.copy()
    b = b0.copy()
    for i in range(n):
        load = loads[i].copy()
        load_norm = 0.0
        for d in range(5):
            load_norm += (load[d] * scale[d]) ** 2
        load_norm = math.sqrt(load_norm)
        ball_tol = max(tolerance * max(load_norm, 1.0) / nb, 2.0 * floor)
        target = tolerance * max(load_norm, 1.0)
        res = ring_newton(
            u, b, free_dofs, load, scale, max_step, balls, ball_tol, target, max_iterations
        )
        status[i] = res[9]
        if res[9] != 0:
            break
        u = res[0]
        b = res[1]
        us[i] = u
        ks[i] = res[8]
        qmax[i] = np.max(res[2])
    return us, ks, qmax, status, b
