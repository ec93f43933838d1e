"""The command line computes with numpy.fft, scipy.special and its own AGM so that a
command imports neither scipy.signal and scipy.stats (~0.5 s each at start-up) nor
scipy.fft (~0.2 s); these are the SciPy functions they stand for, checked against SciPy
itself."""

import numpy as np
import pytest
import scipy.fft
import scipy.signal
import scipy.stats

from bearinglab.diagnosis.statistics import chi2_logsf
from bearinglab.signal.peaks import local_maxima, peak_prominences
from bearinglab.signal.spectra import analytic, analytic_power, welch_power


@pytest.mark.parametrize("n", [16, 1000, 1001, 480_001])
def test_analytic_signal_is_scipy_hilbert(n):
    x = np.random.default_rng(n).normal(size=n)
    fast = scipy.fft.next_fast_len(n, real=True)
    assert np.allclose(analytic(x), scipy.signal.hilbert(x, N=fast)[:n], rtol=0, atol=1e-12)


@pytest.mark.parametrize("n", [16, 17, 1000, 1001, 480_001])
def test_analytic_power_is_the_squared_analytic_signal(n):
    # x^2 + H[x]^2 from one real inverse FFT: |analytic(x)|^2 to round-off
    x = np.random.default_rng(n).normal(size=n) + 0.5
    ref = np.abs(scipy.signal.hilbert(x, N=scipy.fft.next_fast_len(n, real=True))[:n]) ** 2
    assert np.allclose(analytic_power(x), ref, rtol=1e-12, atol=1e-12 * ref.max())


@pytest.mark.parametrize(
    "n, nperseg, noverlap",
    [(12_000, 1024, 512), (12_001, 1024, 512), (5000, 999, 499), (4096, 4096, 0)],
)
def test_welch_power_is_scipy_welch(n, nperseg, noverlap):
    x = np.random.default_rng(n).normal(size=n) + 0.3
    f, p = welch_power(x, 12e3, nperseg, noverlap)
    f2, p2 = scipy.signal.welch(
        x,
        fs=12e3,
        window="hann",
        nperseg=nperseg,
        noverlap=noverlap,
        detrend="constant",
        scaling="spectrum",
    )
    assert np.array_equal(f, f2)
    assert np.allclose(p, p2, rtol=1e-12, atol=0)


def test_local_maxima_are_find_peaks_plateaus_included():
    rng = np.random.default_rng(3)
    for _ in range(300):
        x = rng.integers(0, 4, size=rng.integers(0, 40))
        assert np.array_equal(local_maxima(x), scipy.signal.find_peaks(x)[0])


def test_chi2_tail_is_scipy_stats_where_that_is_finite():
    rng = np.random.default_rng(4)
    x, dof = rng.exponential(30.0, 2000), rng.integers(2, 60, 2000)
    assert np.allclose(chi2_logsf(x, dof), scipy.stats.chi2.logsf(x, dof), rtol=1e-12, atol=1e-12)
    assert np.all(np.isfinite(chi2_logsf(np.array([1e4, 1e6]), np.array([20, 20]))))


def test_peak_prominences_are_scipy_peak_prominences():
    rng = np.random.default_rng(5)
    for size in (3, 10, 200, 5000):
        for x in (rng.normal(size=size), rng.integers(0, 5, size).astype(float)):
            peaks = local_maxima(x)
            want = scipy.signal.peak_prominences(x, peaks)[0] if peaks.size else np.zeros(0)
            assert np.allclose(peak_prominences(x, peaks), want, rtol=0, atol=1e-12)


def test_agm_elliptic_integrals_are_scipys():
    """Hertz contact takes K and E from the AGM (bearinglab.contact.elliptic) so that no
    command imports scipy.special for them; over the whole range of m, with m and its
    complement p = 1 - m each given exactly, they are SciPy's to a few ulp."""
    import scipy.special as sp

    from bearinglab.contact.elliptic import complete_elliptic, ellipk_ellipe

    small = np.logspace(-300, -0.3, 300)  # m -> 0 and, as p, m -> 1
    for m, p in ((small, 1.0 - small), (-np.expm1(np.log(small)), small)):
        k, diff = complete_elliptic(p, m)
        assert np.allclose(k, sp.ellipkm1(p), rtol=2e-15, atol=0)
        big = m > 0.1  # SciPy's difference loses digits at small m; there, the series
        assert np.allclose(diff[big], sp.ellipkm1(p[big]) - sp.ellipe(m[big]), rtol=1e-14)
        series = 0.25 * np.pi * m * (1 + 3 * m / 8)  # pi/4 m (1 + 3/8 m + O(m^2))
        tiny = m < 1e-6
        assert np.allclose(diff[tiny], series[tiny], rtol=1e-12, atol=0)
    m = np.linspace(0.0, 0.9999, 1001)
    k, e = ellipk_ellipe(m)
    assert np.allclose(k, sp.ellipk(m), rtol=2e-15, atol=0)
    assert np.allclose(e, sp.ellipe(m), rtol=2e-15, atol=0)


def test_fast_lengths_are_scipys():
    """numpy.fft is padded to the lengths scipy.fft.next_fast_len/prev_fast_len choose."""
    from bearinglab.signal.spectra import fast_length, fast_length_below

    for n in [*range(1, 3000), 480_001, 1_000_003, 2**20 + 1]:
        assert fast_length(n) == scipy.fft.next_fast_len(n, real=True)
        assert fast_length_below(n) == scipy.fft.prev_fast_len(n, real=True)


@pytest.mark.parametrize("n", [1000, 120_000])
def test_analytic_power_from_a_spectrum_at_hand(n):
    # the whitened record's spectrum, already known, spares the envelope a transform
    from bearinglab.signal.preprocess import cepstral_prewhitening, prewhitened

    x = np.random.default_rng(n).normal(size=n) + 0.5
    y, spectrum = prewhitened(x)
    assert np.array_equal(y, cepstral_prewhitening(x))
    ref = analytic_power(y - y.mean())
    assert np.allclose(analytic_power(y - y.mean(), spectrum), ref, rtol=1e-9, atol=1e-12)
    assert prewhitened(x[:-1])[1] is None  # 119 999 / 999 samples: not a fast length
