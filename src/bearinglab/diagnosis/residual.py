"""A second look once a first fault is accepted: its impacts removed, the rest read again.

A compound fault's second series can hide under the first: the README's ER-16K with an
outer-race and a ball defect shows BPFO's lines at z 80-140 in the squared envelope, and
the outer race's impacts, whose strength varies from one to the next, raise a floor of
their own over the whole envelope spectrum; 2 x BSF lies 2.1 Hz from BPFO + f_r, where the
first fault's intermodulation is masked. What the first fault explains is removed here,
and the other families are read again on what is left:

1. The first fault's rate is estimated from the signal: the fundamental its test fitted
   (:func:`.series.series_test`, a fraction of a Welch bin) is refined on the squared
   envelope of each method, from the harmonics of its whole-record spectrum and the
   synchronous average at that rate (:func:`fault_rate`).
2. Its impacts are removed from the squared envelope (:func:`without_impacts`): the
   synchronous average at that period is the shape of one impact, and each period's own
   impact is that shape scaled by least squares (time-synchronous averaging: McFadden
   P. D., "Examination of a technique for the early detection of failure in gears by
   signal processing of the time domain average of the meshing vibration", MSSP 1(2)
   (1987) 173-183; removing a deterministic part before envelope analysis: Randall R. B.,
   Antoni J., "Rolling element bearing diagnostics - A tutorial", MSSP 25(2) (2011)
   485-520, sec. 3.2). The scale per impact is what a simulation without slip needs: the
   ER-16K's outer-race impacts recur at BPFO to 1e-6 but vary by +-50 % in strength, and
   an inner race's impacts are modulated by the load zone at the shaft rate.
3. The remainder is read as the record was (same methods, Welch segments, masks of the
   machine's lines and test), but only if the first fault is gone from it: its own series
   no longer shows even at the gates' level, SUPPORT_ALPHA (1 %), by any method - below
   the threshold is not enough: a first fault just above it falls below it by little
   (CWRU 119's second half, a ball record read "outer race" at 10^-3.8 by the three
   methods, kept 10^-2.65 of it, and the remainder read an inner race). Where it is not
   gone - a real bearing's impacts drift with random slip (1-2 %, Randall & Antoni 2011
   sec. 2), which an average at a fixed period cannot follow at the higher harmonics -
   nothing changes. Where it is gone, the first
   fault's lines and intermodulation need no mask, and a family of the remainder that
   passes every gate of a second fault at the record's level (:func:`.verdict.decide`
   with the first fault ``prior``: at least MIN_HARMONICS harmonics at LINE_ALPHA) is
   called beside it.
"""

from __future__ import annotations

import math

import numpy as np

from .methods import MethodSpectrum
from .series import SUPPORT_ALPHA

#: Methods whose squared envelope the second look can remove impacts from (``ies`` reads
#: a spectral coherence, not a squared envelope).
READABLE = ("raw", "cpw", "drs-sk")
#: Harmonics of the envelope spectrum the fault rate is read from [-].
RATE_LINES = 8
#: Harmonics of the synchronous average read by the last step of the rate's refinement [-].
RATE_HARMONICS = 32
#: Phase bins of the synchronous average per sample of a period [-] (at least 64 bins).
BINS_PER_SAMPLE = 1


def _folded(e: np.ndarray, sample_rate: float, f0: float, bins: int):
    """(the synchronous average of ``e`` at the rate ``f0`` [Hz] over ``bins`` phase bins,
    the bin of each sample, and the whole phase bins each sample lies from the first,
    counted on: floor(k f0 bins / f_s)). Integers after one product: the float modulo
    cost three times as much."""
    whole = (np.arange(e.size) * (f0 * bins / sample_rate)).astype(np.intp)  # floor: >= 0
    b = whole % bins
    total = np.bincount(b, weights=e, minlength=bins)
    count = np.bincount(b, minlength=bins)
    return total / np.maximum(count, 1), b, whole


