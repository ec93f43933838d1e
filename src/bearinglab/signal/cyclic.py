"""Cyclic spectral analysis: the fast spectral correlation, the spectral coherence and the
improved envelope spectrum.

Layer 1 (NumPy). The spectral correlation of a signal x at cyclic frequency alpha and
spectral frequency f (asymmetric form, [Antoni2017] eq. 1) is
S_x(alpha, f) = lim E{X_T(f) X_T(f - alpha)^*} / T, and its spectral coherence
gamma_x(alpha, f) = S_x(alpha, f) / sqrt(S_x(0, f) S_x(0, f - alpha)) ([Antoni2007b]
sec. 3.2). A bearing fault makes x second-order cyclostationary: its impacts, repeated at
the fault's rate and amplitude-modulated, put S_x(alpha, f) at the harmonics of that rate
across the band their resonance excites ([Antoni2007c]); the coherence weighs every
spectral frequency by its own power, as pre-whitening does.

The fast spectral correlation ([Antoni2017] sec. 3, eqs. 12-16): the short-time Fourier
transform X(i, k) of x (window w of N_w samples, hop R, bins f_k = k f_s / N_w, phase
referred to each frame's start) is multiplied with its own copy shifted by p bins,
X(i, k) X(i, k - p)^*; the discrete Fourier transform of that product over the frames i
is an estimate of S_x(alpha, f_k) near alpha = p f_s / N_w, weighted by the window's
kernel R_w(alpha - p Delta f), R_w(beta) = sum_n w(n)^2 exp(-j 2 pi (n - N_0) beta / f_s)
(N_0 the window's centre, after the phase correction exp(-j 2 pi N_0 (alpha - p Delta f)
/ f_s)); the estimates of every shift p whose kernel covers alpha are added and divided
by the sum of their kernels (eq. 16). Here the shifts used for alpha are those within
2 Delta f of it (the kernel of a Hann window's square falls to 1/6 of its peak there),
and the hop is N_w / 8, so that the frame rate 8 Delta f keeps the products' main lobe
(+-3 Delta f) from folding onto other cyclic frequencies. The cyclic transform over the
frames is the full-record one of [Antoni2017] at resolution f_s / (K R)
(:func:`fast_spectral_correlation`); for diagnosis it is taken over Welch blocks of frames
instead (Hann taper, half overlap) and the squared moduli averaged
(:func:`spectral_coherence`), which puts the cyclic frequencies on the grid of a Welch
squared envelope spectrum of the same segment length and averages its noise.

The improved envelope spectrum (IES) is the spectral coherence averaged over a band of
spectral frequencies ([Mauricio2020] eq. 3, there the modulus |gamma|; here the squared
modulus, whose expectation under stationary noise is known exactly:
:func:`coherence_null`): :func:`improved_envelope_spectrum`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from .spectra import rate, samples

#: STFT hop as a fraction of the window: the frame rate is then 8 Delta f, above twice the
#: half-width (3 Delta f) of the kernel R_w of a Hann window's square.
HOP_FRACTION = 8
#: Largest |alpha - p Delta f| (in Delta f) at which shift p contributes to alpha.
SHIFT_REACH = 2.0
#: Fewest spectral bins a band of the IES may average.
MIN_CARRIERS = 3
#: Blocks of frames processed at once (bounds the memory: blocks x cyclic x spectral
#: frequencies complex numbers).
CHUNK_BLOCKS = 4


class CyclicCorrelation(NamedTuple):
    """Full-record fast spectral correlation: ``alpha`` [Hz] (the cyclic frequencies,
    spacing f_s / (K R)), ``frequency`` [Hz] (the spectral frequencies f_k),
    ``correlation`` S_x(alpha, f_k) (complex, shape (alpha, frequency); NaN for the bins
    below the cyclic range) and ``power`` S_x(0, f_k), both as averages of |X(i, k)|^2
    [unit of x squared] (:func:`fast_spectral_correlation`)."""

    alpha: np.ndarray
    frequency: np.ndarray
    correlation: np.ndarray
    power: np.ndarray


class SpectralCoherence(NamedTuple):
    """Welch-averaged squared spectral coherence (:func:`spectral_coherence`).

    ``alpha`` [Hz] cyclic frequencies (spacing f_s / block length), ``frequency`` [Hz] the
    spectral frequencies kept (every one at least ``alpha[-1]`` + 2 Delta f, so that each
    cyclic frequency is read through the same ones), ``coherence`` the mean over blocks
    of |gamma_b(alpha, f)|^2 (shape (alpha, frequency)), ``null`` its expectation for
    stationary noise at each alpha (:func:`coherence_null`), ``blocks`` averaged,
    ``window_length`` N_w and ``hop`` R [samples], ``block_frames`` per block.
    """

    alpha: np.ndarray
    frequency: np.ndarray
    coherence: np.ndarray
    null: np.ndarray
    blocks: int
    window_length: int
    hop: int
    block_frames: int


def hann(n: int) -> np.ndarray:
    """Periodic Hann window of ``n`` samples (the Welch and STFT window here)."""
    return 0.5 - 0.5 * np.cos(2.0 * np.pi * np.arange(n) / n)


def stft(x: np.ndarray, window_length: int, hop: int) -> np.ndarray:
    """X(i, k) = sum_m x(i R + m) w(m) exp(-j 2 pi k m / N_w), k = 0 .. N_w / 2: the frames
    that fit whole, the phase referred to each frame's start ([Antoni2017] eq. 12)."""
    frames = np.lib.stride_tricks.sliding_window_view(x, window_length)[::hop]
    return np.fft.rfft(frames * hann(window_length), axis=1)


