"""Cyclic spectral analysis (bearinglab.signal.cyclic): the fast spectral correlation
against a direct averaged cyclic periodogram, the spectral coherence of a signal whose
cyclic frequencies and coherence are known, the white-noise expectation that flattens it,
and the improved envelope spectrum.

The known answer: white noise n(t) amplitude-modulated, x = (1 + m cos 2 pi a0 t) n, has
the instantaneous power (1 + m cos)^2 = 1 + m^2/2 + 2 m cos(2 pi a0 t) + (m^2/2) cos(4 pi
a0 t), so its spectral correlation at a0 is m sigma^2 and at 2 a0 m^2 sigma^2 / 4 at every
spectral frequency, and S(0, f) = (1 + m^2/2) sigma^2: coherence m / (1 + m^2/2) at a0 and
(m^2/4) / (1 + m^2/2) at 2 a0 ([Antoni2007b] sec. 3, the amplitude-modulated random
process).
"""

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.signal.cyclic import (
    coherence_null,
    fast_spectral_correlation,
    hann,
    improved_envelope_spectrum,
    spectral_coherence,
    window_kernel,
)

FS = 12000.0


def modulated(a0, m=0.5, n=2**17, seed=0):
    t = np.arange(n) / FS
    return (1 + m * np.cos(2 * np.pi * a0 * t)) * np.random.default_rng(seed).standard_normal(n)


@pytest.mark.parametrize("a0", [107.3, 93.75, 70.31, 300.0])
def test_coherence_of_modulated_noise_at_its_cyclic_frequencies(a0):
    """Off and on the multiples of Delta f = 46.875 Hz (107.3 = 2.29, 93.75 = 2.0,
    70.31 = 1.5 Delta f): the shifts' combination reads the same coherence everywhere."""
    m = 0.5
    c = spectral_coherence(modulated(a0, m), FS, 256, 700.0, 8192)
    alpha, ies = improved_envelope_spectrum(c)
    excess = c.null * (ies - 1.0)  # mean |gamma|^2 over the spectral frequencies, less noise
    # the line's largest bin (the second harmonic is 1/8 of the first: the noise's own
    # spread, ~0.03 in these units, lifts the largest of three bins)
    for k, expected, rel in (
        (1, m / (1 + m * m / 2), 0.08),
        (2, m * m / 4 / (1 + m * m / 2), 0.35),
    ):
        i = int(np.argmin(np.abs(alpha - k * a0)))
        got = np.sqrt(excess[i - 1 : i + 2].max())
        assert got == pytest.approx(expected, rel=rel)
    # nothing at other cyclic frequencies: noise reads about 1 everywhere - a few % more
    # than white noise's 1, the more the closer a0 is to Delta f (14 % at 1.5 Delta f):
    # the cyclic component correlates the spectral bins a0 apart, which adds to the
    # estimate's variance at every cyclic frequency alike
    far = (alpha > 20) & np.all([np.abs(alpha - k * a0) > 8 for k in (1, 2, 3)], axis=0)
    assert 0.98 < np.median(ies[far]) < 1.2
    assert np.max(ies[far]) < 1.25 * np.median(ies[far])
    bands = [np.median(ies[far & (alpha >= lo) & (alpha < lo + 100)]) for lo in range(0, 700, 100)]
    assert np.ptp(bands) < 0.03


def test_no_ghost_lines_from_the_shifts():
    """A strong cyclic line leaves nothing at +-k Delta f or +-4 Delta f (the fold of the
    frame rate 8 Delta f, if the hop were N_w / 4) beside it."""
    a0 = 107.3
    c = spectral_coherence(modulated(a0, 0.8), FS, 256, 800.0, 8192)
    alpha, ies = improved_envelope_spectrum(c)
    df = FS / 256
    for k in (1, 2, 3, 4, 5, 6):
        for side in (-1, 1):
            f = a0 + side * k * df
            if 20 < f < 780:
                i = int(np.argmin(np.abs(alpha - f)))
                assert ies[i - 1 : i + 2].max() < 1.15, (k, side)


