"""The sound field of the bearing's sources at a point: velocity spectra, retarded times
of the moving balls and the pressure series of every part (seed 003 eqs. 19, 23, 24, 26;
the computation behind :func:`.radiation.sound_pressure` and
:meth:`.result.SoundPressure.directivity`, in a module of its own so that neither imports
the other's private code).

The sources of eqs. 19 and 23 are harmonic, so each velocity record is Fourier transformed
(taken as one period of a periodic signal), every line is multiplied by the source's
transfer function at its frequency (:mod:`.sources`), and the pressures are summed in the
time domain. The pressure of ball j is p_j(t) = s_j(t - r_j(t)/c_0) / r_j(t), with s_j the
inverse transform of G(k) U_j, evaluated at each sample's own retarded time
(quasi-stationary moving source; Doppler terms of order 1e-3 are left out).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .model import Air, FieldPoint
from .sources import cylinder_transfer, oscillating_sphere_source, pulsating_sphere_source

#: Largest 2 pi f_max |delay - bin centre| of the Taylor series that applies the
#: retarded times (wider delay ranges are split into bins).
TAYLOR_LIMIT = 12.0


def _retarded(spectrum: np.ndarray, n: int, sample_rate: float, delay: np.ndarray) -> np.ndarray:
    """s(t_i - delay_i) for the periodic signal s whose rfft is ``spectrum`` (Nyquist line
    already removed).

    The delays are split into bins narrow enough that 2 pi f_max |delay - centre| <=
    TAYLOR_LIMIT; in each bin the centre delay is applied exactly (a phase e^{-j omega
    tau_b}) and the rest by the Taylor series sum_m (-d)^m / m! s^(m)(t - tau_b), the
    derivatives s^(m) coming from the spectrum times (j omega)^m. The series is summed
    until its terms' bound x^m / m! falls below 1e-16 (x <= TAYLOR_LIMIT keeps the
    rounding of the alternating sum below ~1e-11 of the signal)."""
    f = np.arange(spectrum.size) * sample_rate / n
    jw = 2j * np.pi * f
    # the m-th derivative is scaled by omega_max^m (and its coefficient by omega_max^-m):
    # (j omega)^m alone overflows at high sample rates (m ~ 60 terms of 2 pi 60 kHz)
    w_max = 2.0 * np.pi * f[-1]
    unit = jw / w_max if w_max > 0 else jw
    lo, hi = float(np.min(delay)), float(np.max(delay))
    width = 2.0 * TAYLOR_LIMIT / (2.0 * np.pi * f[-1])
    bins = max(1, math.ceil((hi - lo) / width))
    which = (
        np.minimum(((delay - lo) / width).astype(int), bins - 1)
        if bins > 1
        else np.zeros(n, dtype=int)
    )
    out = np.empty(n)
    for b in range(bins):
        mask = which == b
        if not mask.any():
            continue
        centre = 0.5 * (np.min(delay[mask]) + np.max(delay[mask]))
        derivative = spectrum * np.exp(-jw * centre)
        value = np.fft.irfft(derivative, n)[mask]
        d = delay[mask] - centre
        x = 2.0 * np.pi * f[-1] * float(np.max(np.abs(d)))
        coefficient = np.ones(d.size)
        bound, m = 1.0, 0
        while x > 0.0 and (m < x or bound > 1e-16):
            m += 1
            derivative = derivative * unit
            coefficient = coefficient * (-d * w_max) / m
            bound *= x / m
            value += coefficient * np.fft.irfft(derivative, n)[mask]
        out[mask] = value
    return out


def velocity_spectra(velocity: np.ndarray, n: int, detrend: bool) -> np.ndarray:
    """rfft along axis 0 of velocity records, with the Nyquist line and the 0 Hz line
    removed. With ``detrend`` a ramp is taken off first so that the periodic extension
    has no jump: the sample after the last, extrapolated linearly (2 v[n-1] - v[n-2]),
    is brought onto v[0] (for an already periodic record the ramp is of second order in
    the time step)."""
    v = velocity
    if detrend:
        jump = 2.0 * v[-1:] - v[-2:-1] - v[:1]
        v = v - jump * (np.arange(n) / n).reshape((n,) + (1,) * (v.ndim - 1))
    spectrum = np.fft.rfft(v, axis=0)
    if n % 2 == 0:
        spectrum[-1] = 0.0
    spectrum[0] = 0.0  # a steady velocity radiates no sound (all transfers vanish at 0 Hz)
    return spectrum


def pressures_at(inputs: dict, point: FieldPoint, medium: Air, options: dict) -> dict:
    """Pressure series of every part at ``point`` [Pa] from the inputs and options that
    :func:`.radiation.sound_pressure` collects (see there)."""
    n, fs = inputs["n"], inputs["sample_rate"]
    f = np.arange(n // 2 + 1) * fs / n
    k = 2 * np.pi * f / medium.sound_speed
    medium_kw = {"density": medium.density, "sound_speed": medium.sound_speed}
    direction = np.array([math.cos(point.angle), math.sin(point.angle)])
    direction[np.abs(direction) < 1e-15] = 0.0  # cos(pi/2) is 6e-17, not 0
    parts: dict[str, np.ndarray] = {}
    if inputs.get("ring_spectrum") is not None:
        a = options["ring_radius"]
        if point.distance <= a:
            raise InputError("point", point.distance, f"a distance > the inner-ring radius {a:g} m")
        h = cylinder_transfer(f, a, point.distance, form=options["ring_model"], **medium_kw)
        ring = inputs["ring_spectrum"]
        for i, axis in enumerate("xy"):
            parts[f"inner_ring_{axis}"] = direction[i] * np.fft.irfft(h * ring[:, i], n)
        parts["inner_ring"] = parts["inner_ring_x"] + parts["inner_ring_y"]
    if inputs.get("ball_spectrum") is not None:
        parts.update(_ball_pressures(inputs, point, k, medium_kw, options))
    parts["total"] = sum(parts[p] for p in ("inner_ring", "balls") if p in parts)
    return parts


def _ball_pressures(inputs, point, k, medium_kw, options) -> dict:
    n, fs = inputs["n"], inputs["sample_rate"]
    spectra, psi = inputs["ball_spectrum"], inputs["ball_angle"]
    r0, rp = options["ball_radius"], options["pitch_radius"]
    gap = point.position[None, None, :] - rp * np.stack([np.cos(psi), np.sin(psi)], axis=-1)
    r = np.linalg.norm(gap, axis=-1)  # (n, Z)
    if np.min(r) <= r0:
        raise InputError(
            "point",
            (point.distance, point.angle),
            f"a point outside every ball (it comes within {np.min(r):g} m of a "
            f"ball centre; ball radius {r0:g} m)",
        )
    unit = gap / r[..., None]
    delay = r / medium_kw["sound_speed"]
    components = spectra.shape[2] if spectra.ndim == 3 else 0
    out = {}
    if options["ball_source"] == "pulsating":
        g = pulsating_sphere_source(k, r0, **medium_kw)
        for c, name in [(None, "balls")] if components == 0 else [(0, "balls_x"), (1, "balls_y")]:
            total = np.zeros(n)
            for j in range(psi.shape[1]):
                u = spectra[:, j] if c is None else spectra[:, j, c]
                total += _retarded(g * u, n, fs, delay[:, j]) / r[:, j]
            out[name] = total
    else:
        g1, g2 = oscillating_sphere_source(k, r0, **medium_kw)
        for c, name in ((0, "balls_x"), (1, "balls_y")):
            total = np.zeros(n)
            for j in range(psi.shape[1]):
                u = spectra[:, j, c]
                total += unit[:, j, c] * (
                    _retarded(g1 * u, n, fs, delay[:, j]) / r[:, j]
                    + _retarded(g2 * u, n, fs, delay[:, j]) / r[:, j] ** 2
                )
            out[name] = total
    if components:
        out["balls"] = out["balls_x"] + out["balls_y"]
    return out