def window_kernel(beta, window_length: int) -> np.ndarray:
    """R_w(beta) = sum_n w(n)^2 exp(-j 2 pi (n - N_0) beta), beta in cycles per sample, for
    the periodic Hann window (real: w^2 is symmetric about N_0 = N_w / 2)
    ([Antoni2017] eq. 14)."""
    beta = np.asarray(beta, dtype=float)
    n = np.arange(window_length) - window_length / 2.0
    w2 = hann(window_length) ** 2
    return np.cos(2.0 * np.pi * beta[..., None] * n) @ w2


def _check(window_length, hop, n):
    if (
        isinstance(window_length, bool)
        or not isinstance(window_length, (int, np.integer))
        or not 16 <= window_length <= n
        or window_length & (window_length - 1)
    ):
        raise InputError(
            "window_length", window_length, f"a power of two from 16 to the {n} samples"
        )
    if not (
        isinstance(hop, (int, np.integer))
        and 1 <= hop <= window_length // 4
        and window_length % hop == 0
    ):
        raise InputError(
            "hop", hop, f"a divisor of N_w = {window_length} from 1 to {window_length // 4}"
        )


def _shifts(alpha_bins: np.ndarray, ratio: float, p_max: int):
    """For each cyclic frequency (in bins of the cyclic grid), the shifts p that contribute
    (|alpha - p Delta f| < SHIFT_REACH Delta f, 0 <= p <= p_max), as a (alpha, 5) array of
    p with a mask, and their offsets eps = alpha - p Delta f in bins of the cyclic grid."""
    base = np.floor(alpha_bins / ratio).astype(int)
    p = base[:, None] + np.arange(-2, 3)[None, :]
    eps = alpha_bins[:, None] - p * ratio
    ok = (np.abs(eps) < SHIFT_REACH * ratio - 1e-9) & (p >= 0) & (p <= p_max)
    return p, eps, ok


