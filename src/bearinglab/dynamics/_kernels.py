"""Hot loops of the rigid-ring defect model (seed 003), each with a NumPy twin.

The loop versions are plain Python that numba compiles (``*_numba`` below); the
``*_numpy`` twins are vectorised over balls and written independently, and the tests
check that the two agree. Everything is SI.

Rigid-ring model state (seed 003 sec. 3): y = [x_s, y_s, x_p, y_p, vx_s, vy_s, vx_p, vy_p]
(shaft with inner ring, pedestal with outer ring). Parameters are packed in one float
array with the indices below so that numba sees a single, stable signature.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..engine.compiling import watch

watch()  # the first compile after install is told, not silent

# ---- packed parameters of the rigid model
(
    M_S,
    M_P,
    K_S,
    C_S,
    K_P,
    C_P,
    K_HERTZ,
    HALF_CLEARANCE,
    C_BEARING,
    BALLS,
    CAGE_SPEED,
    SPIN_SPEED,
    SHAFT_SPEED,
    F_X,
    F_Y,
    UNBALANCE,
    BALL_RADIUS,
    INNER_RADIUS,
    OUTER_RADIUS,
    CAGE_PHASE,
    EXPONENT,
) = range(21)
RIGID_PARAMETER_COUNT = 21


@numba.njit(cache=True)
def _pit_drop(d, r_ball, radius, outer, depth):
    """lambda(d) of defects.edge_drop for one contact, limited by ``depth``; 0 if d <= 0."""
    if d <= 0.0:
        return 0.0
    d = min(d, r_ball)
    ring = radius - math.sqrt(max(radius * radius - d * d, 0.0))
    ball = r_ball - math.sqrt(r_ball * r_ball - d * d)
    return min(ball - ring if outer else ball + ring, depth)


def surface_deviation(psi, spin, shaft_angle, r_ball, r_in, r_out, table, dev_in, dev_out):
    """Extra clearance of every ball's inner and outer contact from the surface table [m].

    The one place where surfaces enter the contact deformation (defects.py: pits;
    waviness, ball-size errors and sampled raceway tracks from
    :class:`bearinglab.imperfections.Imperfections`, with the approach changes of
    seed 003 eqs. 14-17 taken with the opposite sign: clearance). Fills ``dev_in`` and
    ``dev_out`` (Z,) in place.

    Parameters
    ----------
    psi : array (Z,)
        Ball angular positions [rad].
    spin : array (Z,)
        Ball spin phases (0 = the marked point faces the outer race) [rad].
    shaft_angle : float
        Rotation of the inner ring since time 0 [rad].
    r_ball, r_in, r_out : float
        Ball radius, inner and outer groove-bottom radii [m].
    table : array (n, 5)
        Rows of defects.pack_defects (the row kinds are listed there).
    """
    two_pi = 2.0 * math.pi
    z = psi.shape[0]
    for j in range(z):
        dev_in[j] = 0.0
        dev_out[j] = 0.0
    row = 0
    while row < table.shape[0]:
        kind = int(table[row, 0])
        if kind <= 2:  # pits
            half = 0.5 * table[row, 1]
            depth = table[row, 2]
            angle = table[row, 3]
            for j in range(z):
                if kind == 0 or kind == 1:
                    outer = kind == 0
                    ref = angle if outer else angle + shaft_angle
                    radius = r_out if outer else r_in
                    off = (psi[j] - ref + math.pi) % two_pi - math.pi
                    drop = _pit_drop(half - abs(off) * radius, r_ball, radius, outer, depth)
                    if outer:
                        dev_out[j] += drop
                    else:
                        dev_in[j] += drop
                elif j == int(table[row, 4]):
                    # the marked point faces the outer race at spin phase 0, the inner at pi
                    off = (spin[j] - angle + math.pi) % two_pi - math.pi
                    dev_out[j] += _pit_drop(half - abs(off) * r_ball, r_ball, r_out, True, depth)
                    off = (spin[j] - angle) % two_pi - math.pi
                    dev_in[j] += _pit_drop(half - abs(off) * r_ball, r_ball, r_in, False, depth)
        elif kind <= 5:  # waviness A cos(q angle + phase)
            order, amplitude, phase = table[row, 1], table[row, 2], table[row, 3]
            ball = int(table[row, 4])
            for j in range(z):
                if kind == 3:  # outer race: a larger radius opens the contact
                    dev_out[j] += amplitude * math.cos(order * psi[j] + phase)
                elif kind == 4:  # inner race, in the turning ring's frame
                    dev_in[j] -= amplitude * math.cos(order * (psi[j] - shaft_angle) + phase)
                elif ball < 0 or ball == j:  # ball: the points facing each race
                    dev_out[j] -= amplitude * math.cos(order * spin[j] + phase)
                    dev_in[j] -= amplitude * math.cos(order * (spin[j] + math.pi) + phase)
        elif kind == 6:  # ball-size error D_wj - D_w
            j = int(table[row, 4])
            dev_in[j] -= 0.5 * table[row, 1]
            dev_out[j] -= 0.5 * table[row, 1]
        elif kind == 7:  # sampled track: ``count`` rows of heights follow
            outer = table[row, 1] == 0.0
            count = int(table[row, 2])
            for j in range(z):
                angle = psi[j] if outer else psi[j] - shaft_angle
                u = (angle % two_pi) / two_pi * count
                k = min(int(u), count - 1)
                frac = u - k
                height = (1.0 - frac) * table[row + 1 + k, 1] + frac * table[
                    row + 1 + (k + 1) % count, 1
                ]
                if outer:
                    dev_out[j] += height
                else:
                    dev_in[j] -= height
            row += count
        row += 1


def surface_deviation_numpy(psi, spin, shaft_angle, r_ball, r_in, r_out, table):
    """NumPy twin of :func:`surface_deviation`; returns (dev_in, dev_out)."""
    from .defects import edge_drop, wrap_angle

    dev_in = np.zeros_like(psi)
    dev_out = np.zeros_like(psi)
    balls = np.arange(psi.size)
    row = 0
    while row < len(table):
        kind, a, b, c, ball = table[row]
        if kind in (0, 1):
            width, depth, angle = a, b, c
            outer = kind == 0
            radius = r_out if outer else r_in
            ref = angle if outer else angle + shaft_angle
            d = 0.5 * width - np.abs(wrap_angle(psi - ref)) * radius
            drop = np.where(
                d > 0,
                np.minimum(edge_drop(d, r_ball, radius, "outer" if outer else "inner"), depth),
                0,
            )
            (dev_out if outer else dev_in)[:] += drop
        elif kind == 2:
            width, depth, angle, j = a, b, c, int(ball)
            for shift, radius, race, dev in (
                (0.0, r_out, "outer", dev_out),
                (math.pi, r_in, "inner", dev_in),
            ):
                d = 0.5 * width - abs(float(wrap_angle(spin[j] - angle - shift))) * r_ball
                if d > 0:
                    dev[j] += min(float(edge_drop(d, r_ball, radius, race)), depth)
        elif kind == 3:
            dev_out += b * np.cos(a * psi + c)
        elif kind == 4:
            dev_in -= b * np.cos(a * (psi - shaft_angle) + c)
        elif kind == 5:
            mine = (balls == int(ball)) | (ball < 0)
            dev_out -= np.where(mine, b * np.cos(a * spin + c), 0.0)
            dev_in -= np.where(mine, b * np.cos(a * (spin + np.pi) + c), 0.0)
        elif kind == 6:
            dev_in[int(ball)] -= 0.5 * a
            dev_out[int(ball)] -= 0.5 * a
        elif kind == 7:
            count = int(b)
            heights = table[row + 1 : row + 1 + count, 1]
            grid = 2 * np.pi * np.arange(count + 1) / count
            if a == 0:
                dev_out += np.interp(np.mod(psi, 2 * np.pi), grid, np.append(heights, heights[0]))
            else:
                dev_in -= np.interp(
                    np.mod(psi - shaft_angle, 2 * np.pi), grid, np.append(heights, heights[0])
                )
            row += count
        row += 1
    return dev_in, dev_out


surface_deviation_numba = numba.njit(cache=True)(surface_deviation)


def rigid_rhs(t, y, p, table, dydt):
    """Right-hand side of the 4-DOF rigid-ring model (seed 003 sec. 3); fills ``dydt``.

    m_s a_s = F + F_unb(t) - k_s x_s - c_s v_s - f_b,   m_p a_p = f_b - k_p x_p - c_p v_p,
    f_b = sum_j K [delta_j]_+^n e_j + c_b (v_s - v_p) (n = 1.5 for balls, the line law's
    10/9 or a profiled roller's fitted exponent for rollers),
    delta_j = (x_s - x_p) cos psi_j + (y_s - y_p) sin psi_j - P_d/2 - lambda_j(t),
    psi_j = psi_0 + 2 pi j / Z + omega_c t; lambda_j from :func:`surface_deviation`.
    """
    z = int(p[BALLS])
    psi = np.empty(z)
    spin = np.empty(z)
    dev_in = np.empty(z)
    dev_out = np.empty(z)
    for j in range(z):
        psi[j] = p[CAGE_PHASE] + 2.0 * math.pi * j / z + p[CAGE_SPEED] * t
        spin[j] = p[SPIN_SPEED] * t
    surface_deviation_numba(
        psi,
        spin,
        p[SHAFT_SPEED] * t,
        p[BALL_RADIUS],
        p[INNER_RADIUS],
        p[OUTER_RADIUS],
        table,
        dev_in,
        dev_out,
    )
    rx = y[0] - y[2]
    ry = y[1] - y[3]
    fx = p[C_BEARING] * (y[4] - y[6])
    fy = p[C_BEARING] * (y[5] - y[7])
    for j in range(z):
        c = math.cos(psi[j])
        s = math.sin(psi[j])
        delta = rx * c + ry * s - p[HALF_CLEARANCE] - dev_in[j] - dev_out[j]
        if delta > 0.0:
            if p[EXPONENT] == 1.5:  # a ball's Hertz law
                q = p[K_HERTZ] * delta * math.sqrt(delta)
            else:  # a roller's line law (10/9, or a profiled roller's fit)
                q = p[K_HERTZ] * delta ** p[EXPONENT]
            fx += q * c
            fy += q * s
    phase = p[SHAFT_SPEED] * t
    unb = p[UNBALANCE] * p[SHAFT_SPEED] ** 2
    dydt[0] = y[4]
    dydt[1] = y[5]
    dydt[2] = y[6]
    dydt[3] = y[7]
    dydt[4] = (p[F_X] + unb * math.cos(phase) - p[K_S] * y[0] - p[C_S] * y[4] - fx) / p[M_S]
    dydt[5] = (p[F_Y] + unb * math.sin(phase) - p[K_S] * y[1] - p[C_S] * y[5] - fy) / p[M_S]
    dydt[6] = (fx - p[K_P] * y[2] - p[C_P] * y[6]) / p[M_P]
    dydt[7] = (fy - p[K_P] * y[3] - p[C_P] * y[7]) / p[M_P]


def rigid_rhs_numpy(t, y, p, table):
    """NumPy twin of :func:`rigid_rhs`; returns dy/dt."""
    z = int(p[BALLS])
    psi = p[CAGE_PHASE] + 2.0 * np.pi * np.arange(z) / z + p[CAGE_SPEED] * t
    spin = np.full(z, p[SPIN_SPEED] * t)
    dev_in, dev_out = surface_deviation_numpy(
        psi, spin, p[SHAFT_SPEED] * t, p[BALL_RADIUS], p[INNER_RADIUS], p[OUTER_RADIUS], table
    )
    rel = y[0:2] - y[2:4]
    e = np.stack([np.cos(psi), np.sin(psi)])
    delta = rel @ e - p[HALF_CLEARANCE] - dev_in - dev_out
    q = p[K_HERTZ] * np.clip(delta, 0.0, None) ** p[EXPONENT]
    f = e @ q + p[C_BEARING] * (y[4:6] - y[6:8])
    phase = p[SHAFT_SPEED] * t
    unb = p[UNBALANCE] * p[SHAFT_SPEED] ** 2 * np.array([np.cos(phase), np.sin(phase)])
    a_s = (np.array([p[F_X], p[F_Y]]) + unb - p[K_S] * y[0:2] - p[C_S] * y[4:6] - f) / p[M_S]
    a_p = (f - p[K_P] * y[2:4] - p[C_P] * y[6:8]) / p[M_P]
    return np.concatenate([y[4:8], a_s, a_p])


rigid_rhs_numba = numba.njit(cache=True)(rigid_rhs)


@numba.njit(cache=True)
def rigid_accelerations(p, table, t_out, states):
    """Pedestal accelerations (x, y) at the output states [m/s^2]."""
    out = np.empty((t_out.shape[0], 2))
    dydt = np.empty(8)
    for i in range(t_out.shape[0]):
        rigid_rhs_numba(t_out[i], states[i], p, table, dydt)
        out[i, 0] = dydt[6]
        out[i, 1] = dydt[7]
    return out
