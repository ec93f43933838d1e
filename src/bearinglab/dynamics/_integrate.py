"""Compiled time integrators with error control, resampled at the output times.

- :func:`dopri_chunk`: the explicit Dormand-Prince 5(4) pair (Dormand J. R., Prince P. J.,
  "A family of embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19-26;
  the pair behind SciPy's ``RK45``) for the rigid-ring model, whose stiffest mode (the
  shaft on its Hertz contacts, a few kHz) an explicit method follows at the step the
  accuracy needs anyway.
- :func:`rosenbrock_chunk` (in ``_rosenbrock``) for the stiff slip model.

Both integrate one *chunk* of output times and return the state and step size to carry
into the next, so that the caller can show progress between chunks. Between accepted
steps the output is interpolated: by Shampine's 4th-order continuous extension
(:func:`dopri_dense`), or by the cubic Hermite polynomial through the states and
derivatives at both ends (:func:`hermite`, third order). The step never exceeds
``h_max``, which the callers tie to the output interval. Step control: the error norm is the RMS of
err_i / (atol_i + rtol max(|y_i|, |y_new,i|)); a step is accepted when it is <= 1 and the
next step is h * clip(0.9 norm^(-1/5), 0.2, 5) (Hairer, Norsett & Wanner, *Solving
Ordinary Differential Equations I*, 2nd ed., 1993, sec. II.4).
"""

from __future__ import annotations

import numba
import numpy as np

from ..engine.compiling import watch
from . import _kernels

watch()  # the first compile after install is told, not silent

OK, TOO_MANY_STEPS, STEP_TOO_SMALL, NOT_FINITE = 0, 1, 2, 3
STATUS_TEXT = {
    TOO_MANY_STEPS: "the step limit was reached",
    STEP_TOO_SMALL: "the step size fell below 1e-14 s",
    NOT_FINITE: "the state became non-finite",
}