def _weights(n_alpha, ratio, nw, p_max, taper_sum):
    """(shift of each (alpha, slot), mask, complex weight): the phase correction
    exp(-j 2 pi eps N_0) and R_w(0) / sum_p R_w(eps_p) / sum_i h_i ([Antoni2017] eq. 16)."""
    p_of, eps_of, ok = _shifts(np.arange(n_alpha, dtype=float), ratio, p_max)
    eps_c = eps_of / (ratio * nw)  # cycles per sample
    kernel = np.where(ok, window_kernel(eps_c, nw), 0.0)
    scale = window_kernel(np.zeros(1), nw)[0] / kernel.sum(axis=1) / taper_sum
    weight = np.where(ok, np.exp(-1j * np.pi * eps_c * nw), 0.0) * scale[:, None]
    return p_of, ok, weight


def _complex_products(X, h, ratio, n_alpha, k_lo, p_max, weights=None):
    """Per block of frames (``X``: blocks x bins x frames, ``h`` the taper over the
    frames, ``ratio`` = Delta f in cyclic bins): the fast spectral correlation
    sum_p [sum_i h_i X(i, k) X(i, k - p)^* e^{-j 2 pi alpha i R}] e^{-j 2 pi eps_p N_0}
    R_w(0) / sum_p R_w(eps_p) / sum_i h_i at the bins k >= k_lo and alpha = 0 ..
    n_alpha - 1 cyclic bins (blocks x bins x alpha). ``weights``: :func:`_weights`'
    result, when already computed."""
    blocks, bins, frames = X.shape
    p_of, ok, weight = weights or _weights(n_alpha, ratio, 2 * (bins - 1), p_max, h.sum())
    acc = np.zeros((blocks, bins - k_lo, n_alpha), dtype=complex)
    high = X[:, k_lo:, :] * h
    for p in range(p_max + 1):
        rows, cols = np.nonzero(ok & (p_of == p))
        if rows.size == 0:
            continue
        spectrum = np.fft.fft(high * np.conj(X[:, k_lo - p : bins - p, :]), axis=-1)
        # cyclic bin a is the transform's bin a mod frames: the product of shift p holds
        # the cyclic frequencies within +-4 Delta f of p Delta f only (the frame rate is
        # 8 Delta f), so no two of them fold together; the rows of one shift are
        # consecutive
        lo, hi = int(rows[0]), int(rows[-1]) + 1
        part = np.take(spectrum, np.arange(lo, hi) % frames, axis=-1)
        acc[:, :, lo:hi] += part * weight[rows, cols]
    return acc


