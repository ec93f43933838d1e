"""Stiff integrator of the seed-004 slip model: the modified Rosenbrock 2(3) pair of
Shampine & Reichelt ([ShampineReichelt1997], MATLAB's ode23s) with its Jacobian differenced
and factored by blocks (numba, ``cache=True``).

The Jacobian of :func:`bearinglab.dynamics._slip_kernels.slip_rhs` has an arrow structure (a
ball's equations involve only its own state, the rings and the cage), which
:func:`rosenbrock_chunk` uses to difference it with 16 calls (:func:`_jacobian`) and to
solve with it by block elimination (:func:`_factor`, :func:`_solve`, on the small LU
factors of :func:`_lu` and :func:`_lu_solve`).

Every function here is a module-level ``numba.njit(cache=True)`` function that calls only
module-level compiled functions, those of ``_slip_kernels.py`` and ``_integrate.py`` as
attributes of the modules, so that a new process loads them all from numba's on-disk cache.
The cache is keyed on this file alone: after editing ``_slip_kernels.py`` or
``_integrate.py``, delete the cached ``_rosenbrock.*.nbi``/``*.nbc`` files in
``__pycache__`` (or touch this file), or the integrator keeps the old right-hand side.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..engine.compiling import watch
from . import _integrate, _slip_kernels

watch()  # the first compile after install is told, not silent

NG = _slip_kernels.NG  # global states
NB = _slip_kernels.NB  # states per ball
JACOBIAN_AGE = 8  # steps a Jacobian is reused for (see rosenbrock_chunk)


@numba.njit(cache=True)
def _jacobian(t, y, f0, parts0, p, table, jac_g, jac_gb, jac_bg, jac_b):
    """Difference the Jacobian in arrow blocks: jac_g (NG, NG), jac_gb (Z, NG, NB)
    (global rows, ball columns), jac_bg (Z, NB, NG), jac_b (Z, NB, NB)."""
    n = y.shape[0]
    z = (n - NG) // NB
    yp = y.copy()
    f1 = np.empty(n)
    parts1 = np.empty((z, NG))
    for col in range(NG):
        eps = 1e-7 * max(abs(y[col]), 1e-6 if col < 4 else 1e-3)
        yp[col] = y[col] + eps
        _slip_kernels.slip_rhs(t, yp, p, table, f1, parts1)
        yp[col] = y[col]
        for i in range(NG):
            jac_g[i, col] = (f1[i] - f0[i]) / eps
        for j in range(z):
            for i in range(NB):
                jac_bg[j, i, col] = (f1[NG + NB * j + i] - f0[NG + NB * j + i]) / eps
    for m in range(NB):
        steps = np.empty(z)
        for j in range(z):
            k = NG + NB * j + m
            steps[j] = 1e-7 * max(abs(y[k]), 1e-6 if m < 2 else 1e-2)
            yp[k] = y[k] + steps[j]
        _slip_kernels.slip_rhs(t, yp, p, table, f1, parts1)
        for j in range(z):
            k = NG + NB * j + m
            yp[k] = y[k]
            for i in range(NB):
                jac_b[j, i, m] = (f1[NG + NB * j + i] - f0[NG + NB * j + i]) / steps[j]
            for i in range(NG):
                jac_gb[j, i, m] = (parts1[j, i] - parts0[j, i]) / steps[j]


@numba.njit(cache=True)
def _lu(a, piv):
    """LU factors of the small square matrix ``a`` in place, partial pivoting.

    Hand-written because LAPACK through ``np.linalg`` costs more in call overhead and
    allocation than the arithmetic of a 6x6 or 10x10 matrix."""
    n = a.shape[0]
    for k in range(n):
        big = k
        for i in range(k + 1, n):
            if abs(a[i, k]) > abs(a[big, k]):
                big = i
        piv[k] = big
        if big != k:
            for c in range(n):
                a[k, c], a[big, c] = a[big, c], a[k, c]
        inv = 1.0 / a[k, k]
        for i in range(k + 1, n):
            a[i, k] *= inv
            f = a[i, k]
            for c in range(k + 1, n):
                a[i, c] -= f * a[k, c]


@numba.njit(cache=True)
def _lu_solve(lu, piv, x):
    """Overwrite ``x`` (n,) or (n, m) with the solution of A x = x, A given by
    :func:`_lu`; the column loop is innermost so that m right-hand sides vectorise."""
    n = lu.shape[0]
    for k in range(n):
        p = piv[k]
        if p != k:
            for c in range(x.shape[1]):
                x[k, c], x[p, c] = x[p, c], x[k, c]
    for i in range(1, n):
        for k in range(i):
            f = lu[i, k]
            for c in range(x.shape[1]):
                x[i, c] -= f * x[k, c]
    for i in range(n - 1, -1, -1):
        for k in range(i + 1, n):
            f = lu[i, k]
            for c in range(x.shape[1]):
                x[i, c] -= f * x[k, c]
        inv = 1.0 / lu[i, i]
        for c in range(x.shape[1]):
            x[i, c] *= inv


@numba.njit(cache=True)
def _factor(gh, jac_g, jac_gb, jac_bg, jac_b, lu_b, piv_b, m_bg, lu_s, piv_s):
    """Factor W = I - gh J by block elimination: D_j = I - gh J_b,j (lu_b), m_bg,j =
    D_j^-1 (-gh J_bg,j), and the Schur complement on the global block (lu_s)."""
    z = jac_b.shape[0]
    for r in range(NG):
        for c in range(NG):
            lu_s[r, c] = (1.0 if r == c else 0.0) - gh * jac_g[r, c]
    for j in range(z):
        for r in range(NB):
            for c in range(NB):
                lu_b[j, r, c] = (1.0 if r == c else 0.0) - gh * jac_b[j, r, c]
        _lu(lu_b[j], piv_b[j])
        for r in range(NB):
            for c in range(NG):
                m_bg[j, r, c] = -gh * jac_bg[j, r, c]
        _lu_solve(lu_b[j], piv_b[j], m_bg[j])
        # S -= W_gb,j m_bg,j with W_gb,j = -gh J_gb,j
        for r in range(NG):
            for k in range(NB):
                w = gh * jac_gb[j, r, k]
                if w != 0.0:
                    for c in range(NG):
                        lu_s[r, c] += w * m_bg[j, k, c]
    _lu(lu_s, piv_s)


@numba.njit(cache=True)
def _solve(gh, jac_gb, lu_b, piv_b, m_bg, lu_s, piv_s, rhs, out):
    """Solve W x = rhs with the factors of :func:`_factor`."""
    z = lu_b.shape[0]
    for i in range(rhs.shape[0]):
        out[i] = rhs[i]
    column = out.reshape((out.shape[0], 1))
    for j in range(z):
        b = NG + NB * j
        _lu_solve(lu_b[j], piv_b[j], column[b : b + NB])  # D_j^-1 r_j
        for r in range(NG):
            for k in range(NB):
                out[r] += gh * jac_gb[j, r, k] * out[b + k]
    _lu_solve(lu_s, piv_s, column[:NG])
    for j in range(z):
        b = NG + NB * j
        for r in range(NB):
            for c in range(NG):
                out[b + r] -= m_bg[j, r, c] * out[c]


@numba.njit(cache=True)
def rosenbrock_chunk(p, table, t, y, h, t_out, rtol, atol, h_max, max_steps):
    """Integrate the slip model over the output times ``t_out`` with the modified
    Rosenbrock 2(3) pair of Shampine & Reichelt (SIAM J. Sci. Comput. 18 (1997) 1-22,
    MATLAB's ode23s): L-stable, one Jacobian per step, its own continuous extension for
    the output. Returns (Y, t, y, h, steps, rejected, status) like dopri_chunk."""
    n = y.shape[0]
    z = (n - NG) // NB
    d = 1.0 / (2.0 + math.sqrt(2.0))
    e32 = 6.0 + math.sqrt(2.0)
    out = np.empty((t_out.shape[0], n))
    f0 = np.empty(n)
    f1 = np.empty(n)
    f2 = np.empty(n)
    ft = np.empty(n)
    parts0 = np.empty((z, NG))
    parts = np.empty((z, NG))
    jac_g = np.empty((NG, NG))
    jac_gb = np.empty((z, NG, NB))
    jac_bg = np.empty((z, NB, NG))
    jac_b = np.empty((z, NB, NB))
    lu_b = np.empty((z, NB, NB))
    piv_b = np.empty((z, NB), dtype=np.int64)
    m_bg = np.empty((z, NB, NG))
    lu_s = np.empty((NG, NG))
    piv_s = np.empty(NG, dtype=np.int64)
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    rhs = np.empty(n)
    ynew = np.empty(n)
    err = np.empty(n)
    steps = 0
    rejected = 0
    i_out = _integrate.outputs_before(t, y, t_out, out)
    _slip_kernels.slip_rhs(t, y, p, table, f0, parts0)
    need_jacobian = True
    age = 0
    while i_out < t_out.shape[0]:
        h, status = _integrate.step_limits(h, h_max, steps, rejected, max_steps)
        if status != _integrate.OK:
            return out, t, y, h, steps, rejected, status
        if need_jacobian:
            _jacobian(t, y, f0, parts0, p, table, jac_g, jac_gb, jac_bg, jac_b)
            dt = 1e-7 * max(abs(t), 1e-3)
            _slip_kernels.slip_rhs(t + dt, y, p, table, ft, parts)
            for i in range(n):
                ft[i] = (ft[i] - f0[i]) / dt
            need_jacobian = False
            age = 0
        gh = d * h
        _factor(gh, jac_g, jac_gb, jac_bg, jac_b, lu_b, piv_b, m_bg, lu_s, piv_s)
        for i in range(n):
            rhs[i] = f0[i] + h * d * ft[i]
        _solve(gh, jac_gb, lu_b, piv_b, m_bg, lu_s, piv_s, rhs, k1)
        for i in range(n):
            ynew[i] = y[i] + 0.5 * h * k1[i]
        _slip_kernels.slip_rhs(t + 0.5 * h, ynew, p, table, f1, parts)
        for i in range(n):
            rhs[i] = f1[i] - k1[i]
        _solve(gh, jac_gb, lu_b, piv_b, m_bg, lu_s, piv_s, rhs, k2)
        for i in range(n):
            k2[i] += k1[i]
            ynew[i] = y[i] + h * k2[i]
        _slip_kernels.slip_rhs(t + h, ynew, p, table, f2, parts)
        for i in range(n):
            rhs[i] = f2[i] - e32 * (k2[i] - f1[i]) - 2.0 * (k1[i] - f0[i]) + h * d * ft[i]
        _solve(gh, jac_gb, lu_b, piv_b, m_bg, lu_s, piv_s, rhs, k3)
        for i in range(n):
            err[i] = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i])
        norm = _integrate.error_norm(err, y, ynew, rtol, atol)
        if not np.isfinite(norm):
            h, status = _integrate.retry_not_finite(h)
            if status != _integrate.OK:
                return out, t, y, h, steps, rejected, status
            rejected += 1
            continue
        if norm <= 1.0:
            t_new = t + h
            while i_out < t_out.shape[0] and t_out[i_out] <= t_new:
                s = (t_out[i_out] - t) / h
                a1 = s * (1.0 - s) / (1.0 - 2.0 * d)
                a2 = s * (s - 2.0 * d) / (1.0 - 2.0 * d)
                for i in range(n):
                    out[i_out, i] = y[i] + h * (a1 * k1[i] + a2 * k2[i])
                i_out += 1
            t = t_new
            y = ynew.copy()
            f0[:] = f2
            parts0[:, :] = parts
            steps += 1
            age += 1
            # a stale Jacobian keeps the formula's order (ode23s is a W-method) and the
            # error control rejects what it spoils: renew it every few steps only
            need_jacobian = age >= JACOBIAN_AGE
            h *= min(5.0, 0.8 * (1.0 / max(norm, 1e-10)) ** (1.0 / 3.0))
        else:
            rejected += 1
            need_jacobian = age > 0
            h *= max(0.1, 0.8 * (1.0 / norm) ** (1.0 / 3.0))
    return out, t, y, h, steps, rejected, _integrate.OK
