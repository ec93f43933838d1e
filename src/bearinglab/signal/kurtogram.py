"""The fast kurtogram: the band of largest spectral kurtosis on Antoni's 1/3-binary tree.

Layer 1. Antoni J., "Fast computation of the kurtogram for the detection of transient
faults", MSSP 21(1) (2007) 108-124: the kurtosis of the complex envelope of the signal in
the bands of a 1/3-binary tree - level k (k = 0, 1, 2, ...) splits [0, f_s/2] into 2^k
bands of width f_s/2^(k+1), the levels k + log2(3) - 1 (shown as 1.6, 2.6, ...) into
3 x 2^(k-1) bands of width f_s/(3 x 2^k) - and the band of largest kurtosis is where the
impacts of a fault excite the structure most clearly above the background (sec. 3).

Here the complex envelope of each band is computed in the frequency domain (the signal's
FFT restricted to the band, tapered at its edges by a Tukey window, inverse-transformed
at the band's own, decimated, length) instead of by Antoni's cascade of quasi-analytic
FIR filters: the same grid of bands and the same kurtosis K = <|c|^4> / <|c|^2>^2 - 2
(0 for complex Gaussian noise), at a cost of one FFT per level.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from .spectra import fast_length, rate, samples

#: Fewest envelope samples a band's kurtosis is estimated from: the kurtosis of Gaussian
#: noise estimated from m samples scatters by about sqrt(24/m)... 0.2 at m = 600 (complex
#: envelope: about 2/sqrt(m)); bands with fewer samples are not considered.
MIN_BAND_SAMPLES = 128
#: Relative width of the cosine taper at each edge of a band (Tukey window parameter).
TAPER = 0.25
#: Highest frequency a band may reach, as a fraction of the sample rate: vibration
#: analysers sample at 2.56 times their top frequency because the anti-aliasing filter
#: rolls off above it (e.g. ISO 18431-1 practice; Randall R. B., Vibration-based Condition
#: Monitoring, Wiley 2011, sec. 3.2); a band in that roll-off measures the filter and
#: the converter's noise, not the machine.
USABLE_FRACTION = 1.0 / 2.56


class Kurtogram(NamedTuple):
    """The fast kurtogram and its best band.

    ``band`` (low, high), ``centre`` and ``bandwidth`` [Hz] and ``kurtosis`` [-] of the
    band of largest kurtosis, its ``level``; ``levels`` [-], and per level the band
    ``centres`` [Hz] and ``values`` (kurtosis) as tuples of arrays.
    """

    band: tuple[float, float]
    centre: float
    bandwidth: float
    kurtosis: float
    level: float
    levels: tuple
    centres: tuple
    values: tuple


def kurtogram_levels(max_level: int) -> list[tuple[float, int]]:
    """(level, number of bands) of the 1/3-binary tree up to ``max_level``.

    >>> kurtogram_levels(2)
    [(0.0, 1), (1.0, 2), (1.6, 3), (2.0, 4)]
    """
    out = [(0.0, 1)]
    for k in range(1, max_level + 1):
        out.append((float(k), 2**k))
        if k < max_level:
            out.append((round(k + math.log2(3) - 1, 1), 3 * 2 ** (k - 1)))
    return out


def fast_kurtogram(
    x,
    sample_rate,
    max_level: int | None = None,
    min_bandwidth: float = 0.0,
    max_frequency: float | None = None,
) -> Kurtogram:
    """Fast kurtogram of ``x`` and its band of largest kurtosis (Antoni 2007).

    Parameters
    ----------
    x : array_like
        Samples (1-D, >= 2 x MIN_BAND_SAMPLES), any unit.
    sample_rate : float
        Sample rate [Hz].
    max_level : int, optional
        Deepest level; default the deepest whose bands keep MIN_BAND_SAMPLES envelope
        samples (at most 10).
    min_bandwidth : float
        Narrowest band to consider [Hz], e.g. wide enough to pass a fault's modulation
        sidebands; deeper levels are skipped.
    max_frequency : float, optional
        Bands reaching above this frequency are not chosen [Hz]; default
        USABLE_FRACTION x f_s (the anti-aliasing filter's roll-off). The whole band
        (level 0) is always a candidate.

    Returns
    -------
    Kurtogram

    Examples
    --------
    Impacts ringing at 3 kHz, 50 times a second, in white noise: the best band holds 3 kHz.

    >>> fs = 12000.0
    >>> t = np.arange(2**15) / fs
    >>> x = np.exp(-(t % 0.02) / 1e-3) * np.sin(2 * np.pi * 3000.0 * t)
    >>> x = x + 0.3 * np.random.default_rng(1).standard_normal(t.size)
    >>> k = fast_kurtogram(x, fs)
    >>> bool(k.band[0] < 3000.0 < k.band[1]), bool(k.kurtosis > 1.0)
    (True, True)
    """
    x = samples(x)
    fs = rate(sample_rate)
    deepest = _deepest_level(x.size)
    try:
        min_bw = float(min_bandwidth)
    except (TypeError, ValueError):
        min_bw = math.nan
    if not 0.0 <= min_bw < fs / 2:
        raise InputError("min_bandwidth", min_bandwidth, f"a number in [0, {fs / 2:g}) Hz")
    if max_level is None:
        max_level = min(deepest, 10)
    elif (
        isinstance(max_level, bool)
        or not isinstance(max_level, (int, np.integer))
        or not 0 <= max_level <= deepest
    ):
        raise InputError("max_level", max_level, f"an integer in [0, {deepest}]")
    ceiling = USABLE_FRACTION * fs if max_frequency is None else float(max_frequency)
    best = None
    levels, centres, values = [], [], []
    for level, mid, width, kurt, usable in _levels(x, fs, int(max_level), min_bw, ceiling):
        levels.append(level)
        centres.append(mid)
        values.append(kurt)
        if not usable.any():
            continue
        k = int(np.argmax(np.where(usable, kurt, -np.inf)))
        if best is None or kurt[k] > best[0]:
            best = (float(kurt[k]), level, float(mid[k]), width)
    kurtosis, level, centre, width = best
    return Kurtogram(
        (centre - width / 2, centre + width / 2),
        centre,
        width,
        kurtosis,
        level,
        tuple(levels),
        tuple(centres),
        tuple(values),
    )


def tukey(m: int, alpha: float) -> np.ndarray:
    """The symmetric Tukey (tapered cosine) window of ``m`` points whose tapers cover the
    fraction ``alpha`` of it, as ``scipy.signal.windows.tukey(m, alpha)`` defines it
    (Harris 1978 [HarrisFJ1978]); here so that a kurtogram does not import scipy.signal
    (~0.5 s).

    >>> tukey(5, 0.5).round(3).tolist()
    [0.0, 1.0, 1.0, 1.0, 0.0]
    """
    if m <= 1:
        return np.ones(max(m, 0))
    if alpha <= 0:
        return np.ones(m)
    if alpha >= 1:
        alpha = 1.0
    n = np.arange(m)
    width = int(np.floor(alpha * (m - 1) / 2.0))
    w = np.ones(m)
    head, tail = n[: width + 1], n[m - width - 1 :]
    w[: width + 1] = 0.5 * (1 + np.cos(np.pi * (-1 + 2.0 * head / alpha / (m - 1))))
    w[m - width - 1 :] = 0.5 * (
        1 + np.cos(np.pi * (-2.0 / alpha + 1 + 2.0 * tail / alpha / (m - 1)))
    )
    return w


def _deepest_level(n: int) -> int:
    """The deepest level whose bands keep MIN_BAND_SAMPLES envelope samples of a record of
    ``n`` samples (InputError below 2 x MIN_BAND_SAMPLES samples)."""
    if n < 2 * MIN_BAND_SAMPLES:
        raise InputError(
            "x", f"{n} samples", f"at least {2 * MIN_BAND_SAMPLES} samples for a kurtogram"
        )
    return int(math.floor(math.log2(n / (2 * MIN_BAND_SAMPLES))))


def _levels(x: np.ndarray, fs: float, max_level: int, min_bw: float, ceiling: float):
    """Per level of the 1/3-binary tree: (level, band centres [Hz], band width [Hz], the
    kurtosis of each band's complex envelope along the last axis of ``x``, the bands that
    may be chosen). ``x`` holds records along its last axis; the kurtosis has the leading
    shape plus one axis of bands."""
    n = x.shape[-1]
    nfft = fast_length(n)
    spectrum = np.fft.rfft(x - x.mean(axis=-1, keepdims=True), n=nfft, axis=-1)
    df = fs / nfft
    for level, count in kurtogram_levels(max_level):
        width = fs / 2 / count
        if width < min_bw and level > 0:
            break
        edges = np.arange(count + 1) * width
        kurt = np.full((*x.shape[:-1], count), -2.0)
        for i in range(count):
            lo, hi = int(round(edges[i] / df)), int(round(edges[i + 1] / df))
            band = spectrum[..., lo:hi]
            m = band.shape[-1]
            if m < 8:
                continue
            power = np.abs(np.fft.ifft(band * tukey(m, TAPER), axis=-1)) ** 2
            mean = power.mean(axis=-1)
            fourth = np.mean(power**2, axis=-1)
            safe = np.where(mean > 0, mean, 1.0)
            kurt[..., i] = np.where(mean > 0, fourth / safe**2 - 2.0, -2.0)
        # the bands touching 0 Hz hold the mean and the low-frequency shaft lines: skip them
        usable = (
            (np.arange(count) > 0) & (edges[1:] <= ceiling * (1 + 1e-9))
            if count > 1
            else np.ones(1, bool)
        )
        yield level, edges[:-1] + width / 2, width, kurt, usable


def kurtogram_maxima(x, sample_rate, max_frequency: float | None = None) -> np.ndarray:
    """The largest spectral kurtosis of the fast kurtogram of each record of ``x``.

    The same bands and kurtosis as :func:`fast_kurtogram` (its ``kurtosis``, at the
    default depth and ``min_bandwidth`` 0), computed for many records at once: one FFT of
    every record, then one inverse FFT per band for all of them.

    Parameters
    ----------
    x : array_like
        Records along the last axis (e.g. records x channels x samples), any unit; each
        at least 2 x MIN_BAND_SAMPLES samples, finite.
    sample_rate : float
        Sample rate [Hz].
    max_frequency : float, optional
        Bands reaching above it are not chosen [Hz]; default USABLE_FRACTION x f_s.

    Returns
    -------
    numpy.ndarray
        The largest kurtosis [-], of the leading shape of ``x``.

    Examples
    --------
    >>> rng = np.random.default_rng(2)
    >>> x = rng.standard_normal((3, 4096))
    >>> bool(np.allclose(kurtogram_maxima(x, 10e3),
    ...                  [fast_kurtogram(r, 10e3).kurtosis for r in x]))
    True
    """
    a = np.asarray(x, dtype=float)
    if a.ndim < 1 or not np.all(np.isfinite(a)):
        raise InputError("x", f"array of shape {a.shape}", "finite samples along the last axis")
    fs = rate(sample_rate)
    deepest = min(_deepest_level(a.shape[-1]), 10)
    ceiling = USABLE_FRACTION * fs if max_frequency is None else float(max_frequency)
    best = np.full(a.shape[:-1], -np.inf)
    for _, _, _, kurt, usable in _levels(a, fs, deepest, 0.0, ceiling):
        if usable.any():
            best = np.maximum(best, np.max(kurt[..., usable], axis=-1))
    return best
