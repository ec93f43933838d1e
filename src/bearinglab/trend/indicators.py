"""Health indicators of a record, computed for many records at once (layer 1).

Each function takes samples along the last axis of an array (records x channels x
samples, say) and returns one value per record and channel; the sensor's unit is kept
(g, m/s², V) except where a unit is asked for.

**Band.** The trend's indicators are computed over the band from 0 Hz to ``max_frequency``,
by default a quarter of the sample rate (:data:`BAND_FRACTION`, half the Nyquist frequency;
6.4 kHz on PRONOSTIA's 25.6 kHz): the top half of the recorded range holds the
anti-aliasing filter's roll-off (analysers keep 1/2.56 of the rate, [Randall2011] sec.
3.2) and the high-frequency transients of surface distress that come and go on a healthy
machine - asperity contact while a new bearing runs in, debris and electrical spikes -
while a localised defect's impacts excite the structure over the whole band. Measured on
the six PRONOSTIA learning runs (docs/capabilities/trend.md): the running-in of the 4200 N
condition raises the power 3 to 700 times from 6.4 kHz to the Nyquist frequency and
lowers it below, most of Bearing1_2's bursts of impacts lie above 6.4 kHz, and every
failure raises every band. The velocity of the ISO zones keeps its own band (10-1000 Hz).

Definitions and sources:

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
#: Default top of the indicators' band, as a fraction of the sample rate (module docstring).
BAND_FRACTION = 0.25


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


def band_top(sample_rate: float, max_frequency: float | None = None) -> float:
    """The top of the indicators' band [Hz]: ``max_frequency``, or BAND_FRACTION of the
    sample rate (InputError above the Nyquist frequency or at or below 0).

    >>> band_top(25600.0), band_top(25600.0, 10000.0)
    (6400.0, 10000.0)
    """
    if max_frequency is None:
        return BAND_FRACTION * float(sample_rate)
    top = float(max_frequency)
    if not (math.isfinite(top) and 0.0 < top <= sample_rate / 2):
        raise InputError(
            "max_frequency",
            max_frequency,
            f"a frequency in (0, {sample_rate / 2:g}] Hz (the Nyquist frequency of the records)",
        )
    return top


def band_limited(x, sample_rate: float, top: float) -> np.ndarray:
    """``x`` (samples along the last axis) without its mean and its content above ``top``
    [Hz]: the bins above it set to zero in the record's spectrum (no window: a record's
    own spectrum; a tone below ``top`` on a bin is kept exactly).

    >>> t = np.arange(1000) / 1000.0
    >>> y = band_limited(np.sin(2 * np.pi * 50 * t) + np.sin(2 * np.pi * 300 * t), 1000.0, 100.0)
    >>> bool(np.allclose(y, np.sin(2 * np.pi * 50 * t)))
    True
    """
    a = np.asarray(x, dtype=float)
    n = a.shape[-1]
    if top >= sample_rate / 2:
        return a - a.mean(axis=-1, keepdims=True)
    spectrum = np.fft.rfft(a, axis=-1)
    f = np.fft.rfftfreq(n, 1.0 / sample_rate)
    spectrum[..., (f > top) | (f == 0.0)] = 0.0
    return np.fft.irfft(spectrum, n=n, axis=-1)


def record_indicators(x, sample_rate: float, max_frequency: float | None = None) -> dict:
    """The :data:`INDICATORS` of every record of ``x`` (samples along the last axis), over
    the band 0 Hz to :func:`band_top` (module docstring; ``max_frequency`` [Hz])."""
    from ..signal.kurtogram import kurtogram_maxima

    top = band_top(sample_rate, max_frequency)
    out = scalar_indicators(band_limited(x, sample_rate, top))
    out["spectral_kurtosis"] = kurtogram_maxima(x, sample_rate, max_frequency=top)
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
