"""Pre-processing of Smith & Randall's Methods 2 and 3: cepstral pre-whitening,
discrete/random separation, the fast kurtogram (bearinglab.signal.preprocess, .kurtogram),
and the analytic signal at a fast FFT length (bearinglab.signal.spectra)."""

import numpy as np
import pytest
import scipy.signal

from bearinglab.errors import InputError
from bearinglab.signal.kurtogram import fast_kurtogram, kurtogram_levels
from bearinglab.signal.preprocess import cepstral_prewhitening, discrete_random_separation
from bearinglab.signal.spectra import analytic

FS = 12000.0


def impacts(n=2**15, rate=37.0, ring=3000.0, noise=0.3, seed=1):
    t = np.arange(n) / FS
    x = np.exp(-(t % (1 / rate)) / 1e-3) * np.sin(2 * np.pi * ring * t)
    return x + noise * np.random.default_rng(seed).standard_normal(n)


def test_prewhitening_flattens_the_spectrum_and_keeps_the_phase():
    rng = np.random.default_rng(0)
    t = np.arange(4096) / FS
    x = 5 * np.sin(2 * np.pi * 300 * t) + rng.standard_normal(t.size)
    w = cepstral_prewhitening(x)
    assert w.shape == x.shape
    s = np.abs(np.fft.rfft(w))[1:-1]
    assert np.ptp(s) / np.mean(s) < 1e-6  # flat: a 4096 length is fast already
    # the phase is the signal's: the whitened signal still correlates with it
    assert np.corrcoef(w, x - x.mean())[0, 1] > 0.1


def test_drs_keeps_the_tone_in_the_discrete_part():
    rng = np.random.default_rng(2)
    t = np.arange(2**16) / 4096.0
    tone = np.sin(2 * np.pi * 50.0 * t)
    noise = 0.5 * rng.standard_normal(t.size)
    r, d = discrete_random_separation(tone + noise, 4096.0)
    np.testing.assert_allclose(r + d, tone + noise - np.mean(tone + noise), atol=1e-9)
    assert np.std(d - tone) < 0.25  # the discrete part is the tone
    assert abs(np.std(r) - 0.5) < 0.12  # the random part is the noise
    assert abs(np.corrcoef(r, tone)[0, 1]) < 0.1


def test_drs_bad_arguments():
    x = np.random.default_rng(0).standard_normal(4096)
    with pytest.raises(InputError) as err:
        discrete_random_separation(x, FS, segment_length=8)
    assert err.value.parameter == "segment_length"
    with pytest.raises(InputError) as err:
        discrete_random_separation(x, FS, segment_length=512, delay=10**6)
    assert err.value.parameter == "delay"


def test_kurtogram_finds_the_resonance_band():
    k = fast_kurtogram(impacts(), FS)
    assert k.band[0] < 3000.0 < k.band[1] and k.kurtosis > 1.0
    assert k.band[1] <= FS / 2.56 + 1e-9 or k.level == 0  # below the anti-alias roll-off
    assert len(k.levels) == len(k.centres) == len(k.values)


def test_kurtogram_of_noise_is_near_zero_and_min_bandwidth_holds():
    x = np.random.default_rng(4).standard_normal(2**15)
    k = fast_kurtogram(x, FS, min_bandwidth=500.0)
    assert abs(k.kurtosis) < 0.5
    assert k.bandwidth >= 500.0
    assert kurtogram_levels(3) == [(0.0, 1), (1.0, 2), (1.6, 3), (2.0, 4), (2.6, 6), (3.0, 8)]


def test_kurtogram_bad_arguments():
    with pytest.raises(InputError):
        fast_kurtogram(np.zeros(100), FS)
    with pytest.raises(InputError):
        fast_kurtogram(impacts(), FS, max_level=40)
    with pytest.raises(InputError):
        fast_kurtogram(impacts(), FS, min_bandwidth=FS)


def test_analytic_signal_at_a_fast_length_matches_hilbert():
    # an awkward length (a large prime factor) is padded to a fast one; the envelope
    # agrees with SciPy's away from the end
    x = impacts(n=48001)
    ours, ref = np.abs(analytic(x)), np.abs(scipy.signal.hilbert(x))
    inner = slice(1000, -1000)
    assert np.max(np.abs(ours[inner] - ref[inner])) < 0.02 * np.max(ref)


@pytest.mark.parametrize("m", [1, 2, 3, 8, 9, 100, 101])
@pytest.mark.parametrize("alpha", [0.0, 0.25, 0.5, 1.0])
def test_the_kurtogram_taper_is_scipys_tukey_window(m, alpha):
    from scipy.signal.windows import tukey as scipy_tukey

    from bearinglab.signal.kurtogram import tukey

    np.testing.assert_allclose(tukey(m, alpha), scipy_tukey(m, alpha), rtol=0, atol=1e-15)