def test_white_noise_expectation_flattens_the_coherence():
    """Averaged over seeds, white noise's squared coherence divided by coherence_null is
    1 at every cyclic frequency - also where alpha is a multiple of Delta f, where three
    shifts read it instead of four (its raw level is 6 % higher there)."""
    runs = [
        improved_envelope_spectrum(
            spectral_coherence(
                np.random.default_rng(s).standard_normal(60000), FS, 128, 600.0, 4096
            )
        )[1]
        for s in range(6)
    ]
    mean = np.mean(runs, axis=0)[8:]  # from ~23 Hz: the taper's main lobe round 0 excluded
    ratio = 4096 // 128  # cyclic bins per Delta f
    phase = np.arange(8, 8 + mean.size) % ratio
    by_phase = np.array([mean[phase == p].mean() for p in range(ratio)])
    assert np.all(np.abs(by_phase - 1.0) < 0.015)
    raw = np.mean(
        [
            spectral_coherence(
                np.random.default_rng(s).standard_normal(60000), FS, 128, 600.0, 4096
            ).coherence.mean(axis=1)
            for s in range(2)
        ],
        axis=0,
    )[8:]
    assert raw[phase == 0].mean() / raw[phase == ratio // 2].mean() > 1.03


def test_null_matches_a_direct_simulation_of_one_block():
    """coherence_null against the empirical mean of |gamma_b|^2 on many one-block records
    (a record shorter than a block is one zero-padded block)."""
    n_alpha, ratio, nw, hop = 64, 4096 / 128, 128, 16
    h = hann(4096 // hop)
    null = coherence_null(n_alpha, ratio, nw, hop, h)
    sims = [
        spectral_coherence(
            np.random.default_rng(s).standard_normal(4096 + nw - hop), FS, nw, 180.0, 4096
        )
        for s in range(40)
    ]
    assert sims[0].blocks == 1
    empirical = np.mean([s.coherence.mean(axis=1) for s in sims], axis=0)
    sel = slice(6, min(n_alpha, empirical.size))
    assert np.allclose(empirical[sel], null[sel], rtol=0.08)


def _acp(x, nw, hop, alpha, f, fs):
    """Direct averaged cyclic periodogram (Antoni 2007b eq. 25): sum over frames of
    X(i, f) X(i, f - alpha)^* with the phase referred to absolute time, at any f, alpha."""
    w = hann(nw)
    frames = np.lib.stride_tricks.sliding_window_view(x, nw)[::hop]
    t = (np.arange(frames.shape[0])[:, None] * hop + np.arange(nw)[None, :]) / fs
    a = np.sum(frames * w * np.exp(-2j * np.pi * f * t), axis=1)
    b = np.sum(frames * w * np.exp(-2j * np.pi * (f - alpha) * t), axis=1)
    return np.mean(a * np.conj(b))


def test_fast_spectral_correlation_against_the_direct_periodogram():
    """The fast estimate and the direct averaged cyclic periodogram read the same
    correlation (modulus and phase) of a modulated noise at its cyclic frequency, on and
    off the multiples of Delta f: the phase correction and the kernels of eq. 16 right."""
    n, nw = 2**15, 64
    x = modulated(0.0, 0.0, n=n, seed=3)  # plain noise, modulated below
    t = np.arange(n) / FS
    for grid_bin in (200, 228):  # on the grid of the full-record transform
        c0 = fast_spectral_correlation(x, FS, nw, 600.0)
        a0 = c0.alpha[grid_bin]
        y = (1 + 0.6 * np.cos(2 * np.pi * a0 * t + 0.7)) * x
        c = fast_spectral_correlation(y, FS, nw, 600.0)
        for k in (10, 23):
            f = c.frequency[k]
            direct = _acp(y - y.mean(), nw, nw // 8, a0, f, FS)
            fast = c.correlation[grid_bin, k]
            assert abs(fast) == pytest.approx(abs(direct), rel=0.25)
            assert abs(np.angle(fast * np.conj(direct))) < 0.3
        # the modulation's phase: the cyclic autocorrelation at a0 is m sigma^2 e^{j 0.7}
        mean = np.nanmean(c.correlation[grid_bin, 8:])
        assert abs(np.angle(mean * np.exp(-0.7j))) < 0.2


def test_window_kernel_of_the_hann_square():
    """R_w at whole bins: 3/8, 1/4, 1/16 of N_w (Hann squared has three cosine terms)."""
    nw = 256
    got = window_kernel(np.array([0.0, 1.0, 2.0, 3.0]) / nw, nw) / nw
    assert np.allclose(got, [3 / 8, 1 / 4, 1 / 16, 0.0], atol=1e-12)


def test_inputs_are_checked():
    x = np.random.default_rng(0).standard_normal(20000)
    with pytest.raises(InputError, match="window_length"):
        spectral_coherence(x, FS, 100, 300.0, 4096)
    with pytest.raises(InputError, match="alpha_max"):
        spectral_coherence(x, FS, 256, 5900.0, 4096)
    with pytest.raises(InputError, match="hop"):
        spectral_coherence(x, FS, 256, 300.0, 4096, hop=48)
    with pytest.raises(InputError, match="block_length"):
        spectral_coherence(x, FS, 256, 300.0, 4100)
    c = spectral_coherence(x, FS, 256, 300.0, 4096)
    with pytest.raises(InputError, match="band"):
        improved_envelope_spectrum(c, (100.0, 200.0))  # below the spectral bins kept
    assert c.frequency[0] >= 300.0 + 2 * FS / 256
