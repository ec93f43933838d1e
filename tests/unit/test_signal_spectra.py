"""Amplitude spectra, envelope analysis, spectral kurtosis and coherence (bearinglab.signal)."""

from __future__ import annotations

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.signal import (
    amplitude_spectrum,
    coherence,
    envelope,
    envelope_spectrum,
    spectral_kurtosis,
    spectral_kurtosis_band,
)

FS = 12000.0  # Hz, the CWRU drive-end rate
N = 12000  # 1 s: 1 Hz bins
T = np.arange(N) / FS
FAULT_HZ = 107.4  # close to the CWRU 6205 BPFO at 1797 rpm
RESONANCE_HZ = 3000.0


def _impacts(rate_hz=FAULT_HZ, resonance_hz=RESONANCE_HZ, decay_s=0.0008):
    """Decaying rings of a resonance, struck at ``rate_hz`` (an outer-race defect)."""
    x = np.zeros(N)
    for start in np.arange(0.002, T[-1], 1.0 / rate_hz):
        i = int(np.ceil(start * FS))
        tau = T[i:] - start
        x[i:] += np.exp(-tau / decay_s) * np.sin(2 * np.pi * resonance_hz * tau)
    return x


@pytest.fixture(scope="module")
def faulty():
    """Impacts + a strong stationary 1 kHz tone (20x the impacts' rms) + noise."""
    rng = np.random.default_rng(7)
    return _impacts() + 3.0 * np.sin(2 * np.pi * 1000.0 * T) + 0.2 * rng.standard_normal(N)


# ---------------------------------------------------------------- amplitude spectrum


def test_sine_amplitude_on_a_bin():
    x = 0.7 * np.sin(2 * np.pi * 250.0 * T + 0.3) + 0.05
    s = amplitude_spectrum(x, FS)
    k = np.argmax(s.amplitude)
    assert s.frequency[k] == pytest.approx(250.0)
    assert s.amplitude[k] == pytest.approx(0.7, rel=0.02)
    assert s.amplitude[0] < 1e-12  # the mean is removed
    assert s.resolution == pytest.approx(1.0)


def test_sine_amplitude_off_bin_with_flattop_and_segments():
    x = 1.3 * np.sin(2 * np.pi * 1234.56 * T)  # between bins
    s = amplitude_spectrum(x, FS, window="flattop", segment_length=2048, overlap=0.5)
    assert s.resolution == pytest.approx(FS / 2048)
    assert s.amplitude.max() == pytest.approx(1.3, rel=0.02)
    assert s.frequency[np.argmax(s.amplitude)] == pytest.approx(1234.56, abs=s.resolution)


def test_hann_scalloping_is_what_flattop_avoids():
    x = np.sin(2 * np.pi * 100.5 * T)  # half-way between 1 Hz bins
    hann = amplitude_spectrum(x, FS).amplitude.max()
    assert 0.80 < hann < 0.90  # Hann loses up to 15 % (1.42 dB)


@pytest.mark.parametrize(
    ("kwargs", "parameter"),
    [
        ({"sample_rate": 0.0}, "sample_rate"),
        ({"sample_rate": np.nan}, "sample_rate"),
        ({"segment_length": 8}, "segment_length"),
        ({"segment_length": N + 1}, "segment_length"),
        ({"overlap": 1.0}, "overlap"),
        ({"window": "no-such-window"}, "window"),
    ],
)
def test_spectrum_bad_inputs(kwargs, parameter):
    args = {"x": np.ones(64), "sample_rate": FS} | kwargs
    with pytest.raises(InputError) as err:
        amplitude_spectrum(**args)
    assert err.value.parameter == parameter


@pytest.mark.parametrize("x", [np.ones(8), np.ones((32, 2)), np.r_[np.ones(31), np.nan]])
def test_spectrum_bad_samples(x):
    with pytest.raises(InputError) as err:
        amplitude_spectrum(x, FS)
    assert err.value.parameter == "x"


# ---------------------------------------------------------------- envelope


def test_envelope_of_am_carrier_is_the_modulation():
    # 3 kHz carrier, 30 % modulated at 50 Hz: envelope = 1 + 0.3 cos(2 pi 50 t), mean removed
    x = (1.0 + 0.3 * np.cos(2 * np.pi * 50.0 * T)) * np.sin(2 * np.pi * 3000.0 * T)
    env = envelope(x, FS, band=(2500.0, 3500.0))
    middle = slice(600, -600)  # away from the Hilbert transform's end effects
    assert np.allclose(env[middle], 0.3 * np.cos(2 * np.pi * 50.0 * T[middle]), atol=0.01)


def test_envelope_spectrum_finds_the_impact_rate(faulty):
    e = envelope_spectrum(faulty, FS, band=(2000.0, 4000.0))
    assert e.band == (2000.0, 4000.0)
    low = (e.frequency > 20.0) & (e.frequency < 500.0)
    peak = e.frequency[low][np.argmax(e.amplitude[low])]
    assert abs(peak - FAULT_HZ) <= e.resolution
    # the tone, 20x stronger than the impacts, buries the line without the band-pass
    raw = envelope_spectrum(faulty, FS)
    assert raw.band is None
    k = np.argmin(np.abs(e.frequency - FAULT_HZ))
    assert e.amplitude[k] / np.median(e.amplitude[low]) > 10.0
    assert raw.amplitude[k] / np.median(raw.amplitude[low]) < 5.0


