"""Pre-processing before envelope analysis: cepstral pre-whitening and the separation of
discrete (deterministic) from random components.

Layer 1 functions on 1-D sample arrays (any unit) sampled at ``sample_rate`` [Hz]. They are
two of the three pre-processing routes of the benchmark study of the Case Western Reserve
University data, Smith W. A., Randall R. B., "Rolling element bearing diagnostics using the
Case Western Reserve University data: a benchmark study", MSSP 64-65 (2015) 100-131 (its
Methods 2 and 3; Method 1 is the envelope of the raw signal).

Sources:
- cepstral pre-whitening (CPW): setting the real cepstrum to zero everywhere except at
  zero quefrency leaves the phase and a flat (white) amplitude spectrum,
  x_w = IFFT(X / |X|); discrete components and the resonances both lose their weight and
  the impulses of a bearing fault stand out. Sawalhi N., Randall R. B., "Signal
  pre-whitening using cepstrum editing (liftering) to enhance fault detection in rolling
  element bearings", Proc. COMADEM 2011; Borghesani P., Pennacchi P., Randall R. B.,
  Sawalhi N., Ricci R., "Application of cepstrum pre-whitening for the diagnosis of
  bearing faults under variable speed conditions", MSSP 36 (2013) 370-384, eq. 3;
- discrete/random separation (DRS): the deterministic part of x is what x(t) shares with
  x(t - D) when the delay D exceeds the correlation length of the random part. Its
  frequency response H(f) = S_{x x_D}(f) / S_{x x}(f), Welch-averaged over segments, is
  ~1 (in magnitude) at discrete frequencies and ~0 elsewhere; the random part is
  x - IFFT(|H| X). Antoni J., Randall R. B., "Unsupervised noise cancellation for
  vibration signals: part II - a novel frequency-domain algorithm", MSSP 18 (2004)
  103-117, sec. 3 (here: zero-phase |H| applied by an STFT / inverse STFT with the same
  segments).
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .spectra import fast_length, rate, samples

#: Resolution of the DRS filter [Hz]: segments of about 1 s separate discrete lines 1 Hz
#: apart (shaft harmonics and supply lines); capped by the record length (``drs_segment``).
DRS_RESOLUTION_HZ = 1.0
#: Fewest segment pairs a DRS filter is averaged over: with K pairs the gain of a random
#: bin scatters about 1/sqrt(K) (Antoni & Randall 2004, sec. 4).
DRS_MIN_AVERAGES = 8


def cepstral_prewhitening(x) -> np.ndarray:
    """Cepstrum pre-whitened copy of ``x``: IFFT(X / |X|) (Borghesani et al. 2013, eq. 3).

    The FFT is taken at a fast length at least as long as ``x`` (zero-padded) and the
    result cut back to ``len(x)``; bins with no energy stay zero.

    Parameters
    ----------
    x : array_like
        Samples (1-D, >= 16), any unit.

    Returns
    -------
    numpy.ndarray
        The whitened signal, same length; its amplitude spectrum is flat (unit-free).

    Examples
    --------
    >>> t = np.arange(4096) / 4096.0
    >>> w = cepstral_prewhitening(np.sin(2 * np.pi * 50 * t) + 0.01 * np.sin(2 * np.pi * 900 * t))
    >>> s = np.abs(np.fft.rfft(w))
    >>> bool(abs(s[50] / s[900] - 1.0) < 1e-6)   # both tones now weigh the same
    True
    """
    return prewhitened(samples(x))[0]


def prewhitened(x: np.ndarray, spectrum=None) -> tuple[np.ndarray, np.ndarray | None]:
    """(:func:`cepstral_prewhitening` of the samples ``x``, its real spectrum X / |X| when
    the transform's length is the record's own - a fast length - else None): the
    spectrum of the whitened record, for an envelope that needs it not to transform the
    record again (:func:`bearinglab.signal.spectra.analytic_power`).

    Parameters
    ----------
    x : numpy.ndarray
        Samples (1-D, float, checked).
    spectrum : numpy.ndarray, optional
        ``numpy.fft.rfft(x - x.mean())`` when already at hand and the record's length is
        a fast one (not changed).
    """
    n = x.size
    nfft = fast_length(n)
    if spectrum is None or nfft != n or len(spectrum) != n // 2 + 1:
        spectrum = np.fft.rfft(x - x.mean(), n=nfft)
    magnitude = np.abs(spectrum)
    live = magnitude > 1e-12 * max(float(magnitude.max()), 1e-300)
    whitened = np.divide(spectrum, magnitude, out=np.zeros_like(spectrum), where=live)
    return np.fft.irfft(whitened, n=nfft)[:n], (whitened if nfft == n else None)


def drs_segment(n: int, sample_rate: float) -> int:
    """DRS segment length [samples]: a power of two giving about DRS_RESOLUTION_HZ, but
    short enough for DRS_MIN_AVERAGES half-overlapping segment pairs in ``n`` samples."""
    target = 2 ** int(np.ceil(np.log2(max(sample_rate / DRS_RESOLUTION_HZ, 16))))
    # K half-overlapping segment pairs, each two segments long, need (K/2 + 2) N samples
    fit = 2 ** int(np.floor(np.log2(max(n / (DRS_MIN_AVERAGES / 2 + 2), 16))))
    return int(max(16, min(target, fit)))


def discrete_random_separation(
    x, sample_rate, segment_length: int | None = None, delay: int | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Split ``x`` into its random and discrete (deterministic) parts (Antoni & Randall
    2004, the frequency-domain DRS).

    Parameters
    ----------
    x : array_like
        Samples (1-D), any unit; at least 4 segments long.
    sample_rate : float
        Sample rate [Hz].
    segment_length : int, optional
        Samples per segment N (its resolution f_s/N must separate the discrete lines);
        default :func:`drs_segment`.
    delay : int, optional
        Delay D [samples] between the two copies of x, longer than the correlation length
        of the random part; default N. With D < N the two windowed segments share
        samples, and even white noise is then correlated between them (the cross-spectrum
        of the shared samples is sigma^2 sum w(t) w(t + D)): D >= N keeps the random part
        out of H.

    Returns
    -------
    (random, discrete) : tuple of numpy.ndarray
        Same length and unit as ``x``; random + discrete = x - mean(x).

    Examples
    --------
    A 50 Hz tone in white noise: the discrete part keeps the tone, the random part the
    noise.

    >>> rng = np.random.default_rng(0)
    >>> t = np.arange(2**16) / 4096.0
    >>> tone = np.sin(2 * np.pi * 50.0 * t)
    >>> r, d = discrete_random_separation(tone + 0.5 * rng.standard_normal(t.size), 4096.0)
    >>> bool(np.std(d - tone) < 0.2), bool(abs(np.std(r) - 0.5) < 0.1)
    (True, True)
    """
    import scipy.signal  # imported here: it costs ~0.5 s at start-up

    x = samples(x)
    fs = rate(sample_rate)
    n = x.size
    nseg = drs_segment(n, fs) if segment_length is None else segment_length
    if (
        isinstance(nseg, bool)
        or not isinstance(nseg, (int, np.integer))
        or not 16 <= nseg <= n // 4
    ):
        raise InputError(
            "segment_length", segment_length, f"an integer number of samples in [16, {n // 4}]"
        )
    nseg = int(nseg)
    lag = nseg if delay is None else delay
    if (
        isinstance(lag, bool)
        or not isinstance(lag, (int, np.integer))
        or not 1 <= lag <= n - 2 * nseg
    ):
        raise InputError("delay", delay, f"an integer number of samples in [1, {n - 2 * nseg}]")
    lag = int(lag)
    y = x - x.mean()
    window = scipy.signal.get_window("hann", nseg)
    hop = nseg // 2
    starts = np.arange(0, n - nseg - lag + 1, hop)
    # Welch averages of the cross-spectrum of x(t) and x(t - D) and of the auto-spectra
    index = starts[:, None] + np.arange(nseg)[None, :]
    now = np.fft.rfft(y[index + lag] * window, axis=1)
    before = np.fft.rfft(y[index] * window, axis=1)
    cross = np.mean(now * np.conj(before), axis=0)
    auto = 0.5 * (np.mean(np.abs(now) ** 2, axis=0) + np.mean(np.abs(before) ** 2, axis=0))
    gain = np.zeros(auto.shape)
    live = auto > 0
    gain[live] = np.minimum(np.abs(cross[live]) / auto[live], 1.0)
    # zero-phase filtering by the gain, segment by segment (Hann at 50 %: overlap-add)
    _, _, z = scipy.signal.stft(
        y, window="hann", nperseg=nseg, noverlap=nseg - hop, boundary="even", padded=True
    )
    _, discrete = scipy.signal.istft(
        z * gain[:, None], window="hann", nperseg=nseg, noverlap=nseg - hop, boundary=True
    )
    discrete = discrete[:n]
    return y - discrete, discrete
