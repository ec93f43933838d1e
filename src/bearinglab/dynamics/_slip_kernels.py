"""Hot loops of the seed-004 slip model: right-hand side and its NumPy twin; the stiff
integrator that steps it is in ``_rosenbrock.py``.

State (SI): global part g = [x_i, y_i, x_o, y_o, vx_i, vy_i, vx_o, vy_o, theta_c, omega_c]
(inner ring, outer ring, cage angle and speed), then six entries per ball j:
[rho_j, rho_j', psi_j, omega_m,j, phi_j, omega_r,j] (radial offset of the ball centre from
the pitch circle, orbital angle and speed, spin phase and spin speed; phi = 0 when a
marked point faces the outer race; omega_r > 0 in the rolling sense, the inner contact
point moving forward). The equations are documented in ``slip.py``.

:func:`slip_rhs` also returns each ball's share of the global rows, so that the integrator
can difference the Jacobian's arrow structure by ball groups.

Numba's on-disk cache (``cache=True``) is keyed on this file alone: after editing
``_kernels.py`` (the surface function), delete the cached ``*.nbi``/``*.nbc`` files in
``__pycache__``, or the slip kernels keep the old surface function.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..engine.compiling import watch
from ._kernels import surface_deviation_numba

watch()  # the first compile after install is told, not silent

NG = 10  # global states
NB = 6  # states per ball
(
    BALLS,
    M_I,
    M_O,
    K_O,
    C_O,
    M_B,
    J_B,
    J_C,
    R_M,
    R_B,
    R_IN,
    R_OUT,
    QUARTER_CLEARANCE,
    K_IN,
    K_OUT,
    H_IN,
    H_OUT,
    C_IN,
    C_OUT,
    P1_IN,
    P1_OUT,
    OMEGA_I,
    F_X,
    F_Y,
    UNBALANCE,
    GRAVITY,
    K_CAGE,
    C_CAGE,
    POCKET,
    TRACTION,
    ETA0,
    ALPHA,
    MU_LIMIT,
    FLOW_INDEX,
    G_OIL,
    V_REG,
    DRAG,
    CAGE_DRAG,
    IMPACTS,
    DEFECT_ANGLE,
    ONSET,
    CAGE_MU,
    SPIN_RHO,
    SPIN_MU,
) = range(44)
SLIP_PARAMETER_COUNT = 44
SEED004, BAIR_WINER = 0, 1
# Masjedi & Khonsari boundary friction curve, seed 004 eq. 11 (ball-cage contact)
CAGE_A, CAGE_B, CAGE_C, CAGE_D = -0.1, 22.28, 181.46, 0.1
#: ... at the slide-roll ratio 2 of a pocket contact (the ball surface slides on the pocket):
#: the default of ``SlipParameters.cage_friction``
CAGE_SLIDING_MU = (CAGE_A + CAGE_B * 2.0) * math.exp(-CAGE_C * 2.0) + CAGE_D
#: Rotational drag coefficient of a sphere (Dennis, Singh & Ingham 1980): Stokes' couple
#: below Re_r = 32, their fit C_R = 12.9 Re_r^-1/2 + 128.4 / Re_r above
SPIN_STOKES_REYNOLDS = 32.0
# 4-point Gauss-Legendre rule on [0, 1] for the pressure averages of Bair-Winer traction
_GL_X = np.array([0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263])
_GL_W = np.array([0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269])


@numba.njit(cache=True)
def _traction_raw(speed, load, p_1, h, p):
    """Traction coefficient at sliding speed ``speed`` >= 0 [m/s], Hertz load ``load``."""
    if load <= 0.0 or speed <= 0.0:
        return 0.0
    pmax = p_1 * load ** (1.0 / 3.0)
    limit = p[MU_LIMIT]
    alpha = p[ALPHA]
    if int(p[TRACTION]) == SEED004:
        # seed 004 eq. 12: power-law shear stress over the Hertz pressure, capped at tau_L/p
        n = p[FLOW_INDEX]
        na = n * alpha * pmax
        bracket = 4.0 / (math.pi * pmax) + n * alpha / 3.0 * (
            1.866 * math.exp(na * math.sqrt(0.067))
            + math.exp(0.707 * na)
            + 0.134 * math.exp(na * math.sqrt(0.933))
        )
        mu = (p[ETA0] * speed / h) ** n * p[G_OIL] ** (1.0 - n) * bracket
        return min(mu, limit)
    # Bair & Winer (1979): tau = tau_L (1 - exp(-eta gamma / tau_L)), tau_L = limit * pressure,
    # averaged over the Hertz ellipse: mu = 3 int_0^1 tau(pmax u)/pmax u du
    total = 0.0
    for k in range(4):
        u = _GL_X[k]
        pressure = pmax * u
        eta = p[ETA0] * math.exp(min(alpha * pressure, 600.0))
        tau_l = limit * pressure
        total += _GL_W[k] * tau_l * (1.0 - math.exp(-eta * speed / (h * tau_l))) * u
    return 3.0 * total / pmax


@numba.njit(cache=True)
def traction(dv, load, p_1, h, p):
    """Signed traction coefficient, linear below the regularisation speed V_REG."""
    v = abs(dv)
    reg = p[V_REG]
    if v < reg:
        return _traction_raw(reg, load, p_1, h, p) * dv / reg
    return math.copysign(_traction_raw(v, load, p_1, h, p), dv)


@numba.njit(cache=True)
def cage_friction(speed, mu):
    """Ball-cage friction coefficient ``mu`` (``SlipParameters.cage_friction``; seed 004
    eq. 11 at slide-roll ratio 2 by default), signed with the sliding ``speed`` [m/s] of
    the ball surface on the pocket, linear below 1 mm/s."""
    return mu * max(-1.0, min(1.0, speed / 1e-3))


@numba.njit(cache=True)
def spin_drag(w_r, p):
    """Drag moment on a ball spinning at ``w_r`` [rad/s] in the oil-air mixture [N m],
    signed with the spin: M = 0.5 rho_e R_b^5 C_R(Re_r) |w_r| w_r, Re_r = rho_e |w_r|
    D_w^2 / mu_e (Dennis, Singh & Ingham, *J. Fluid Mech.* 101 (1980) 257-279: C_R =
    64 pi / Re_r, Stokes' couple 8 pi mu_e R_b^3 w_r, below Re_r = 32; 12.9 Re_r^-1/2 +
    128.4 / Re_r above). Zero when the drag is off (SPIN_RHO = 0)."""
    rho = p[SPIN_RHO]
    if rho <= 0.0:
        return 0.0
    r_b = p[R_B]
    re = rho * abs(w_r) * 4.0 * r_b * r_b / p[SPIN_MU]
    if re < SPIN_STOKES_REYNOLDS:
        return 8.0 * math.pi * p[SPIN_MU] * r_b**3 * w_r
    return 0.5 * rho * r_b**5 * (12.9 / math.sqrt(re) + 128.4 / re) * abs(w_r) * w_r


@numba.njit(cache=True)
def slip_rhs(t, y, p, table, dydt, parts):
    """Right-hand side of the slip model; fills dydt and parts[j] = ball j's share of
    the global rows (so that the Jacobian can be differenced by ball groups)."""
    z = int(p[BALLS])
    psi = np.empty(z)
    spin = np.empty(z)
    dev_in = np.empty(z)
    dev_out = np.empty(z)
    for j in range(z):
        psi[j] = y[NG + NB * j + 2]
        spin[j] = y[NG + NB * j + 4]
    w_i = p[OMEGA_I]
    surface_deviation_numba(psi, spin, w_i * t, p[R_B], p[R_IN], p[R_OUT], table, dev_in, dev_out)
    for i in range(NG):
        dydt[i] = 0.0
    xi, yi, xo, yo = y[0], y[1], y[2], y[3]
    vxi, vyi, vxo, vyo = y[4], y[5], y[6], y[7]
    theta_c, w_c = y[8], y[9]
    r_m, r_b = p[R_M], p[R_B]
    m_b = p[M_B]
    g = p[GRAVITY]
    for j in range(z):
        b = NG + NB * j
        rho, vrho, ps, w_m, ph, w_r = y[b], y[b + 1], y[b + 2], y[b + 3], y[b + 4], y[b + 5]
        c, s = math.cos(ps), math.sin(ps)
        r = r_m + rho
        # approaches (seed 004 eq. 2; the film adds to the approach, see slip.py)
        d_in = xi * c + yi * s - rho - p[QUARTER_CLEARANCE] - dev_in[j] + p[H_IN]
        d_out = rho - xo * c - yo * s - p[QUARTER_CLEARANCE] - dev_out[j] + p[H_OUT]
        n_in = 0.0
        n_out = 0.0
        if d_in > 0.0:
            rate = (vxi * c + vyi * s - vrho) * min(1.0, d_in / p[ONSET])
            n_in = max(0.0, p[K_IN] * d_in * math.sqrt(d_in) + p[C_IN] * rate)
        if d_out > 0.0:
            rate = (vrho - vxo * c - vyo * s) * min(1.0, d_out / p[ONSET])
            n_out = max(0.0, p[K_OUT] * d_out * math.sqrt(d_out) + p[C_OUT] * rate)
        # slip speeds (seed 004 eq. 13) and tractions on the ball, forward positive
        dv_in = (w_i - w_m) * p[R_IN] - w_r * r_b
        dv_out = w_r * r_b - w_m * p[R_OUT]
        f_in = traction(dv_in, n_in, p[P1_IN], p[H_IN], p) * n_in
        f_out = traction(dv_out, n_out, p[P1_OUT], p[H_OUT], p) * n_out
        # ball-cage pocket contact (seed 004 eq. 4), with an optional pocket clearance
        gap = (ps - theta_c - 2.0 * math.pi * j / z) * r_m
        n_c = 0.0
        if abs(gap) > p[POCKET]:
            n_c = p[K_CAGE] * (gap - math.copysign(p[POCKET], gap)) + p[C_CAGE] * r_m * (w_m - w_c)
        mu_c = cage_friction(w_r * r_b, p[CAGE_MU])  # signed with the spin: opposes it
        # ball drag (seed 004 eq. 14 in SI, mixture mass density)
        drag = p[DRAG] * abs(2.0 * r_m * w_m) ** 1.95 * math.copysign(1.0, w_m)
        # ball-defect impacts (seed 004 eqs. 16-19), radial, for a defective ball only
        f_imp = 0.0
        if p[IMPACTS] > 0.0:
            for row in range(table.shape[0]):
                if int(table[row, 0]) == 2 and int(table[row, 4]) == j:
                    width = p[DEFECT_ANGLE]
                    phase_out = (ph - table[row, 3]) % (2.0 * math.pi)
                    phase_in = (ph - table[row, 3] - math.pi) % (2.0 * math.pi)
                    if phase_in <= width:
                        f_imp += m_b * (w_i - w_m) ** 2 * p[R_IN]
                    if phase_out <= width:
                        f_imp -= m_b * w_m * w_m * (p[R_OUT] - r_b)
        radial = n_in - n_out - mu_c * n_c + f_imp - m_b * g * s
        tangential = f_in + f_out - n_c - drag - m_b * g * c
        dydt[b] = vrho
        dydt[b + 1] = radial / m_b + r * w_m * w_m
        dydt[b + 2] = w_m
        dydt[b + 3] = (tangential / m_b - 2.0 * vrho * w_m) / r
        dydt[b + 4] = w_r
        dydt[b + 5] = ((f_in - f_out - mu_c * abs(n_c)) * r_b - spin_drag(w_r, p)) / p[J_B]
        # reactions on the rings (inner: -N e_r - F e_t; outer: +N e_r - F e_t), cage torque
        fx_i = -(n_in + max(f_imp, 0.0)) * c + f_in * s
        fy_i = -(n_in + max(f_imp, 0.0)) * s - f_in * c
        fx_o = (n_out - min(f_imp, 0.0)) * c + f_out * s
        fy_o = (n_out - min(f_imp, 0.0)) * s - f_out * c
        parts[j, 0] = 0.0
        parts[j, 1] = 0.0
        parts[j, 2] = 0.0
        parts[j, 3] = 0.0
        parts[j, 4] = fx_i / p[M_I]
        parts[j, 5] = fy_i / p[M_I]
        parts[j, 6] = fx_o / p[M_O]
        parts[j, 7] = fy_o / p[M_O]
        parts[j, 8] = 0.0
        parts[j, 9] = r_m * n_c / p[J_C]
        for i in range(NG):
            dydt[i] += parts[j, i]
    unb = p[UNBALANCE] * w_i * w_i
    dydt[0] = vxi
    dydt[1] = vyi
    dydt[2] = vxo
    dydt[3] = vyo
    dydt[4] += (p[F_X] + unb * math.cos(w_i * t)) / p[M_I]
    dydt[5] += (p[F_Y] + unb * math.sin(w_i * t)) / p[M_I]
    dydt[6] += (-p[K_O] * xo - p[C_O] * vxo) / p[M_O]
    dydt[7] += (-p[K_O] * yo - p[C_O] * vyo) / p[M_O]
    dydt[8] = w_c
    dydt[9] += -p[CAGE_DRAG] * w_c * abs(w_c) / p[J_C]


def _traction_numpy(dv, load, p_1, h, p):
    """Vectorised twin of :func:`traction`."""
    reg = p[V_REG]
    speed = np.maximum(np.abs(dv), reg)
    load = np.asarray(load, dtype=float)
    safe = np.where(load > 0, load, 1.0)
    pmax = p_1 * safe ** (1.0 / 3.0)
    if int(p[TRACTION]) == SEED004:
        n = p[FLOW_INDEX]
        na = n * p[ALPHA] * pmax
        bracket = 4.0 / (np.pi * pmax) + n * p[ALPHA] / 3.0 * (
            1.866 * np.exp(na * np.sqrt(0.067))
            + np.exp(0.707 * na)
            + 0.134 * np.exp(na * np.sqrt(0.933))
        )
        mu = np.minimum((p[ETA0] * speed / h) ** n * p[G_OIL] ** (1.0 - n) * bracket, p[MU_LIMIT])
    else:
        pressure = pmax[..., None] * _GL_X
        eta = p[ETA0] * np.exp(np.minimum(p[ALPHA] * pressure, 600.0))
        tau_l = p[MU_LIMIT] * pressure
        tau = tau_l * (1.0 - np.exp(-eta * speed[..., None] / (h * tau_l)))
        mu = 3.0 * np.sum(_GL_W * tau * _GL_X, axis=-1) / pmax
    mu = np.where(load > 0, mu, 0.0)
    return np.where(np.abs(dv) < reg, mu * dv / reg, np.sign(dv) * mu)


def spin_drag_numpy(w_r, p):
    """Vectorised twin of :func:`spin_drag`."""
    w_r = np.asarray(w_r, dtype=float)
    if p[SPIN_RHO] <= 0.0:
        return np.zeros_like(w_r)
    rho, mu, r_b = p[SPIN_RHO], p[SPIN_MU], p[R_B]
    re = np.maximum(rho * np.abs(w_r) * 4.0 * r_b**2 / mu, 1e-300)
    fitted = 0.5 * rho * r_b**5 * (12.9 / np.sqrt(re) + 128.4 / re) * np.abs(w_r) * w_r
    return np.where(re < SPIN_STOKES_REYNOLDS, 8.0 * np.pi * mu * r_b**3 * w_r, fitted)


def slip_rhs_numpy(t, y, p, table):
    """NumPy twin of :func:`slip_rhs` (vectorised over balls); returns dy/dt."""
    from ._kernels import surface_deviation_numpy

    z = int(p[BALLS])
    balls = y[NG:].reshape(z, NB)
    rho, vrho, psi, w_m, phi, w_r = balls.T
    w_i = p[OMEGA_I]
    dev_in, dev_out = surface_deviation_numpy(psi, phi, w_i * t, p[R_B], p[R_IN], p[R_OUT], table)
    e = np.stack([np.cos(psi), np.sin(psi)])  # (2, Z)
    tang = np.stack([-np.sin(psi), np.cos(psi)])
    u_i, u_o, v_i, v_o = y[0:2], y[2:4], y[4:6], y[6:8]
    theta_c, w_c = y[8], y[9]
    d_in = u_i @ e - rho - p[QUARTER_CLEARANCE] - dev_in + p[H_IN]
    d_out = rho - u_o @ e - p[QUARTER_CLEARANCE] - dev_out + p[H_OUT]
    d_in, d_out = np.clip(d_in, 0, None), np.clip(d_out, 0, None)
    onset_in, onset_out = np.minimum(1, d_in / p[ONSET]), np.minimum(1, d_out / p[ONSET])
    n_in = np.maximum(0.0, p[K_IN] * d_in**1.5 + p[C_IN] * (v_i @ e - vrho) * onset_in)
    n_out = np.maximum(0.0, p[K_OUT] * d_out**1.5 + p[C_OUT] * (vrho - v_o @ e) * onset_out)
    dv_in = (w_i - w_m) * p[R_IN] - w_r * p[R_B]
    dv_out = w_r * p[R_B] - w_m * p[R_OUT]
    f_in = _traction_numpy(dv_in, n_in, p[P1_IN], p[H_IN], p) * n_in
    f_out = _traction_numpy(dv_out, n_out, p[P1_OUT], p[H_OUT], p) * n_out
    gap = (psi - theta_c - 2 * np.pi * np.arange(z) / z) * p[R_M]
    n_c = np.where(
        np.abs(gap) > p[POCKET],
        p[K_CAGE] * (gap - np.sign(gap) * p[POCKET]) + p[C_CAGE] * p[R_M] * (w_m - w_c),
        0.0,
    )
    mu_c = p[CAGE_MU] * np.clip(w_r * p[R_B] / 1e-3, -1, 1)
    drag = p[DRAG] * np.abs(2 * p[R_M] * w_m) ** 1.95 * np.where(w_m >= 0, 1.0, -1.0)
    f_imp = np.zeros(z)
    if p[IMPACTS] > 0:
        for kind, _, _, angle, ball in table:
            if kind == 2:
                j = int(ball)
                if (phi[j] - angle - np.pi) % (2 * np.pi) <= p[DEFECT_ANGLE]:
                    f_imp[j] += p[M_B] * (w_i - w_m[j]) ** 2 * p[R_IN]
                if (phi[j] - angle) % (2 * np.pi) <= p[DEFECT_ANGLE]:
                    f_imp[j] -= p[M_B] * w_m[j] ** 2 * (p[R_OUT] - p[R_B])
    m_b, r = p[M_B], p[R_M] + rho
    radial = n_in - n_out - mu_c * n_c + f_imp - m_b * p[GRAVITY] * np.sin(psi)
    tangential = f_in + f_out - n_c - drag - m_b * p[GRAVITY] * np.cos(psi)
    dballs = np.stack(
        [
            vrho,
            radial / m_b + r * w_m**2,
            w_m,
            (tangential / m_b - 2 * vrho * w_m) / r,
            w_r,
            ((f_in - f_out - mu_c * np.abs(n_c)) * p[R_B] - spin_drag_numpy(w_r, p)) / p[J_B],
        ],
        axis=1,
    )
    # ring reactions: inner -N e_r - F e_t, outer +N e_r - F e_t (impacts split by sign)
    force_i = -(e @ (n_in + np.maximum(f_imp, 0))) - tang @ f_in
    force_o = e @ (n_out - np.minimum(f_imp, 0)) - tang @ f_out
    unb = p[UNBALANCE] * w_i**2 * np.array([np.cos(w_i * t), np.sin(w_i * t)])
    a_i = (force_i + np.array([p[F_X], p[F_Y]]) + unb) / p[M_I]
    a_o = (force_o - p[K_O] * u_o - p[C_O] * v_o) / p[M_O]
    cage = (p[R_M] * n_c.sum() - p[CAGE_DRAG] * w_c * abs(w_c)) / p[J_C]
    return np.concatenate([v_i, v_o, a_i, a_o, [w_c, cage], dballs.ravel()])


@numba.njit(cache=True)
def slip_accelerations(p, table, t_out, states):
    """Outer-ring accelerations (x, y) at the output states [m/s^2]."""
    n = states.shape[1]
    z = (n - NG) // NB
    out = np.empty((t_out.shape[0], 2))
    dydt = np.empty(n)
    parts = np.empty((z, NG))
    for i in range(t_out.shape[0]):
        slip_rhs(t_out[i], states[i], p, table, dydt, parts)
        out[i, 0] = dydt[6]
        out[i, 1] = dydt[7]
    return out