def test_envelope_spectrum_auto_band_uses_spectral_kurtosis(faulty):
    e = envelope_spectrum(faulty, FS, band="auto")
    assert e.band == spectral_kurtosis_band(faulty, FS).band
    low = (e.frequency > 20.0) & (e.frequency < 500.0)
    assert abs(e.frequency[low][np.argmax(e.amplitude[low])] - FAULT_HZ) <= e.resolution


@pytest.mark.parametrize(
    "band",
    [(0.0, 1000.0), (3000.0, 2000.0), (1000.0, FS / 2), (1000.0,), "kurtogram", (np.nan, 100.0)],
)
def test_bad_band(band):
    with pytest.raises(InputError) as err:
        envelope_spectrum(np.ones(1024), FS, band=band)
    assert err.value.parameter == "band"


def test_bad_filter_order():
    with pytest.raises(InputError) as err:
        envelope(np.ones(1024), FS, band=(100.0, 200.0), order=0)
    assert err.value.parameter == "order"


# ---------------------------------------------------------------- spectral kurtosis


def test_spectral_kurtosis_of_noise_sine_and_impacts(faulty):
    sk = spectral_kurtosis(faulty, FS, 32)  # 2.7 ms: about one ring of the resonance
    at = {f: sk.amplitude[np.argmin(np.abs(sk.frequency - f))] for f in (1000.0, 3000.0, 5000.0)}
    assert at[1000.0] < -0.5  # a stationary sine: SK = -1
    assert abs(at[5000.0]) < 0.5  # Gaussian noise: SK = 0
    assert at[3000.0] > 1.0  # the struck resonance


def test_kurtogram_band_holds_the_resonance_not_the_tone(faulty):
    b = spectral_kurtosis_band(faulty, FS)
    low, high = b.band
    assert low < RESONANCE_HZ < high
    assert not low < 1000.0 < high
    assert b.kurtosis > 1.0
    assert high - low == pytest.approx(b.bandwidth)
    assert 0.0 < low and high < FS / 2


def test_kurtogram_min_bandwidth(faulty):
    b = spectral_kurtosis_band(faulty, FS, window_lengths=[16, 32, 64, 128], min_bandwidth=500.0)
    assert b.bandwidth >= 500.0
    assert b.band[0] < RESONANCE_HZ < b.band[1]
    with pytest.raises(InputError) as err:
        spectral_kurtosis_band(faulty, FS, window_lengths=[256], min_bandwidth=500.0)
    assert err.value.parameter == "min_bandwidth"


def test_spectral_kurtosis_bad_inputs():
    with pytest.raises(InputError) as err:
        spectral_kurtosis(np.ones(256), FS, 128)
    assert err.value.parameter == "window_length"
    with pytest.raises(InputError) as err:
        spectral_kurtosis_band(np.ones(32), FS)
    assert err.value.parameter == "x"
    for lengths in ([], [4], [16, 32.0], [1024]):
        with pytest.raises(InputError) as err:
            spectral_kurtosis_band(np.ones(1024), FS, window_lengths=lengths)
        assert err.value.parameter == "window_lengths"


# ---------------------------------------------------------------- coherence


def test_coherence_of_a_shared_sine_and_the_phase_of_a_delay():
    rng = np.random.default_rng(3)
    f0, delay = 750.0, 4  # Hz, samples
    s = np.sin(2 * np.pi * f0 * np.arange(N + delay) / FS)
    x = s[delay:] + 0.5 * rng.standard_normal(N)
    y = s[:-delay] + 0.5 * rng.standard_normal(N)  # y(t) = x(t - delay) + other noise
    c = coherence(x, y, FS, segment_length=1200)
    k = np.argmin(np.abs(c.frequency - f0))
    assert c.frequency[k] == pytest.approx(f0)
    assert c.coherence[k] > 0.95
    assert np.median(c.coherence) < 0.2  # independent noise elsewhere
    expected = (-360.0 * f0 * delay / FS + 180.0) % 360.0 - 180.0  # y lags: -90 deg
    assert c.phase_deg[k] == pytest.approx(expected, abs=2.0)


def test_coherence_default_segments_and_bad_inputs():
    x = np.random.default_rng(0).standard_normal(4096)
    c = coherence(x, x, 1000.0)
    assert len(c.frequency) == 512 // 2 + 1  # 2**floor(log2(4096 / 8))
    with pytest.raises(InputError) as err:
        coherence(x, x[:-1], 1000.0)
    assert err.value.parameter == "y"
    with pytest.raises(InputError) as err:
        coherence(x, x, -1.0)
    assert err.value.parameter == "sample_rate"
