"""Compiled kernels of the roller-bearing load distribution (numba, ``cache=True``); the
model, the notation and the NumPy twins are in :mod:`._roller_kernels`, which the tests
check these against.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..engine.compiling import watch
from ._ring import _lu_solve
from ._roller_kernels import REG_ABSOLUTE, REG_RELATIVE, ROLLER_ITERATIONS

watch()  # the first compile after install is told, not silent


@numba.njit(cache=True)
def _ring_projection(u, psi, e_rho, e_z, ring_arm, inner, out):
    """a_c . u for every contact of one roller (0 for outer-ring contacts)."""
    c, s = math.cos(psi), math.sin(psi)
    xr = u[0] * c + u[1] * s
    theta = u[3] * s - u[4] * c
    for i in range(out.shape[0]):
        if inner[i]:
            out[i] = xr * e_rho[i] + u[2] * e_z[i] + theta * ring_arm[i]
        else:
            out[i] = 0.0


@numba.njit(cache=True)
def _energy(v, proj, j, rs):
    """Energy of roller j at v (see the module docstring)."""
    total = -rs.fext[j] * v[0]
    for i in range(proj.shape[0]):
        bv = rs.e_rho[j, i] * v[0] + rs.e_z[j, i] * v[1] + rs.roller_arm[j, i] * v[2]
        d = rs.sign[i] * (proj[i] - bv) - rs.gap[j, i]
        if d > rs.delta_floor:
            n = rs.power[i]
            total += rs.k[j, i] * d ** (n + 1.0) / (n + 1.0)
    return total


@numba.njit(cache=True)
def _solve3(h, g, dof):
    """x with h x = g on the free DOFs (x = 0 on the others), Gaussian elimination with
    partial pivoting on the 3x3 (regularised) matrix."""
    a = np.zeros((3, 3))
    b = np.zeros(3)
    for r in range(3):
        if dof[r]:
            b[r] = g[r]
            for c in range(3):
                if dof[c]:
                    a[r, c] = h[r, c]
        else:
            a[r, r] = 1.0
    for col in range(3):
        p = col
        for r in range(col + 1, 3):
            if abs(a[r, col]) > abs(a[p, col]):
                p = r
        if p != col:
            for c in range(3):
                a[col, c], a[p, c] = a[p, c], a[col, c]
            b[col], b[p] = b[p], b[col]
        for r in range(col + 1, 3):
            f = a[r, col] / a[col, col]
            for c in range(col, 3):
                a[r, c] -= f * a[col, c]
            b[r] -= f * b[col]
    x = np.zeros(3)
    for r in range(2, -1, -1):
        acc = b[r]
        for c in range(r + 1, 3):
            acc -= a[r, c] * x[c]
        x[r] = acc / a[r, r]
    return x


@numba.njit(cache=True)
def _roller_gh(v, proj, j, rs, g, h):
    """Out-of-balance force G (3) and tangent H = -dG/dv (3x3) of roller j at v."""
    for a in range(3):
        g[a] = 0.0
        for b in range(3):
            h[a, b] = 0.0
    g[0] = rs.fext[j]
    for i in range(proj.shape[0]):
        br = rs.e_rho[j, i]
        bz = rs.e_z[j, i]
        bt = rs.roller_arm[j, i]
        d = rs.sign[i] * (proj[i] - (br * v[0] + bz * v[1] + bt * v[2])) - rs.gap[j, i]
        if d > rs.delta_floor:
            n = rs.power[i]
            q = rs.k[j, i] * d**n
            kp = n * q / d
            sq = rs.sign[i] * q
            g[0] += sq * br
            g[1] += sq * bz
            g[2] += sq * bt
            h[0, 0] += kp * br * br
            h[0, 1] += kp * br * bz
            h[0, 2] += kp * br * bt
            h[1, 1] += kp * bz * bz
            h[1, 2] += kp * bz * bt
            h[2, 2] += kp * bt * bt
    h[1, 0] = h[0, 1]
    h[2, 0] = h[0, 2]
    h[2, 1] = h[1, 2]
    big = max(h[0, 0], h[1, 1], h[2, 2])
    reg = REG_RELATIVE * big + REG_ABSOLUTE
    for a in range(3):
        h[a, a] += reg


@numba.njit(cache=True)
def solve_roller(j, u, v0, rs):
    """Equilibrium of roller j for ring displacement u, from v0: (v, converged)."""
    ncon = rs.sign.shape[0]
    proj = np.empty(ncon)
    _ring_projection(u, rs.psi[j], rs.e_rho[j], rs.e_z[j], rs.ring_arm[j], rs.inner, proj)
    v = v0.copy()
    for a in range(3):
        if not rs.dof[a]:
            v[a] = 0.0
    g = np.zeros(3)
    h = np.zeros((3, 3))
    trial = np.zeros(3)
    g_trial = np.zeros(3)
    h_trial = np.zeros((3, 3))
    for _ in range(ROLLER_ITERATIONS):
        _roller_gh(v, proj, j, rs, g, h)
        worst = 0.0
        for a in range(3):
            if rs.dof[a]:
                worst = max(worst, abs(g[a]))
        if worst <= rs.tol:
            return v, True
        dv = _solve3(h, g, rs.dof)
        size = math.sqrt(dv[0] ** 2 + dv[1] ** 2 + dv[2] ** 2)
        if size > rs.max_step:
            for a in range(3):
                dv[a] *= rs.max_step / size
        e0 = _energy(v, proj, j, rs)
        slope = -(g[0] * dv[0] + g[1] * dv[1] + g[2] * dv[2])
        lam = 1.0
        moved = False
        for _ in range(60):
            for a in range(3):
                trial[a] = v[a] + lam * dv[a]
            # Armijo on the energy, or (near the solution, where the energy's decrease is
            # below its round-off) a smaller out-of-balance force
            if _energy(trial, proj, j, rs) < e0 + 1e-4 * lam * slope:
                moved = True
                break
            _roller_gh(trial, proj, j, rs, g_trial, h_trial)
            worse = 0.0
            for a in range(3):
                if rs.dof[a]:
                    worse = max(worse, abs(g_trial[a]))
            if worse < (1.0 - 1e-4 * lam) * worst:
                moved = True
                break
            lam *= 0.5
        if not moved:
            for a in range(3):
                trial[a] = v[a] + dv[a]
        for a in range(3):
            v[a] = trial[a]
    _roller_gh(v, proj, j, rs, g, h)
    worst = 0.0
    for a in range(3):
        if rs.dof[a]:
            worst = max(worst, abs(g[a]))
    return v, worst <= 10.0 * rs.tol


@numba.njit(cache=True)
def _series_state(u, rs):
    """:func:`roller_set_state` of rollers whose slice pairs are springs in series (see
    RollerSet.series): q_k = k (delta_k / 2)^n with delta_k the pair's total approach."""
    nz, ncon = rs.k.shape
    ns = ncon // 2
    v_new = np.zeros((nz, 3))
    q = np.zeros((nz, ncon))
    delta = np.zeros((nz, ncon))
    force = np.zeros(5)
    stiff = np.zeros((5, 5))
    proj = np.empty(ncon)
    a_vec = np.zeros(5)
    for j in range(nz):
        _ring_projection(u, rs.psi[j], rs.e_rho[j], rs.e_z[j], rs.ring_arm[j], rs.inner, proj)
        c, s = math.cos(rs.psi[j]), math.sin(rs.psi[j])
        normal = np.zeros((3, 3))
        rhs = np.zeros(3)
        for k in range(ns):
            total = proj[k] - rs.gap[j, k] - rs.gap[j, ns + k]
            half = 0.5 * total
            delta[j, k] = half
            delta[j, ns + k] = half
            b0, b2 = rs.e_rho[j, k], rs.roller_arm[j, k]
            t = 0.5 * (proj[k] - rs.gap[j, k] + rs.gap[j, ns + k])
            normal[0, 0] += b0 * b0
            normal[0, 2] += b0 * b2
            normal[2, 2] += b2 * b2
            rhs[0] += b0 * t
            rhs[2] += b2 * t
            if total <= 2.0 * rs.delta_floor:
                continue
            n = rs.power[k]
            qk = rs.k[j, k] * half**n
            kp = n * qk / total
            q[j, k] = qk
            q[j, ns + k] = qk
            arm = rs.ring_arm[j, k]
            a_vec[0] = c * rs.e_rho[j, k]
            a_vec[1] = s * rs.e_rho[j, k]
            a_vec[2] = rs.e_z[j, k]
            a_vec[3] = s * arm
            a_vec[4] = -c * arm
            for a in range(5):
                force[a] -= qk * a_vec[a]
                for b in range(5):
                    stiff[a, b] += kp * a_vec[a] * a_vec[b]
        normal[2, 0] = normal[0, 2]
        normal[1, 1] = 1.0
        x = _solve3(normal, rhs, rs.dof)
        for a in range(3):
            v_new[j, a] = x[a]
    return v_new, q, delta, force, stiff, True