def _bins(sample_rate: float, f0: float) -> int:
    return max(64, int(math.ceil(BINS_PER_SAMPLE * sample_rate / f0)))


def periodic_power(e: np.ndarray, sample_rate: float, f0: float, harmonics: int) -> float:
    """Power of the first ``harmonics`` harmonics of the synchronous average of ``e`` at
    the rate ``f0`` [Hz] [unit of ``e`` squared].

    Parameters
    ----------
    e : numpy.ndarray
        The squared envelope (mean removed).
    sample_rate : float
        f_s [Hz].
    f0 : float
        The rate averaged at [Hz], > 0.
    harmonics : int
        Harmonics of the average summed [-].
    """
    average, _, _ = _folded(e, sample_rate, f0, max(64, 8 * harmonics))
    lines = np.fft.rfft(average)[1 : harmonics + 1] / average.size
    return float(2.0 * np.sum(np.abs(lines) ** 2))


def fault_rate(e: np.ndarray, sample_rate: float, fitted: float, uncertainty: float) -> float:
    """The rate [Hz] within ``fitted`` +- ``uncertainty`` of the impacts in the squared
    envelope ``e``, to a small fraction of 1 / T (T the record's length).

    Each of the first RATE_LINES harmonics that lie below Nyquist is found as the
    strongest bin of the Hann-windowed spectrum of the whole ``e``: the first within
    ``fitted`` +- ``uncertainty``, each next one within 3 bins x k / j of k times the rate
    from the j harmonics found so far (so that another series' line beside a high
    harmonic cannot pull the rate), placed between bins by the parabola through the
    logarithms of its power and its neighbours' (Gaussian interpolation: a bias below a
    few per cent of a bin for the Hann window; Gasior M., Gonzalez J. L., "Improving FFT
    frequency measurement resolution by parabolic and Gaussian spectrum interpolation",
    AIP Conf. Proc. 732 (2004) 276-285); the rate is their least-squares slope over k,
    each weighted by its power. Then the synchronous average's power in its first
    RATE_HARMONICS harmonics is read at that rate and a quarter of its main lobe either
    side, and the rate moved to the top of the parabola through the three
    (:func:`periodic_power`).

    Parameters
    ----------
    e : numpy.ndarray
        The squared envelope (mean removed).
    sample_rate : float
        f_s [Hz].
    fitted : float
        The rate the family's test fitted [Hz], > 0.
    uncertainty : float
        How far from ``fitted`` the rate may be [Hz] (a Welch bin).

    Returns
    -------
    float
        The rate [Hz]; ``fitted`` when no harmonic can be read.

    Examples
    --------
    >>> fs, f = 2000.0, 31.7
    >>> t = np.arange(8000) / fs
    >>> e = np.exp(-((t * f) % 1.0) * 20.0)
    >>> round(fault_rate(e - e.mean(), fs, 31.5, 0.5), 3)
    31.7
    """
    from ..signal.spectra import fast_length
    from .speed import periodic_hann

    n = e.size
    window = periodic_hann(n)
    size = fast_length(n)  # zero-padded to a length the FFT is fast at
    power = np.abs(np.fft.rfft((e - e.mean()) * window, size)) ** 2
    bin_hz = sample_rate / size
    ks, rates, weights = [], [], []
    centre, half = fitted, uncertainty
    for k in range(1, RATE_LINES + 1):
        lo = max(int(math.floor(k * (centre - half) / bin_hz)), 1)
        hi = int(math.ceil(k * (centre + half) / bin_hz))
        if hi + 1 >= power.size or hi < lo:
            break
        i = lo + int(np.argmax(power[lo : hi + 1]))
        a, b, c = np.log(np.maximum(power[i - 1 : i + 2], 1e-300))
        curvature = a - 2.0 * b + c
        offset = 0.5 * (a - c) / curvature if curvature < 0.0 else 0.0
        ks.append(k)
        rates.append((i + offset) * bin_hz / k)
        weights.append(power[i])
        f = _slope(ks, rates, weights)
        centre, half = f, min(uncertainty, 3.0 * bin_hz / k)  # k x half: 3 bins x k / j
    if not ks:
        return fitted
    step = 1.0 / (4.0 * (n / sample_rate) * RATE_HARMONICS)
    a, b, c = (periodic_power(e, sample_rate, f + d * step, RATE_HARMONICS) for d in (-1, 0, 1))
    curvature = a - 2.0 * b + c
    if curvature < 0.0:
        f += float(np.clip(0.5 * (a - c) / curvature, -1.0, 1.0)) * step
    return f


