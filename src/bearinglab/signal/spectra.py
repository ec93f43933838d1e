"""Amplitude spectra, envelope analysis and the choice of a demodulation band.

Layer 1 functions on 1-D sample arrays (any unit, e.g. m/s^2) sampled at ``sample_rate``
[Hz]; frequencies in Hz. The numerical work is SciPy's (``butter``/``sosfiltfilt``,
``stft``, windows other than Hann) and numpy.fft's (the Hann Welch average and the
analytic signal, written out here as ``scipy.signal.welch`` and ``hilbert`` compute them,
so that the command line imports neither scipy.signal nor scipy.fft); this module chooses
the scaling and the parameters.

Sources:
- envelope analysis (band-pass round a structural resonance excited by the defect
  impacts, demodulate with the Hilbert transform, take the spectrum of the envelope):
  Randall R. B., Antoni J., "Rolling element bearing diagnostics - A tutorial",
  Mechanical Systems and Signal Processing 25(2) (2011) 485-520, sections 3.1-3.3;
- spectral kurtosis SK(f) = <|X(t, f)|^4> / <|X(t, f)|^2>^2 - 2 of the short-time Fourier
  transform, and the kurtogram (SK over centre frequency and bandwidth) to choose that
  band: Antoni J., "The spectral kurtosis: a useful tool for characterising
  non-stationary signals", MSSP 20(2) (2006) 282-307; Antoni J., Randall R. B., "The
  spectral kurtosis: application to the vibratory surveillance and diagnostics of rotating
  machines", MSSP 20(2) (2006) 308-331; Antoni J., "Fast computation of the kurtogram for
  the detection of transient faults", MSSP 21(1) (2007) 108-124 (here: the STFT-based
  kurtogram of its section 2, on a grid of window lengths);
- amplitude scaling of the periodogram/Welch estimate: SciPy ``welch(scaling="spectrum")``
  gives the power P of each line, so a sinusoid of amplitude A reads sqrt(2 P) = A on
  its bin (Heinzel G., Ruediger A., Schilling R., "Spectrum and spectral density
  estimation by the DFT", Max-Planck-Institut report, 2002, sec. 9).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from .record import MIN_SAMPLES


class Spectrum(NamedTuple):
    """Single-sided amplitude spectrum.

    ``frequency`` [Hz]; ``amplitude`` in the unit of the samples (a sinusoid of amplitude
    A reads A on its bin).
    """

    frequency: np.ndarray
    amplitude: np.ndarray

    @property
    def resolution(self) -> float:
        """Bin spacing [Hz]."""
        return float(self.frequency[1] - self.frequency[0])


class EnvelopeSpectrum(NamedTuple):
    """Amplitude spectrum of the envelope and the demodulation ``band`` (low, high) [Hz]
    used (None: no band-pass)."""

    frequency: np.ndarray
    amplitude: np.ndarray
    band: tuple[float, float] | None

    @property
    def resolution(self) -> float:
        """Bin spacing [Hz]."""
        return float(self.frequency[1] - self.frequency[0])


class KurtogramBand(NamedTuple):
    """Band of largest spectral kurtosis: ``band`` (low, high), ``centre`` and
    ``bandwidth`` [Hz], the ``kurtosis`` there [-] and the STFT ``window_length``
    [samples] that found it."""

    band: tuple[float, float]
    centre: float
    bandwidth: float
    kurtosis: float
    window_length: int


# ---------------------------------------------------------------- validation


def samples(x, name: str = "x") -> np.ndarray:
    """``x`` as a 1-D finite float array of at least 16 samples, else InputError."""
    try:
        a = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        raise InputError(name, type(x).__name__, "a 1-D array of numbers") from None
    if a.ndim != 1 or a.size < MIN_SAMPLES:
        raise InputError(
            name, f"array of shape {a.shape}", f"a 1-D array of at least {MIN_SAMPLES} samples"
        )
    if not np.all(np.isfinite(a)):
        raise InputError(name, "an array with NaN or inf", "finite samples")
    return a


def rate(sample_rate, name: str = "sample_rate") -> float:
    """``sample_rate`` as a finite float > 0 [Hz], else InputError."""
    try:
        fs = float(sample_rate)
    except (TypeError, ValueError):
        raise InputError(name, sample_rate, "a number > 0 Hz") from None
    if not math.isfinite(fs) or fs <= 0:
        raise InputError(name, sample_rate, "a finite number > 0 Hz")
    return fs


def band_limits(band, sample_rate: float) -> tuple[float, float]:
    """``band`` as (low, high) with 0 < low < high < Nyquist [Hz], else InputError.

    >>> band_limits((2000, 4000), 12000.0)
    (2000.0, 4000.0)
    """
    nyquist = sample_rate / 2.0
    allowed = f"(low, high) in Hz with 0 < low < high < {nyquist:g} (Nyquist)"
    try:
        low, high = (float(v) for v in band)
    except (TypeError, ValueError):
        raise InputError("band", band, allowed) from None
    if not (0.0 < low < high < nyquist):
        raise InputError("band", band, allowed)
    return low, high


def _integer_in(value, low: int, high: int) -> bool:
    """Whether ``value`` is an integer (not a bool) in [low, high]."""
    return (
        not isinstance(value, bool)
        and isinstance(value, (int, np.integer))
        and low <= value <= high
    )


def segment(segment_length, n: int, default: int | None = None) -> int:
    """Samples per segment: ``default`` (or ``n``) when None, else an int in [16, n]."""
    if segment_length is None:
        return n if default is None else default
    if not _integer_in(segment_length, MIN_SAMPLES, n):
        raise InputError(
            "segment_length",
            segment_length,
            f"an integer number of samples in [{MIN_SAMPLES}, {n}]",
        )
    return int(segment_length)


def overlapping(overlap, nperseg: int) -> int:
    """Samples shared by consecutive segments for an ``overlap`` fraction in [0, 1)."""
    try:
        o = float(overlap)
    except (TypeError, ValueError):
        raise InputError("overlap", overlap, "a fraction in [0, 1)") from None
    if not 0.0 <= o < 1.0:
        raise InputError("overlap", overlap, "a fraction in [0, 1)")
    return min(round(o * nperseg), nperseg - 1)


def check_window(window, nperseg: int):
    """``window`` if ``scipy.signal.get_window`` understands it, else InputError."""
    import scipy.signal  # imported here: it costs ~0.5 s at start-up

    try:
        scipy.signal.get_window(window, nperseg)
    except (TypeError, ValueError) as exc:
        raise InputError(
            "window", window, "a window scipy.signal.get_window knows", hint=str(exc)
        ) from None
    return window


# ---------------------------------------------------------------- spectra


def amplitude_spectrum(x, sample_rate, window="hann", segment_length=None, overlap=0.5) -> Spectrum:
    """Single-sided amplitude spectrum, averaged over segments (Welch).

    ``scipy.signal.welch(..., scaling="spectrum")`` gives the power P_k of each line
    (doubled for the negative frequencies, except at 0 and Nyquist); the amplitude is
    sqrt(2 P_k) (sqrt(P_k) at 0 and Nyquist), so a sinusoid of amplitude A on a bin
    reads A. The mean of each segment is removed. A Hann window reads a tone half-way
    between bins up to 15 % low (scalloping); use ``window="flattop"`` to read the
    amplitude of tones off the bins (within ~0.1 %), at the price of wider peaks.

    Parameters
    ----------
    x : array_like
        Samples (1-D, >= 16), any unit.
    sample_rate : float
        Sample rate [Hz].
    window : str or tuple
        Any window ``scipy.signal.get_window`` accepts.
    segment_length : int, optional
        Samples per segment; None (default) uses the whole record as one segment
        (resolution f_s/n). Shorter segments trade resolution for averaging.
    overlap : float
        Fraction of a segment shared with the next one, in [0, 1).

    Returns
    -------
    Spectrum
        ``frequency`` [Hz] from 0 to f_s/2 in steps of f_s/segment_length, and
        ``amplitude`` in the unit of ``x``.

    Examples
    --------
    >>> t = np.arange(1000) / 1000.0
    >>> s = amplitude_spectrum(2.5 * np.sin(2 * np.pi * 50.0 * t), 1000.0)
    >>> float(s.frequency[np.argmax(s.amplitude)]), round(float(s.amplitude.max()), 6)
    (50.0, 2.5)
    """
    x = samples(x)
    fs = rate(sample_rate)
    nperseg = segment(segment_length, x.size)
    noverlap = overlapping(overlap, nperseg)
    if isinstance(window, str) and window == "hann":  # without importing scipy.signal
        frequency, power = welch_power(x, fs, nperseg, noverlap)
    else:
        import scipy.signal  # imported here: it costs ~0.5 s at start-up

        check_window(window, nperseg)
        frequency, power = scipy.signal.welch(
            x,
            fs=fs,
            window=window,
            nperseg=nperseg,
            noverlap=noverlap,
            detrend="constant",
            scaling="spectrum",
        )
    amplitude = np.sqrt(2.0 * power)
    # welch doubles every line but DC and (even segments) Nyquist, which have no mirror
    amplitude[0] = math.sqrt(power[0])
    if nperseg % 2 == 0:
        amplitude[-1] = math.sqrt(power[-1])
    return Spectrum(frequency, amplitude)


def envelope(x, sample_rate, band=None, order: int = 4, squared: bool = False) -> np.ndarray:
    """Envelope of ``x``: band-pass, Hilbert-transform magnitude, mean removed.

    The band-pass is a Butterworth filter of ``order`` in second-order sections run
    forwards and backwards (``scipy.signal.sosfiltfilt``: zero phase, so the envelope is
    not delayed; effective order 2 x ``order``). The envelope is |x + j H[x]|
    (``scipy.signal.hilbert``) minus its mean, so its spectrum has no line at 0 Hz
    (Randall & Antoni 2011, sec. 3.1).

    Parameters
    ----------
    x : array_like
        Samples (1-D, >= 16), any unit.
    sample_rate : float
        Sample rate [Hz].
    band : (float, float), optional
        Pass band (low, high) [Hz], 0 < low < high < Nyquist; None: no filtering.
    order : int
        Butterworth order, 1 to 10.
    squared : bool
        Return the squared envelope |x + j H[x]|^2 (minus its mean), whose spectrum
        Randall & Antoni (2011, sec. 3.1) recommend for diagnosis; unit: the unit of
        ``x`` squared.

    Returns
    -------
    numpy.ndarray
        The envelope, same length and unit as ``x`` (squared unit if ``squared``).
    """
    x = samples(x)
    fs = rate(sample_rate)
    if not _integer_in(order, 1, 10):
        raise InputError("order", order, "an integer from 1 to 10")
    if band is not None:
        import scipy.signal  # imported here: it costs ~0.5 s at start-up

        low, high = band_limits(band, fs)
        sos = scipy.signal.butter(int(order), [low, high], btype="bandpass", fs=fs, output="sos")
        # SciPy's default pad (3 x the filter length) exceeds very short records
        padlen = min(3 * (2 * len(sos) + 1), x.size - 1)
        x = scipy.signal.sosfiltfilt(sos, x, padlen=padlen)
    power = analytic_power(x - x.mean())
    magnitude = power if squared else np.sqrt(power)
    return magnitude - magnitude.mean()


def _smooth_lengths(limit: int) -> list[int]:
    """Every 2^a 3^b 5^c <= ``limit`` (a few hundred up to a million)."""
    out, p5 = [], 1
    while p5 <= limit:
        p35 = p5
        while p35 <= limit:
            k = p35
            while k <= limit:
                out.append(k)
                k *= 2
            p35 *= 3
        p5 *= 5
    return out


def fast_length(n: int) -> int:
    """The smallest 2^a 3^b 5^c >= ``n``: the lengths that numpy's pocketfft transforms
    fastest (what ``scipy.fft.next_fast_len(n, real=True)`` returns; numpy.fft is used
    because importing scipy.fft costs ~0.2 s of a command's start-up).

    >>> fast_length(480_000), fast_length(480_001), fast_length(7)
    (480000, 486000, 8)
    """
    n = max(int(n), 1)
    return min(k for k in _smooth_lengths(2 * n) if k >= n)  # a power of two <= 2n is one


def fast_length_below(n: int) -> int:
    """The largest 2^a 3^b 5^c <= ``n`` (``scipy.fft.prev_fast_len(n, real=True)``).

    >>> fast_length_below(479_999), fast_length_below(7)
    (472392, 6)
    """
    return max(_smooth_lengths(max(int(n), 1)))


def analytic(x) -> np.ndarray:
    """Analytic signal x + j H[x] computed at a fast FFT length.

    As ``scipy.signal.hilbert`` computes it (Marple, "Computing the discrete-time analytic
    signal via FFT", IEEE Trans. Signal Process. 47 (1999) 2600-2603: the spectrum's
    negative frequencies zeroed, the positive ones doubled), written with ``numpy.fft``
    here so that the command line does not import scipy.signal (~0.5 s); a test checks
    the two agree. ``hilbert`` transforms at the record's own length, and an awkward
    length (a large prime factor: 480 001 samples) costs several times a nearby fast one;
    the record is zero-padded to :func:`fast_length` and the result cut back. The
    padding only changes the last few samples' envelope, as an end effect of the same size
    as the circular one it replaces. The forward transform is a real one (the negative
    frequencies it leaves out are those zeroed anyway): numpy's complex FFT of a real
    record costs three times its real FFT.
    """
    n = len(x)
    m = fast_length(n)
    half = np.fft.rfft(x, m)  # bins 0 .. m // 2
    spectrum = np.zeros(m, dtype=complex)
    spectrum[: half.size] = half
    spectrum[1 : (m + 1) // 2] *= 2.0  # the positive frequencies; 0 Hz and Nyquist stay
    return np.fft.ifft(spectrum)[:n]


def analytic_power(x, spectrum=None) -> np.ndarray:
    """Squared magnitude |x + j H[x]|^2 of the analytic signal (:func:`analytic`), as
    x^2 + H[x]^2 with the Hilbert transform H[x] from one real inverse FFT.

    The imaginary part of :func:`analytic`'s inverse transform is the real inverse
    transform of -j X (X the record's real spectrum at the same fast length, its 0 Hz and
    Nyquist bins zeroed: they are real and add nothing to it), and its real part is the
    record itself; numpy's complex inverse FFT costs three times the real one. Equal to
    ``abs(analytic(x)) ** 2`` to round-off (a test checks it).

    Parameters
    ----------
    x : array_like
        Samples (1-D), any unit.
    spectrum : numpy.ndarray, optional
        ``numpy.fft.rfft(x)`` already at hand, when the record's length is a fast one
        (:func:`fast_length`), or the spectrum of a record that differs from ``x`` only
        by a constant (its 0 Hz bin is not used); not changed.
    """
    x = np.asarray(x, dtype=float)
    n = x.size
    m = fast_length(n)
    if spectrum is not None and m == n and len(spectrum) == n // 2 + 1:
        half = np.asarray(spectrum, dtype=complex) * -1j  # a new array: the input kept
    else:
        half = np.fft.rfft(x, m)
        half *= -1j
    half[0] = 0.0
    if m % 2 == 0:
        half[-1] = 0.0
    hilbert = np.fft.irfft(half, m)[:n]
    return x * x + hilbert * hilbert


def welch_power(x, sample_rate: float, nperseg: int, noverlap: int):
    """(frequency [Hz], power [unit^2]) of ``x`` by Welch's method with a Hann window and
    each segment's mean removed, scaled so that a line's value is its power.

    This is ``scipy.signal.welch(x, fs, "hann", nperseg, noverlap, detrend="constant",
    scaling="spectrum")`` (Welch, IEEE Trans. Audio Electroacoust. 15 (1967) 70-73),
    written with ``numpy.fft`` so that the command line does not import scipy.signal
    (~0.5 s); a test checks the two agree.
    """
    x = np.asarray(x, dtype=float)
    step = nperseg - noverlap
    count = 1 + (x.size - nperseg) // step
    segments = np.lib.stride_tricks.sliding_window_view(x, nperseg)[::step][:count]
    window = 0.5 - 0.5 * np.cos(2.0 * np.pi * np.arange(nperseg) / nperseg)  # periodic Hann
    spectra = np.fft.rfft((segments - segments.mean(axis=1, keepdims=True)) * window, axis=1)
    power = np.mean(np.abs(spectra) ** 2, axis=0) / window.sum() ** 2
    power[1 : nperseg // 2 + (nperseg % 2)] *= 2.0  # one-sided: all but 0 Hz and Nyquist
    return np.fft.rfftfreq(nperseg, 1.0 / sample_rate), power


def envelope_spectrum(
    x, sample_rate, band=None, window="hann", segment_length=None, overlap=0.5, order: int = 4
) -> EnvelopeSpectrum:
    """Amplitude spectrum of the envelope of ``x`` (Randall & Antoni 2011, sec. 3).

    Parameters
    ----------
    x : array_like
        Samples (1-D, >= 16), any unit.
    sample_rate : float
        Sample rate [Hz].
    band : (float, float) or "auto" or None
        Demodulation band (low, high) [Hz]; ``"auto"`` chooses it by spectral kurtosis
        (:func:`spectral_kurtosis_band` with its defaults); None demodulates the whole
        band (no filter).
    window, segment_length, overlap :
        As in :func:`amplitude_spectrum`, applied to the envelope.
    order : int
        Butterworth order of the band-pass, as in :func:`envelope`.

    Returns
    -------
    EnvelopeSpectrum
        ``frequency`` [Hz], ``amplitude`` (unit of ``x``) and the ``band`` used.
    """
    x = samples(x)
    fs = rate(sample_rate)
    if isinstance(band, str):
        if band != "auto":
            raise InputError("band", band, '(low, high) in Hz, "auto" or None')
        band = spectral_kurtosis_band(x, fs).band
    elif band is not None:
        band = band_limits(band, fs)
    env = envelope(x, fs, band=band, order=order)
    spectrum = amplitude_spectrum(
        env, fs, window=window, segment_length=segment_length, overlap=overlap
    )
    return EnvelopeSpectrum(spectrum.frequency, spectrum.amplitude, band)


# ---------------------------------------------------------------- spectral kurtosis


def spectral_kurtosis(x, sample_rate, window_length: int) -> Spectrum:
    """Spectral kurtosis SK(f) of ``x``, sampled at ``sample_rate`` [Hz], from its STFT
    (Antoni 2006, eq. 8 estimator).

    SK(f) = <|X(t, f)|^4> / <|X(t, f)|^2>^2 - 2, the average over the STFT frames of a
    Hann window of ``window_length`` samples with 75 % overlap (``scipy.signal.stft``,
    no boundary padding so that no frame is part zeros). SK is ~0 for stationary
    Gaussian noise, -1 for a stationary sinusoid and large and positive where impacts
    excite a resonance. Returned as a :class:`Spectrum` whose ``amplitude`` is SK [-].

    Parameters
    ----------
    x : array_like
        The samples, 1-D, finite, at least 16 of them (any unit: SK is dimensionless).
    sample_rate : float
        Sample rate [Hz], finite and > 0.
    window_length : int
        Length of the Hann window [samples], a whole number in [8, len(x) // 4].
    """
    import scipy.signal  # imported here: it costs ~0.5 s at start-up

    x = samples(x)
    fs = rate(sample_rate)
    if not _integer_in(window_length, 8, x.size // 4):
        raise InputError(
            "window_length", window_length, f"an integer number of samples in [8, {x.size // 4}]"
        )
    n = int(window_length)
    frequency, _, z = scipy.signal.stft(
        x - x.mean(),
        fs=fs,
        window="hann",
        nperseg=n,
        noverlap=3 * n // 4,
        boundary=None,
        padded=False,
    )
    power = np.abs(z) ** 2
    mean_power = power.mean(axis=1)
    fourth = (power**2).mean(axis=1)
    # a bin with no energy at all has no defined kurtosis; rank it below any other
    sk = np.full(mean_power.shape, -2.0)
    live = mean_power > 0
    sk[live] = fourth[live] / mean_power[live] ** 2 - 2.0
    return Spectrum(frequency, sk)


def spectral_kurtosis_band(
    x, sample_rate, window_lengths=None, min_bandwidth: float = 0.0
) -> KurtogramBand:
    """Demodulation band of largest spectral kurtosis (an STFT kurtogram).

    For each window length N_w the STFT bin k (centre f_k = k f_s/N_w) stands for the
    band [f_k - f_s/N_w, f_k + f_s/N_w] (the -6 dB width of the Hann window, 2 bins);
    SK(f_k) is computed by :func:`spectral_kurtosis` and the (centre, bandwidth) pair of
    largest SK over all window lengths and bins wins (Antoni 2007, "Fast computation of
    the kurtogram ...", sec. 2: short windows find short, wide-band transients, long
    windows narrow resonances). Bins whose band would touch 0 Hz or Nyquist are left out.

    Parameters
    ----------
    x : array_like
        Samples (1-D, >= 64), any unit.
    sample_rate : float
        Sample rate [Hz].
    window_lengths : sequence of int, optional
        STFT window lengths [samples]; default the powers of two from 16 up to n/32 (at
        least ~120 frames each, so that the SK estimate of noise scatters by < ~0.2).
    min_bandwidth : float
        Narrowest band to consider [Hz] (e.g. 3 x the largest defect frequency, to keep
        its modulation sidebands in the band); window lengths giving narrower bands are
        skipped.

    Returns
    -------
    KurtogramBand
        ``band`` (low, high), ``centre``, ``bandwidth`` [Hz], ``kurtosis`` [-],
        ``window_length`` [samples].
    """
    x = samples(x)
    fs = rate(sample_rate)
    if x.size < 64:
        raise InputError("x", f"{x.size} samples", "at least 64 samples for a kurtogram")
    if window_lengths is None:
        lengths = [2**k for k in range(4, 16) if 2**k <= max(x.size // 32, 16)]
    else:
        lengths = list(window_lengths)
        if not lengths or not all(_integer_in(n, 8, x.size // 4) for n in lengths):
            raise InputError(
                "window_lengths",
                window_lengths,
                f"one or more integers in [8, {x.size // 4}] samples",
            )
    try:
        min_bw = float(min_bandwidth)
    except (TypeError, ValueError):
        raise InputError("min_bandwidth", min_bandwidth, "a number >= 0 Hz") from None
    if not 0.0 <= min_bw < fs / 2:
        raise InputError("min_bandwidth", min_bandwidth, f"a number in [0, {fs / 2:g}) Hz")
    best = None
    for n in (int(n) for n in lengths):
        bandwidth = 2.0 * fs / n
        if bandwidth < min_bw:
            continue
        sk = spectral_kurtosis(x, fs, n)
        inner = slice(2, n // 2 - 1)  # bins 2 .. N/2-2: the band stays inside (0, f_s/2)
        values = sk.amplitude[inner]
        k = int(np.argmax(values))
        if best is None or values[k] > best.kurtosis:
            centre = float(sk.frequency[inner][k])
            best = KurtogramBand(
                (centre - fs / n, centre + fs / n), centre, bandwidth, float(values[k]), n
            )
    if best is None:
        raise InputError(
            "min_bandwidth",
            min_bandwidth,
            f"at most {2.0 * fs / min(lengths):g} Hz for window lengths {lengths}",
            hint="no band left to search",
        )
    return best
