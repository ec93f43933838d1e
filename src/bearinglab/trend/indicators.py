"""Health indicators of a record, computed for many records at once (layer 1).

Each function takes samples along the last axis of an array (records x channels x
samples, say) and returns one value per record and channel; the sensor's unit is kept
(g, m/s², V) except where a unit is asked for. Definitions and sources:

- ``rms``: root mean square of the record about its mean (the sensor's offset removed),
  sqrt(<(x - <x>)²>): the overall vibration level ([Randall2011] ch. 1).
- ``peak``: max |x - <x>|, the largest excursion.
- ``crest_factor``: peak / rms [-]; rises as impacts appear in an otherwise steady signal
  and falls again when the damage spreads and the rms catches up ([Randall2011] ch. 5).
- ``kurtosis``: <(x - <x>)⁴> / <(x - <x>)²>² [-], 3 for Gaussian noise; the classic
  statistic of bearing impacts ([DyerStewart1978]).
- ``spectral_kurtosis``: the largest spectral kurtosis of the fast kurtogram of the record
  ([Antoni2007a]; :func:`bearinglab.signal.kurtogram.kurtogram_maxima`): the kurtosis of
  the complex envelope in the band where impacts stand out most, 0 for Gaussian noise.
- ``velocity_rms``: r.m.s. vibration velocity over 10-1000 Hz [m/s], integrated from the
  acceleration in the frequency domain (V(f) = A(f) / (i 2 pi f), Parseval's sum over the
  band): the quantity whose zones ISO 20816-1 and -3 state ([ISO20816-1], [ISO20816-3]);
  needs the channel's unit.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

#: The indicators computed for every record and channel, in the order reported.
INDICATORS = ("rms", "peak", "crest_factor", "kurtosis", "spectral_kurtosis")
#: Standard gravity [m/s²] (ISO 80000-3), one g.
STANDARD_GRAVITY = 9.80665
#: Acceleration units a channel may be given in -> their value in m/s².
ACCELERATION_UNITS = {"g": STANDARD_GRAVITY, "m/s2": 1.0}
#: Other spellings of those units.
_UNIT_SPELLINGS = {"m/s^2": "m/s2", "m/s²": "m/s2", "m_s2": "m/s2", "ms2": "m/s2", "gn": "g"}
#: ISO 20816-1 and -3's band of the r.m.s. velocity for machines above 600 r/min [Hz].
VELOCITY_BAND = (10.0, 1000.0)


def acceleration_unit(unit: str | None) -> str | None:
    """The channel unit as ``g`` or ``m/s2`` (None passes; InputError for any other).

    >>> acceleration_unit("m/s^2"), acceleration_unit("G")
    ('m/s2', 'g')
    """
    if unit is None:
        return None
    key = str(unit).strip().lower()
    key = _UNIT_SPELLINGS.get(key, key)
    if key not in ACCELERATION_UNITS:
        raise InputError(
            "unit",
            unit,
            "g or m/s2: an acceleration, which the ISO 20816 zones use as the r.m.s. "
            "velocity integrated from it",
        )
    return key


def scalar_indicators(x) -> dict[str, np.ndarray]:
    """rms, peak, crest_factor and kurtosis along the last axis of ``x``.

    >>> t = np.arange(1000) / 1000.0
    >>> d = scalar_indicators(np.sqrt(2.0) * np.sin(2 * np.pi * 10 * t))
    >>> [round(float(d[k]), 3) for k in ("rms", "peak", "crest_factor", "kurtosis")]
    [1.0, 1.414, 1.414, 1.5]
    """
    a = np.asarray(x, dtype=float)
    a = a - a.mean(axis=-1, keepdims=True)
    power = np.mean(a * a, axis=-1)
    rms = np.sqrt(power)
    peak = np.max(np.abs(a), axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        crest = peak / rms
        kurtosis = np.mean(a**4, axis=-1) / power**2
    return {"rms": rms, "peak": peak, "crest_factor": crest, "kurtosis": kurtosis}


def record_indicators(x, sample_rate: float) -> dict[str, np.ndarray]:
    """The :data:`INDICATORS` of every record of ``x`` (samples along the last axis)."""
    from ..signal.kurtogram import kurtogram_maxima

    out = scalar_indicators(x)
    out["spectral_kurtosis"] = kurtogram_maxima(x, sample_rate)
    return out


def velocity_rms(x, sample_rate: float, unit: str, band=VELOCITY_BAND) -> np.ndarray:
    """r.m.s. velocity [m/s] over ``band`` [Hz] of accelerations ``x`` in ``unit``.

    The record's own spectrum (no window; Parseval's sum, so a tone on a bin keeps its
    exact power) divided by 2 pi f; bins from band[0] to band[1] inclusive.

    >>> fs, f0 = 25600.0, 160.0
    >>> t = np.arange(2560) / fs
    >>> a = 10.0 * np.sqrt(2.0) * np.sin(2 * np.pi * f0 * t)     # 10 m/s² r.m.s.
    >>> round(float(velocity_rms(a, fs, "m/s2")) * 1e3, 4)        # mm/s
    9.9472
    >>> round(10.0 / (2 * np.pi * f0) * 1e3, 4)
    9.9472
    """
    a = np.asarray(x, dtype=float)
    n = a.shape[-1]
    spectrum = np.fft.rfft(a - a.mean(axis=-1, keepdims=True), axis=-1)
    f = np.fft.rfftfreq(n, 1.0 / sample_rate)
    keep = (f >= band[0]) & (f <= band[1]) & (f > 0)
    weight = np.where(np.isclose(f[keep], sample_rate / 2), 1.0, 2.0)
    v = spectrum[..., keep] / (2 * math.pi * f[keep])
    mean_square = np.sum(weight * np.abs(v) ** 2, axis=-1) / n**2
    return np.sqrt(mean_square) * ACCELERATION_UNITS[acceleration_unit(unit)]