def fast_spectral_correlation(
    x, sample_rate, window_length: int, alpha_max: float, hop: int | None = None
) -> CyclicCorrelation:
    """Fast spectral correlation of ``x`` over the whole record ([Antoni2017] eq. 16).

    Parameters
    ----------
    x : array_like
        Samples (1-D), any unit; the mean is removed.
    sample_rate : float
        Sample rate [Hz].
    window_length : int
        STFT window N_w [samples], a power of two; Delta f = f_s / N_w.
    alpha_max : float
        Largest cyclic frequency [Hz], below f_s / 2 - 2 Delta f.
    hop : int, optional
        STFT hop R [samples]; default N_w / HOP_FRACTION.

    Returns
    -------
    CyclicCorrelation
        S_x(alpha, f_k) at alpha = 0, f_s / (K' R), ... (K' the frames, rounded up to a
        multiple of N_w / R so that Delta f is a whole number of cyclic bins), for the
        spectral bins f_k >= alpha_max + 2 Delta f (the
        others are NaN); ``power`` is S_x(0, f_k). Both in x's unit squared, as averages
        of |X(i, k)|^2 (divide by f_s sum w^2 for a density).

    Examples
    --------
    White noise amplitude-modulated at alpha_0 with depth m: its coherence at alpha_0 is
    m / (1 + m^2 / 2) at every spectral frequency (0.44 for m = 0.5); alpha_0 is put on
    the cyclic grid (2^16 samples: 4089 frames of hop 16, transformed at 4096).

    >>> fs = 12000.0
    >>> t = np.arange(2**16) / fs
    >>> a0 = 585 * fs / 2**16                                  # 107.1 Hz
    >>> noise = np.random.default_rng(0).standard_normal(t.size)
    >>> x = (1 + 0.5 * np.cos(2 * np.pi * a0 * t)) * noise
    >>> c = fast_spectral_correlation(x, fs, 128, 300.0)
    >>> k = c.frequency > 1000
    >>> gamma = np.abs(c.correlation[585, k]) / c.power[k]
    >>> round(float(c.alpha[585]), 2), bool(0.40 < np.median(gamma) < 0.49)
    (107.12, True)
    """
    x = samples(x)
    fs = rate(sample_rate)
    nw = window_length
    hop = nw // HOP_FRACTION if hop is None else hop
    _check(nw, hop, x.size)
    X = stft(x - x.mean(), nw, hop)
    frames, bins = X.shape
    df = fs / nw
    try:
        amax = float(alpha_max)
    except (TypeError, ValueError):
        amax = math.nan
    if not 0.0 <= amax < fs / 2 - 2 * df:
        raise InputError("alpha_max", alpha_max, f"a frequency in [0, {fs / 2 - 2 * df:g}) Hz")
    # cyclic grid: the transform over the frames, made a multiple of N_w / R long so that
    # Delta f is a whole number of cyclic bins
    m = nw // hop
    length = int(math.ceil(frames / m)) * m
    ratio = length / m  # cyclic bins per Delta f
    d_alpha = fs / (length * hop)
    n_alpha = int(math.floor(amax / d_alpha)) + 1
    k_lo = min(int(math.ceil((amax + SHIFT_REACH * df) / df)), bins - 1)
    p_max = int(math.ceil(amax / df + SHIFT_REACH))
    padded = np.zeros((1, bins, length), dtype=complex)
    padded[0, :, :frames] = X.T
    h = np.zeros(length)
    h[:frames] = 1.0
    # one "block": the whole record, rectangular taper; keep the complex values
    out = np.full((n_alpha, bins), np.nan + 0j)
    out[:, k_lo:] = _complex_products(padded, h, ratio, n_alpha, k_lo, p_max)[0].T
    power = np.mean(np.abs(X) ** 2, axis=0)
    return CyclicCorrelation(np.arange(n_alpha) * d_alpha, np.arange(bins) * df, out, power)