@numba.njit(cache=True)
def roller_set_state(u, v_all, rs):
    """All rollers in equilibrium at ring displacement u (each from its row of ``v_all``).

    Returns (v (Z, 3), q (Z, C), delta (Z, C), force on the inner ring (5,), condensed
    stiffness K (5, 5), ok): ok is False when a roller's equilibrium was not found.
    """
    nz, ncon = rs.k.shape
    v_new = np.empty((nz, 3))
    q = np.zeros((nz, ncon))
    delta = np.zeros((nz, ncon))
    force = np.zeros(5)
    stiff = np.zeros((5, 5))
    proj = np.empty(ncon)
    a_vec = np.zeros(5)
    b_vec = np.zeros(3)
    if rs.series:
        return _series_state(u, rs)
    ok = True
    for j in range(nz):
        v, good = solve_roller(j, u, v_all[j], rs)
        ok = ok and good
        for a in range(3):
            v_new[j, a] = v[a]
        _ring_projection(u, rs.psi[j], rs.e_rho[j], rs.e_z[j], rs.ring_arm[j], rs.inner, proj)
        c, s = math.cos(rs.psi[j]), math.sin(rs.psi[j])
        amat = np.zeros((5, 5))
        mmat = np.zeros((3, 5))
        hmat = np.zeros((3, 3))
        for i in range(ncon):
            br = rs.e_rho[j, i]
            bz = rs.e_z[j, i]
            bt = rs.roller_arm[j, i]
            d = rs.sign[i] * (proj[i] - (br * v[0] + bz * v[1] + bt * v[2])) - rs.gap[j, i]
            delta[j, i] = d
            if d <= rs.delta_floor:
                continue
            n = rs.power[i]
            qi = rs.k[j, i] * d**n
            kp = n * qi / d
            q[j, i] = qi
            b_vec[0], b_vec[1], b_vec[2] = br, bz, bt
            for a in range(3):
                for b in range(3):
                    hmat[a, b] += kp * b_vec[a] * b_vec[b]
            if rs.inner[i]:
                arm = rs.ring_arm[j, i]
                a_vec[0] = c * br
                a_vec[1] = s * br
                a_vec[2] = bz
                a_vec[3] = s * arm
                a_vec[4] = -c * arm
                for a in range(5):
                    force[a] -= qi * a_vec[a]
                    for b in range(5):
                        amat[a, b] += kp * a_vec[a] * a_vec[b]
                    for b in range(3):
                        mmat[b, a] += kp * b_vec[b] * a_vec[a]
        big = max(hmat[0, 0], hmat[1, 1], hmat[2, 2])
        reg = REG_RELATIVE * big + REG_ABSOLUTE
        for a in range(3):
            hmat[a, a] += reg
        for col in range(5):
            x = _solve3(hmat, mmat[:, col].copy(), rs.dof)
            for a in range(5):
                acc = 0.0
                for b in range(3):
                    acc += mmat[b, a] * x[b]
                stiff[a, col] += amat[a, col] - acc
    return v_new, q, delta, force, stiff, ok


