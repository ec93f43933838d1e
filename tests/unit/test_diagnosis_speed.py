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
    # line reading one of them moved its p-value by up to 14 % with the FFT's round-off)
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