def coherence_null(
    n_alpha: int, ratio: float, window_length: int, hop: int, taper: np.ndarray
) -> np.ndarray:
    """E|gamma_b(alpha, f)|^2 of one block for stationary white noise, at the cyclic bins
    0 .. n_alpha - 1 (``ratio`` = Delta f in cyclic bins, ``taper`` h over the block's
    frames) [-].

    The estimate is a sum over shifts p and frames i of products X(i, k) X(i, k - p)^*;
    for circular Gaussian X its second moment follows from Isserlis' theorem,
    E{X_1 X_2^* X_3^* X_4} = E{X_1 X_3^*} E{X_2^* X_4} (+ the product of the means, which
    only reaches alpha within the taper's main lobe of 0), with the white-noise moments
    E{X(i, k) X(i + l, k + d)^*} = sigma^2 e^{-j 2 pi (k + d) l R / N_w} G(l, d),
    G(l, d) = sum_m w(m) w(m - l R) e^{j 2 pi d m / N_w}:

    E|gamma_b|^2 = (R_w(0) / sum_p R_w(eps_p))^2 / ((sum_i h_i)^2 (sum_m w_m^2)^2)
                   x sum_{p, p'} e^{-j 2 pi (eps_p - eps_p') N_0}
                     sum_l (sum_i h_i h_{i+l}) e^{j 2 pi eps_p' l R} G(l, 0) G(l, p - p')^*

    (eps_p = alpha - p Delta f in cycles per sample). It is not flat in alpha: where
    alpha is a multiple of Delta f three shifts read it, elsewhere four, and the products'
    correlation over overlapping frames weighs each differently (+-3 % for N_w / R = 8).
    Dividing by it makes every cyclic frequency's reading of noise alike.
    """
    nw, R = window_length, hop
    h = np.asarray(taper, dtype=float)
    w = hann(nw)
    lags = np.arange(-(nw // R) + 1, nw // R)
    hh = np.array(
        [
            np.sum(h[max(0, -lag) : h.size - max(0, lag)] * h[max(0, lag) : h.size - max(0, -lag)])
            for lag in lags
        ]
    )
    m = np.arange(nw)
    shifted = np.zeros((lags.size, nw))
    for j, lag in enumerate(lags):
        s = lag * R
        if s >= 0:
            shifted[j, s:] = w[s:] * w[: nw - s]
        else:
            shifted[j, : nw + s] = w[: nw + s] * w[-s:]
    d = np.arange(-4, 5)
    G = shifted @ np.exp(2j * np.pi * np.outer(m, d) / nw)  # lags x d
    p_of, eps_of, ok = _shifts(np.arange(n_alpha, dtype=float), ratio, np.iinfo(int).max)
    eps_c = np.where(ok, eps_of / (ratio * nw), 0.0)
    kernel = np.where(ok, window_kernel(eps_c, nw), 0.0)
    gain = (window_kernel(np.zeros(1), nw)[0] / kernel.sum(axis=1)) ** 2
    diff = p_of[:, :, None] - p_of[:, None, :]  # p - p'
    g0 = G[:, 4]  # G(l, 0)
    gd = np.conj(np.moveaxis(G[:, np.clip(diff, -4, 4) + 4], 0, -1))  # alpha x p x p' x lags
    phase_l = np.exp(2j * np.pi * eps_c[:, None, :, None] * lags * R)  # eps_p' l R
    inner = np.sum(hh * g0 * phase_l * gd, axis=-1)
    centre = np.exp(-1j * np.pi * (eps_c[:, :, None] - eps_c[:, None, :]) * nw)
    pair = ok[:, :, None] & ok[:, None, :]
    total = np.real(np.sum(np.where(pair, centre * inner, 0.0), axis=(1, 2)))
    return total * gain / (h.sum() ** 2 * np.sum(w**2) ** 2)


def spectral_coherence(
    x,
    sample_rate,
    window_length: int,
    alpha_max: float,
    block_length: int,
    hop: int | None = None,
) -> SpectralCoherence:
    """Squared spectral coherence of ``x``, Welch-averaged over blocks (module docstring).

    Parameters
    ----------
    x : array_like
        Samples (1-D), any unit; the mean is removed.
    sample_rate : float
        Sample rate [Hz].
    window_length : int
        STFT window N_w [samples], a power of two; Delta f = f_s / N_w.
    alpha_max : float
        Largest cyclic frequency [Hz].
    block_length : int
        Samples per block (a multiple of the hop): the cyclic resolution is
        f_s / block_length; blocks overlap by half and are Hann-tapered over their frames.
        A record shorter than one block is read as one block, its frames zero-padded.
    hop : int, optional
        STFT hop R [samples]; default N_w / HOP_FRACTION.

    Returns
    -------
    SpectralCoherence

    Examples
    --------
    >>> fs = 12000.0
    >>> t = np.arange(2**17) / fs
    >>> noise = np.random.default_rng(0).standard_normal(t.size)
    >>> x = (1 + 0.5 * np.cos(2 * np.pi * 107.0 * t)) * noise
    >>> c = spectral_coherence(x, fs, 256, 300.0, 8192)
    >>> a = int(np.argmax(c.coherence[10:].mean(axis=1))) + 10
    >>> round(float(c.alpha[a])), bool(0.40 < np.sqrt(np.mean(c.coherence[a] - c.null[a])) < 0.49)
    (107, True)
    """
    x = samples(x)
    fs = rate(sample_rate)
    nw = window_length
    hop = nw // HOP_FRACTION if hop is None else hop
    _check(nw, hop, x.size)
    if (
        isinstance(block_length, bool)
        or not isinstance(block_length, (int, np.integer))
        or block_length < nw
        or block_length % hop
    ):
        raise InputError(
            "block_length", block_length, f"a multiple of the hop {hop} of at least {nw} samples"
        )
    df = fs / nw
    try:
        amax = float(alpha_max)
    except (TypeError, ValueError):
        amax = math.nan
    if not 0.0 <= amax < fs / 2 - 3 * df:
        raise InputError("alpha_max", alpha_max, f"a frequency in [0, {fs / 2 - 3 * df:g}) Hz")
    X = stft(x - x.mean(), nw, hop)
    count, bins = X.shape
    per_block = block_length // hop
    if count >= per_block:
        h = hann(per_block)
        step = per_block // 2
        blocks = 1 + (count - per_block) // step
        # blocks x bins x frames
        view = np.lib.stride_tricks.sliding_window_view(X, per_block, axis=0)[::step][:blocks]
    else:
        h = np.zeros(per_block)
        h[:count] = hann(count)
        view = np.zeros((1, bins, per_block), dtype=complex)
        view[0, :, :count] = X.T
        blocks = 1
    ratio = block_length / nw  # cyclic bins per Delta f
    d_alpha = fs / block_length
    n_alpha = int(math.floor(amax / d_alpha)) + 1
    k_lo = int(math.ceil(amax / df + SHIFT_REACH))
    p_max = int(math.ceil(amax / df + SHIFT_REACH))
    total = np.zeros((bins - k_lo, n_alpha))
    weights = _weights(n_alpha, ratio, nw, p_max, h.sum())
    for start in range(0, blocks, CHUNK_BLOCKS):
        chunk = view[start : start + CHUNK_BLOCKS]
        acc = _complex_products(chunk, h, ratio, n_alpha, k_lo, p_max, weights)
        total += np.sum(acc.real**2 + acc.imag**2, axis=0)
    power = np.mean(X.real**2 + X.imag**2, axis=0)
    k = np.arange(k_lo, bins)
    # S(0, f - alpha), interpolated between the bins
    other = np.interp(k[None, :] - np.arange(n_alpha)[:, None] / ratio, np.arange(bins), power)
    floor = 1e-300 + 1e-30 * float(power.max())
    coherence = total.T / blocks / np.maximum(power[k][None, :] * other, floor)
    null = coherence_null(n_alpha, ratio, nw, hop, h)
    return SpectralCoherence(
        np.arange(n_alpha) * d_alpha, k * df, coherence, null, blocks, nw, hop, per_block
    )


def improved_envelope_spectrum(coherence: SpectralCoherence, band=None):
    """(alpha [Hz], IES / its noise expectation [-]): the squared spectral coherence
    averaged over the spectral frequencies of ``band`` (low, high) [Hz] (None: all those
    kept), divided by its expectation for stationary noise ([Mauricio2020] eq. 3, with
    |gamma|^2 for |gamma|; :func:`coherence_null`). Stationary noise reads about 1 at every
    cyclic frequency; a cyclostationary component adds its squared coherence over the
    noise level.
    """
    f = coherence.frequency
    if band is None:
        keep = np.ones(f.size, bool)
    else:
        low, high = (float(v) for v in band)
        keep = (f >= low) & (f <= high)
        if np.count_nonzero(keep) < MIN_CARRIERS:
            raise InputError(
                "band",
                band,
                f"a band holding at least {MIN_CARRIERS} spectral bins (of {f[1] - f[0]:.4g} "
                f"Hz) between {f[0]:.5g} and {f[-1]:.5g} Hz",
                hint="the spectral frequencies below the highest cyclic frequency + 2 Delta f "
                "are not used, so that every cyclic frequency is read through the same ones",
            )
    ies = np.mean(coherence.coherence[:, keep], axis=1)
    return coherence.alpha, ies / coherence.null
