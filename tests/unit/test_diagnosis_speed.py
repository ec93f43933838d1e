"""What the diagnosis' speed-ups rest on (issue 27, its speed criterion): the line statistic
does not depend on the round-off of the FFTs before it, and the faster paths agree with
the plain ones they replace."""

import numpy as np
import scipy.ndimage

from bearinglab.diagnosis.statistics import FLOOR_BINS, normalised


def _ranks(z):
    """How many bins read at least as much as each (the empirical null's count)."""
    s = np.sort(z)
    return s.size - np.searchsorted(s, z, side="left")


def test_bins_at_their_running_median_tie_exactly_whatever_the_round_off():
    # a bin that is its own window's running median reads exactly chi2_median / nu: such
    # bins tie, and a rank among them does not move when the power moves by round-off
    # (before: p / (median x nu / chi2_median) differed in the last bit bin by bin, and a
    # line reading one of them moved its family's significance by 4.5 % when the envelope's
    # FFT path changed at round-off: MFPT OuterRaceFault_vload_1, raw, ball)
    rng = np.random.default_rng(3)
    nu = 8.0
    p = rng.chisquare(nu, 4000) / nu
    z = normalised(p, nu)
    median = scipy.ndimage.median_filter(np.r_[p[1], p[1:]], size=FLOOR_BINS, mode="reflect")
    own = np.flatnonzero(np.r_[p[1], p[1:]] == median)
    assert own.size >= 20
    assert np.unique(z[own]).size == 1
    wobble = p * (1.0 + 4e-16 * rng.standard_normal(p.size))
    assert np.array_equal(_ranks(normalised(wobble, nu)), _ranks(z))


def test_the_whole_record_alignment_is_the_passage_by_passage_one():
    from bearinglab.diagnosis.events import align_passages, align_passages_rows

    rng = np.random.default_rng(5)
    n, period = 60_000, 173.3
    e = rng.exponential(1.0, n)
    grid = np.arange(300, n - 300, period)
    starts = (grid + rng.integers(-4, 5, grid.size)).astype(int)
    for i in starts:
        e[i : i + 6] += 40.0 * np.exp(-np.arange(6) / 2.0)
        e[i + 20 : i + 24] += 15.0
    times = starts + rng.integers(-6, 7, starts.size)
    for margin, reach in ((40, 8), (67, 12)):
        want = align_passages_rows(e, times, margin, reach)
        assert np.array_equal(align_passages(e, times, margin, reach), want)
        assert not np.array_equal(want, times)  # the test moves passages


def test_median_is_numpys():
    from bearinglab.diagnosis.events import median

    rng = np.random.default_rng(7)
    for n in (1, 2, 3, 10, 11, 120_000, 120_001):
        x = rng.exponential(1.0, n)
        assert median(x) == float(np.median(x))
    assert median([1.0, 1.0, 2.0, 2.0]) == 1.5


def test_moving_average_is_the_plain_centred_mean():
    from bearinglab.diagnosis.events import moving_average

    rng = np.random.default_rng(11)
    for n, length in ((1, 1), (5, 2), (5, 7), (100, 10), (101, 13), (2000, 12), (7, 7)):
        x = rng.exponential(1.0, n)
        c = np.concatenate(([0.0], np.cumsum(x)))
        i = np.arange(n)
        lo = np.clip(i - length // 2, 0, n)
        hi = np.clip(i - length // 2 + length, 0, n)
        assert np.array_equal(moving_average(x, length), (c[hi] - c[lo]) / (hi - lo))