@numba.njit(cache=True)
def _residual_norm(load, force, free, scale):
    total = 0.0
    for d in range(5):
        if free[d]:
            total += ((load[d] + force[d]) * scale[d]) ** 2
    return math.sqrt(total)


@numba.njit(cache=True)
def ring_newton(u0, v0, free, load, scale, max_step, rs, target, max_iterations):
    """Damped Newton on the free ring DOFs. Returns (u, v, q, delta, force, stiffness,
    status, residual): status 0 converged, 1 out of iterations, 2 no step reduced the
    residual, 3 the rollers were not solved at the start."""
    u = u0.copy()
    v, q, dl, force, stiff, ok = roller_set_state(u, v0, rs)
    if not ok:
        return u, v, q, dl, force, stiff, 3, math.inf
    nfree = 0
    for d in range(5):
        if free[d]:
            nfree += 1
    idx = np.empty(nfree, dtype=np.int64)
    m = 0
    for d in range(5):
        if free[d]:
            idx[m] = d
            m += 1
    norm = _residual_norm(load, force, free, scale)
    for _ in range(max_iterations):
        if norm <= target:
            return u, v, q, dl, force, stiff, 0, norm
        kff = np.empty((nfree, nfree))
        rhs = np.empty(nfree)
        for a in range(nfree):
            rhs[a] = load[idx[a]] + force[idx[a]]
            for b in range(nfree):
                kff[a, b] = stiff[idx[a], idx[b]]
        du_f, solved = _lu_solve(kff, rhs, 1e-14)
        if not solved or not np.all(np.isfinite(du_f)):
            for a in range(nfree):
                du_f[a] = rhs[a] / max(abs(kff[a, a]), 1.0)
        limit = 0.0
        for a in range(nfree):
            limit = max(limit, abs(du_f[a]) / max_step[idx[a]])
        if limit > 1.0:
            for a in range(nfree):
                du_f[a] /= limit
        du = np.zeros(5)
        for a in range(nfree):
            du[idx[a]] = du_f[a]
        lam = 1.0
        accepted = False
        for _ in range(40):
            trial = u + lam * du
            v1, q1, dl1, f1, k1, ok1 = roller_set_state(trial, v, rs)
            if ok1:
                n1 = _residual_norm(load, f1, free, scale)
                if n1 < norm:
                    u, v, q, dl, force, stiff, norm = trial, v1, q1, dl1, f1, k1, n1
                    accepted = True
                    break
            lam *= 0.5
        if not accepted:
            return u, v, q, dl, force, stiff, 2, norm
    if norm <= target:
        return u, v, q, dl, force, stiff, 0, norm
    return u, v, q, dl, force, stiff, 1, norm