def _slope(ks, rates, weights) -> float:
    """The rate of the harmonics found: the least-squares slope over k, weighted by power."""
    k2w = np.asarray(weights) * np.asarray(ks, dtype=float) ** 2
    return float(np.sum(k2w * np.asarray(rates)) / np.sum(k2w))


def without_impacts(e: np.ndarray, sample_rate: float, f0: float) -> np.ndarray:
    """The squared envelope ``e`` without the impacts that recur at ``f0`` [Hz]: each
    period's impact, the synchronous average scaled by least squares, subtracted.

    Periods start where the average (smoothed over 1/16 of a period) is lowest, between
    impacts. Within each period the fit is of the average's shape about its mean, so that
    what does not recur (another fault's lines, the noise) stays.

    Parameters
    ----------
    e : numpy.ndarray
        The squared envelope (mean removed).
    sample_rate : float
        f_s [Hz].
    f0 : float
        The impacts' rate [Hz]; ``e`` is returned as it is unless 0 < f0 < f_s / 2.

    Examples
    --------
    Impacts whose strength varies at random from one to the next lose their line:

    >>> fs, f = 2000.0, 31.7
    >>> t = np.arange(4000) / fs
    >>> strength = 1.0 + 0.5 * np.random.default_rng(0).random(127)[np.floor(t * f).astype(int)]
    >>> e = strength * np.exp(-((t * f) % 1.0) * 20.0)
    >>> line = lambda v: abs(np.exp(-2j * np.pi * f * t) @ v) / t.size
    >>> bool(line(without_impacts(e, fs, f)) < 0.02 * line(e))
    True
    """
    if not 0.0 < f0 < 0.5 * sample_rate or e.size < 2:
        return e
    bins = _bins(sample_rate, f0)
    average, b, whole = _folded(e, sample_rate, f0, bins)
    width = max(bins // 16, 1)
    wrapped = np.r_[average[-width:], average, average[:width]]
    smooth = np.convolve(wrapped, np.ones(width) / width, "same")[width : width + bins]
    period = (whole - int(np.argmin(smooth))) // bins  # periods start between impacts
    period -= period.min()
    n = int(period.max()) + 1
    count = np.maximum(np.bincount(period, minlength=n), 1)

    def centred(v):
        return v - (np.bincount(period, weights=v, minlength=n) / count)[period]

    shape = centred(average[b] - average.mean())
    cross = np.bincount(period, weights=centred(e) * shape, minlength=n)
    power = np.bincount(period, weights=shape * shape, minlength=n)
    scale = np.divide(cross, power, out=np.zeros(n), where=power > 0)
    return e - scale[period] * shape


def residual_spectra(sample_rate: float, spectra, fitted: float) -> list:
    """Each readable method's squared envelope spectrum with the impacts at the rate
    refined from ``fitted`` [Hz] removed, as :class:`.methods.MethodSpectrum` with ``z``,
    and the rate used for each [Hz].

    Parameters
    ----------
    sample_rate : float
        f_s [Hz].
    spectra : sequence of MethodSpectrum
        The first reading's, each with its squared ``envelope`` (those without are left
        out).
    fitted : float
        The first fault's rate as its test fitted it [Hz].
    """
    from ..signal.spectra import welch_power
    from .statistics import welch_dof
    from .verdict import with_z

    out = []
    for spec in spectra:
        e = spec.envelope
        if spec.method not in READABLE or e is None:
            continue
        f0 = fault_rate(e, sample_rate, fitted, spec.resolution)
        rest = without_impacts(e, sample_rate, f0)
        nperseg = int(round(sample_rate / spec.resolution))
        frequency, power = welch_power(rest, sample_rate, nperseg, nperseg // 2)
        nu = welch_dof(nperseg, nperseg // 2, rest.size)
        out.append((with_z(MethodSpectrum(spec.method, frequency, power, nu, spec.band, None)), f0))
    return out


def second_look(
    sample_rate: float,
    spectra,
    fams,
    decision: dict,
    lines: dict,
    max_frequency: float,
    harmonics: int,
    false_alarm: float,
    modulations: tuple,
    reference: float,
) -> dict:
    """``decision`` (:func:`.verdict.decide`) with the faults the remainder shows once the
    first fault's impacts are removed (see the module docstring); unchanged when no fault
    was accepted, every family was, or the first fault is not gone from the remainder.

    The decision returned carries ``second_look``: the first fault, the rate [Hz] its
    impacts were removed at (in the method that read the first fault added), and the
    faults the remainder added. The families read again are read at the first reading's
    level ``alpha``, not a level split between the two readings: the second look adds at
    most as many tests as the families left, and only where a first fault is accepted.

    Parameters
    ----------
    sample_rate : float
        f_s [Hz].
    spectra : sequence of MethodSpectrum
        The first reading's spectra, with their squared envelopes.
    fams : sequence of Family
        Every family tested.
    decision : dict
        The first reading's :func:`.verdict.decide`.
    lines : dict
        The machine's lines masked (shaft, supply, mesh, varying compliance) [Hz].
    max_frequency : float
        Top of the line search [Hz].
    harmonics : int
        Harmonics read per family [-].
    false_alarm : float
        The record's false-alarm probability [-].
    modulations : tuple
        (shaft, cage) rates [Hz] of the sidebands.
    reference : float
        Top of the tail's reference [Hz].
    """
    from .verdict import decide, discrete_mask, read_families

    accepted = list(decision["faults"])
    others = [f for f in fams if f.name not in accepted]
    if not accepted or not others:
        return decision
    first = accepted[0]
    fitted = decision["tests"][first][1].fundamental_hz
    read = residual_spectra(sample_rate, spectra, fitted)
    if not read:
        return decision
    rest = [spec for spec, _ in read]
    rates = {spec.method: rate for spec, rate in read}
    valid, _ = discrete_mask(rest, lines, max(reference, max_frequency))
    by_name = {f.name: f for f in fams}
    bottom = min(f.lowest for f in fams)
    gone = read_families(rest, [by_name[first]], valid, max_frequency, harmonics, bottom, reference)
    # gone: not even a series at the gates' level (SUPPORT_ALPHA) - a first fault just
    # above the threshold falls below it by little, and is not removed for that
    if any(t.log_p < math.log(SUPPORT_ALPHA) for t in gone.values()):
        return decision
    again = decide(
        rest,
        others,
        valid,
        max_frequency,
        harmonics,
        false_alarm,
        modulations,
        reference,
        prior=tuple(accepted),
        alpha=decision["alpha"],
        bottom=bottom,
    )
    added = [f for f in again["faults"] if f not in accepted]
    if not added:
        return decision
    tests = dict(decision["tests"])
    tests.update({f: again["tests"][f] for f in added})
    rate = rates[again["tests"][added[0]][0]]  # in the method that read the fault added
    return {
        **decision,
        "faults": accepted + added,
        "tests": tests,
        "modulation": list(dict.fromkeys(list(decision["modulation"]) + again["modulation"])),
        "second_look": {"removed": first, "rate_hz": rate, "added": added},
    }