# Dormand-Prince coefficients
_C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0])
_A = np.array(
    [
        [0, 0, 0, 0, 0, 0],
        [1 / 5, 0, 0, 0, 0, 0],
        [3 / 40, 9 / 40, 0, 0, 0, 0],
        [44 / 45, -56 / 15, 32 / 9, 0, 0, 0],
        [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0, 0],
        [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0],
        [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84],
    ]
)
_E = np.array([71 / 57600, 0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525, -1 / 40])
# A continuous extension of order 4 of the Dormand-Prince pair (Shampine L. F., "Some
# practical Runge-Kutta formulas", Math. Comp. 46 (1986) 135-150; the coefficients of
# SciPy's RK45.P): y(t + x h) = y + h sum_k K_k (P_k1 x + P_k2 x^2 + P_k3 x^3 + P_k4 x^4)
_P = np.array(
    [
        [1, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
        [0, 0, 0, 0],
        [0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
        [0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
        [0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632],
        [0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
        [0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423],
    ]
)


@numba.njit(cache=True)
def hermite(t0, y0, f0, t1, y1, f1, t, out):
    """Cubic Hermite interpolation between (t0, y0, y0') and (t1, y1, y1') at t."""
    h = t1 - t0
    s = (t - t0) / h
    h00 = (1.0 + 2.0 * s) * (1.0 - s) ** 2
    h10 = s * (1.0 - s) ** 2
    h01 = s * s * (3.0 - 2.0 * s)
    h11 = s * s * (s - 1.0)
    for i in range(y0.shape[0]):
        out[i] = h00 * y0[i] + h10 * h * f0[i] + h01 * y1[i] + h11 * h * f1[i]


@numba.njit(cache=True)
def dopri_dense(t0, y0, h, k, t, out):
    """Shampine's 4th-order continuous extension of the Dormand-Prince step (t0, y0, h) with
    stages ``k`` (7 x n), at t in [t0, t0 + h]."""
    x = (t - t0) / h
    w = np.empty(7)
    for m in range(7):
        w[m] = x * (_P[m, 0] + x * (_P[m, 1] + x * (_P[m, 2] + x * _P[m, 3])))
    for i in range(y0.shape[0]):
        acc = 0.0
        for m in range(7):
            acc += w[m] * k[m, i]
        out[i] = y0[i] + h * acc


@numba.njit(cache=True)
def error_norm(err, y0, y1, rtol, atol):
    """RMS of err / (atol + rtol max(|y0|, |y1|))."""
    total = 0.0
    for i in range(err.shape[0]):
        scale = atol[i] + rtol * max(abs(y0[i]), abs(y1[i]))
        total += (err[i] / scale) ** 2
    return np.sqrt(total / err.shape[0])


@numba.njit(cache=True)
def outputs_before(t, y, t_out, out):
    """Fill the outputs at (or before) the start time ``t`` with ``y``; return the index of
    the first output still to come."""
    i_out = 0
    while i_out < t_out.shape[0] and t_out[i_out] <= t:
        out[i_out] = y
        i_out += 1
    return i_out


@numba.njit(cache=True)
def step_limits(h, h_max, steps, rejected, max_steps):
    """(step to try, OK): ``h`` capped at ``h_max``; or the status that ends the chunk,
    TOO_MANY_STEPS once ``max_steps`` steps were tried, STEP_TOO_SMALL below 1e-14 s."""
    if steps + rejected >= max_steps:
        return h, TOO_MANY_STEPS
    h = min(h, h_max)
    if h < 1e-14:
        return h, STEP_TOO_SMALL
    return h, OK


@numba.njit(cache=True)
def retry_not_finite(h):
    """After a step whose error norm is not finite: (a quarter of ``h`` to retry with, OK),
    or (h, NOT_FINITE) once ``h`` is below 1e-12 s."""
    if h < 1e-12:
        return h, NOT_FINITE
    return 0.25 * h, OK


@numba.njit(cache=True)
def dopri_chunk(rhs, p, table, t, y, h, t_out, rtol, atol, h_max, max_steps):
    """Integrate dy/dt = rhs(t, y, p, table) from t over the output times ``t_out``.

    Returns (Y (len(t_out), n), t, y, h, steps, rejected, status).
    """
    n = y.shape[0]
    out = np.empty((t_out.shape[0], n))
    k = np.empty((7, n))
    ytmp = np.empty(n)
    ynew = np.empty(n)
    err = np.empty(n)
    rhs(t, y, p, table, k[0])
    steps = 0
    rejected = 0
    i_out = outputs_before(t, y, t_out, out)
    while i_out < t_out.shape[0]:
        h, status = step_limits(h, h_max, steps, rejected, max_steps)
        if status != OK:
            return out, t, y, h, steps, rejected, status
        for s in range(1, 7):
            for i in range(n):
                acc = y[i]
                for m in range(s):
                    acc += h * _A[s, m] * k[m, i]
                ytmp[i] = acc
            rhs(t + _C[s] * h, ytmp, p, table, k[s])
        for i in range(n):
            ynew[i] = ytmp[i]  # the 7th stage point is the 5th-order solution
            acc = 0.0
            for m in range(7):
                acc += _E[m] * k[m, i]
            err[i] = h * acc
        norm = error_norm(err, y, ynew, rtol, atol)
        if not np.isfinite(norm):
            h, status = retry_not_finite(h)
            if status != OK:
                return out, t, y, h, steps, rejected, status
            rejected += 1
            continue
        if norm <= 1.0:
            t_new = t + h
            while i_out < t_out.shape[0] and t_out[i_out] <= t_new:
                dopri_dense(t, y, h, k, t_out[i_out], out[i_out])
                i_out += 1
            t = t_new
            y = ynew.copy()
            k[0] = k[6]
            steps += 1
            factor = 5.0 if norm == 0.0 else min(5.0, max(0.2, 0.9 * norm**-0.2))
            h *= factor
        else:
            rejected += 1
            h *= max(0.2, 0.9 * norm**-0.2)
    return out, t, y, h, steps, rejected, OK


@numba.njit(cache=True)
def dopri_chunk_rigid(p, table, t, y, h, t_out, rtol, atol, h_max, max_steps):
    """:func:`dopri_chunk` with the rigid-ring model's right-hand side bound.

    The right-hand side is read as the module attribute ``_kernels.rigid_rhs_numba`` so that
    numba's on-disk cache can key this function; a compiled function passed in as an
    argument (or a name imported with ``from ... import``) cannot be cached, and every new
    process would compile the integrator again (several seconds).
    """
    return dopri_chunk(
        _kernels.rigid_rhs_numba, p, table, t, y, h, t_out, rtol, atol, h_max, max_steps
    )


def cached_on_disk(dispatcher) -> bool:
    """Whether numba's on-disk cache holds code for ``dispatcher`` that matches its source,
    so that a new process loads it instead of compiling it (reads numba's cache index, a
    private interface: False when it cannot tell)."""
    try:
        return bool(dispatcher._cache._cache_file._load_index())
    except Exception:  # noqa: BLE001 - any change in numba's internals means "cannot tell"
        return False
