"""Hot loops of the roller-bearing load distribution: the NumPy twins (``*_numpy``) of the
compiled kernels of :mod:`._roller_compiled` (numba, ``cache=True``), which the tests check
against each other.

Every roller j lies in its own plane (rho radial, z axial) at azimuth psi_j and has up to
three unknowns v = (v_rho, v_z, chi * L) (translation and tilt, the tilt scaled by a length
L so that all three are lengths). Its contacts c (the slices of the inner and outer line
contacts, and for a tapered roller the rib) each have a unit normal e_c, a load law
q = k_c [delta_c]_+^n_c (n = 10/9 for a slice, 1.5 for the rib's point contact) and an
approach

    delta_c = s_c (a_c . u - B_c . v) - g_c,

s_c = +1 for contacts with the inner ring (the ring pushes the roller along e_c), -1 for
the outer ring, a_c the inner ring's displacement at the contact point projected on e_c
per ring displacement u = (x, y, z, tilt_x, tilt_y) (0 for the outer ring, whose
misalignment is in the gap g_c), B_c = (e_rho, e_z, m_c) with m_c the contact point's
moment arm about the roller's middle. The roller is in equilibrium when
G(v) = sum_c s_c q_c B_c + f = 0 (f its centrifugal force, outward), the minimum of the
convex energy sum_c k_c delta_c^(n+1)/(n+1) - f . v; Newton's method with a backtracking
line search on that energy finds it. The inner ring feels F = -sum_(c inner) q_c a_c and
the condensed tangent stiffness of the bearing is

    K = A - M^T H^-1 M,  A = sum_inner k'_c a_c a_c^T, M = sum_inner k'_c B_c a_c^T,
    H = sum_all k'_c B_c B_c^T,  k'_c = dq_c/d(delta_c).

Everything is SI. This module holds the NumPy twins and the fixed data (:class:`RollerSet`);
the compiled kernels are in :mod:`._roller_compiled` (imported only when a solve runs, so
that importing the solver does not import numba). The ring iteration (damped Newton on the
free ring DOFs with backtracking on the residual) is :func:`ring_newton_numpy` here and
``_roller_compiled.ring_newton`` compiled.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np


class RollerSet(NamedTuple):
    """What stays fixed during one solve (arrays (Z, C) over rollers j and contacts c).

    Attributes
    ----------
    psi : array (Z,)
        Roller azimuths [rad].
    e_rho, e_z : arrays (Z, C)
        Unit contact normals [-].
    ring_arm : array (Z, C)
        (J p) . e of the contact point p (absolute, in the roller's plane), the inner
        ring's displacement along e per unit rotation of the ring in that plane [m].
    roller_arm : array (Z, C)
        (J (p - C)) . e / L, the same about the roller's middle C, per scaled tilt [-].
    sign : array (C,)
        s_c: +1 inner ring and rib, -1 outer ring [-].
    inner : bool array (C,)
        Contacts with the inner ring (slices and rib) [-].
    k : array (Z, C)
        Load-deflection constants [N/m^n].
    power : array (C,)
        Exponents n [-].
    gap : array (Z, C)
        Gaps at zero displacement: clearance, profile drop, outer misalignment [m].
    fext : array (Z,)
        Outward radial force on each roller (centrifugal force and a seating floor) [N].
    dof : bool array (3,)
        Which roller unknowns are free (v_z is fixed for cylindrical rollers) [-].
    max_step : float
        Largest roller step per Newton iteration [m].
    tol : float
        Roller force tolerance [N].
    delta_floor : float
        Approaches up to this are no contact [m]: the line law's stiffness
        dq/d(delta) ~ delta^(1/9) is still a tenth of a loaded contact's at 1e-16 m, so the
        convergence noise of a displacement (a roller 90 deg from the load touching by
        1e-14 m) would otherwise show in the tangent stiffness; 1e-10 D_we carries 1e-6 N
        a slice.
    series : bool
        The rollers need no equilibrium iteration: cylindrical rollers without centrifugal
        force (contacts 0..n_s-1 inner, n_s..2 n_s-1 outer, equal constants and drops),
        whose inner and outer slice approaches are equal, so that each slice pair is two
        springs in series (ISO/TS 16281's own model) [-].
    """

    psi: np.ndarray
    e_rho: np.ndarray
    e_z: np.ndarray
    ring_arm: np.ndarray
    roller_arm: np.ndarray
    sign: np.ndarray
    inner: np.ndarray
    k: np.ndarray
    power: np.ndarray
    gap: np.ndarray
    fext: np.ndarray
    dof: np.ndarray
    max_step: float
    tol: float
    delta_floor: float
    series: bool


#: Regularisation of a roller's tangent matrix, relative to its largest diagonal term,
#: plus an absolute floor [N/m].
REG_RELATIVE, REG_ABSOLUTE = 1e-12, 1e-6
ROLLER_ITERATIONS = 80


# ------------------------------------------------------------------ NumPy twins
def _projection_numpy(u, rs):
    """a_c . u (Z, C) and the 5-vectors a_c (Z, C, 5)."""
    c, s = np.cos(rs.psi)[:, None], np.sin(rs.psi)[:, None]
    a = np.stack(
        [
            c * rs.e_rho,
            s * rs.e_rho,
            np.broadcast_to(rs.e_z, rs.e_rho.shape),
            s * rs.ring_arm,
            -c * rs.ring_arm,
        ],
        axis=-1,
    )
    a = np.where(rs.inner[None, :, None], a, 0.0)
    return a @ u, a


def _state_numpy(v, proj, rs):
    """delta, q, k' (Z, C) and B (Z, C, 3) for roller states v (Z, 3)."""
    b = np.stack([rs.e_rho, rs.e_z, rs.roller_arm], axis=-1)
    delta = rs.sign * (proj - np.einsum("jci,ji->jc", b, v)) - rs.gap
    pos = np.maximum(delta, 0.0)
    q = rs.k * pos**rs.power
    kp = np.where(delta > 0, rs.power * q / np.where(delta > 0, delta, 1.0), 0.0)
    return delta, q, kp, b


def _energy_numpy(v, proj, rs):
    delta, _, _, _ = _state_numpy(v, proj, rs)
    pos = np.where(delta > rs.delta_floor, delta, 0.0)
    return (rs.k * pos ** (rs.power + 1.0) / (rs.power + 1.0)).sum(axis=1) - rs.fext * v[:, 0]


def _masked_solve_numpy(h, g, dof):
    """Batched h x = g on the free DOFs (x = 0 on the others)."""
    mask = dof.astype(float)
    hm = h * mask[:, None] * mask[None, :] + np.diag(1.0 - mask)
    return np.linalg.solve(hm, (g * mask)[..., None])[..., 0]


def solve_rollers_numpy(u, v0, rs):
    """NumPy twin of the compiled roller solves: all rollers at once, (v (Z, 3), ok)."""
    proj, _ = _projection_numpy(u, rs)
    v = np.where(rs.dof, v0, 0.0)
    done = np.zeros(len(v), bool)
    for _ in range(ROLLER_ITERATIONS):
        _, q, kp, b = _state_numpy(v, proj, rs)
        g = np.einsum("c,jc,jci->ji", rs.sign, q, b)
        g[:, 0] += rs.fext
        h = np.einsum("jc,jci,jck->jik", kp, b, b)
        big = np.max(np.diagonal(h, axis1=1, axis2=2), axis=1)
        h = h + (REG_RELATIVE * big + REG_ABSOLUTE)[:, None, None] * np.eye(3)
        done = np.max(np.abs(np.where(rs.dof, g, 0.0)), axis=1) <= rs.tol
        if np.all(done):
            return v, True
        dv = _masked_solve_numpy(h, g, rs.dof)
        size = np.linalg.norm(dv, axis=1)
        dv *= np.minimum(1.0, rs.max_step / np.maximum(size, 1e-300))[:, None]
        dv[done] = 0.0
        e0 = _energy_numpy(v, proj, rs)
        slope = -np.einsum("ji,ji->j", g, dv)
        worst = np.max(np.abs(np.where(rs.dof, g, 0.0)), axis=1)
        lam = np.ones(len(v))
        pending = ~done
        for _ in range(60):
            if not np.any(pending):
                break
            trial = v + lam[:, None] * dv
            good = _energy_numpy(trial, proj, rs) < e0 + 1e-4 * lam * slope
            _, qt, _, bt = _state_numpy(trial, proj, rs)
            gt = np.einsum("c,jc,jci->ji", rs.sign, qt, bt)
            gt[:, 0] += rs.fext
            good |= np.max(np.abs(np.where(rs.dof, gt, 0.0)), axis=1) < (1 - 1e-4 * lam) * worst
            pending &= ~good
            lam = np.where(pending, 0.5 * lam, lam)
        lam = np.where(pending, 1.0, lam)  # round-off floor: the full step
        v = v + lam[:, None] * dv
    _, q, _, b = _state_numpy(v, proj, rs)
    g = np.einsum("c,jc,jci->ji", rs.sign, q, b)
    g[:, 0] += rs.fext
    return v, bool(np.all(np.max(np.abs(np.where(rs.dof, g, 0.0)), axis=1) <= 10 * rs.tol))


def _series_state_numpy(u, rs):
    """NumPy twin of the compiled series state (RollerSet.series)."""
    ns = rs.k.shape[1] // 2
    proj, a = _projection_numpy(u, rs)
    total = proj[:, :ns] - rs.gap[:, :ns] - rs.gap[:, ns:]
    on = total > 2.0 * rs.delta_floor
    pos = np.where(on, total, 0.0)
    qk = rs.k[:, :ns] * (0.5 * pos) ** rs.power[:ns]
    kp = np.where(on, rs.power[:ns] * qk / np.where(on, total, 1.0), 0.0)
    ai = a[:, :ns]
    force = -np.einsum("jk,jki->i", qk, ai)
    stiff = np.einsum("jk,jki,jkl->il", kp, ai, ai)
    t = 0.5 * (proj[:, :ns] - rs.gap[:, :ns] + rs.gap[:, ns:])
    b = np.stack([rs.e_rho[:, :ns], np.zeros_like(t), rs.roller_arm[:, :ns]], axis=-1)
    normal = np.einsum("jki,jkl->jil", b, b) + np.diag([0.0, 1.0, 0.0])
    v = np.linalg.solve(normal, np.einsum("jki,jk->ji", b, t)[..., None])[..., 0]
    q = np.concatenate([qk, qk], axis=1)
    delta = np.concatenate([0.5 * total, 0.5 * total], axis=1)
    return v, q, delta, force, stiff, True


def roller_set_state_numpy(u, v_all, rs):
    """NumPy twin of :func:`roller_set_state`."""
    if rs.series:
        return _series_state_numpy(u, rs)
    v, ok = solve_rollers_numpy(u, v_all, rs)
    proj, a = _projection_numpy(u, rs)
    delta, q, kp, b = _state_numpy(v, proj, rs)
    inner = rs.inner[None, :]
    force = -np.einsum("jc,jci->i", np.where(inner, q, 0.0), a)
    kin = np.where(inner, kp, 0.0)
    amat = np.einsum("jc,jci,jck->ik", kin, a, a)
    mmat = np.einsum("jc,jci,jck->jik", kin, b, a)  # (Z, 3, 5)
    h = np.einsum("jc,jci,jck->jik", kp, b, b)
    big = np.max(np.diagonal(h, axis1=1, axis2=2), axis=1)
    h = h + (REG_RELATIVE * big + REG_ABSOLUTE)[:, None, None] * np.eye(3)
    mask = rs.dof.astype(float)
    hm = h * mask[:, None] * mask[None, :] + np.diag(1.0 - mask)
    x = np.linalg.solve(hm, mmat * mask[None, :, None])  # (Z, 3, 5)
    stiff = amat - np.einsum("jba,jbc->ac", mmat * mask[None, :, None], x)
    return v, q, delta, force, stiff, ok


def ring_newton_numpy(u0, v0, free, load, scale, max_step, rs, target, max_iterations):
    """Python twin of :func:`ring_newton` on the NumPy roller solves."""
    u = np.array(u0, dtype=float)
    v, q, dl, force, stiff, ok = roller_set_state_numpy(u, v0, rs)
    if not ok:
        return u, v, q, dl, force, stiff, 3, math.inf

    def norm_of(f):
        return float(np.linalg.norm(((load + f) * scale)[free]))

    norm = norm_of(force)
    for _ in range(max_iterations):
        if norm <= target:
            return u, v, q, dl, force, stiff, 0, norm
        rhs = (load + force)[free]
        kff = stiff[np.ix_(free, free)]
        try:
            du_f = np.linalg.solve(kff, rhs)
        except np.linalg.LinAlgError:
            du_f = rhs / np.maximum(np.abs(np.diag(kff)), 1.0)
        limit = np.max(np.abs(du_f) / max_step[free])
        if limit > 1:
            du_f = du_f / limit
        du = np.zeros(5)
        du[free] = du_f
        lam, accepted = 1.0, False
        for _ in range(40):
            trial = u + lam * du
            v1, q1, dl1, f1, k1, ok1 = roller_set_state_numpy(trial, v, rs)
            if ok1 and norm_of(f1) < norm:
                u, v, q, dl, force, stiff, norm = trial, v1, q1, dl1, f1, k1, norm_of(f1)
                accepted = True
                break
            lam *= 0.5
        if not accepted:
            return u, v, q, dl, force, stiff, 2, norm
    return u, v, q, dl, force, stiff, (0 if norm <= target else 1), norm
