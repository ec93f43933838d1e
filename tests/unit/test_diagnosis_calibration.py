"""Calibration of the diagnosis' probabilities under no fault (issue 27).

The line statistic with its tail (:func:`bearinglab.diagnosis.tail.reference_logp`,
:func:`~bearinglab.diagnosis.tail.tail_tables`), the chain bound on a scan's best
p-value (:mod:`bearinglab.diagnosis.chain`) on its own, the family test on noise, and the
speed check's supply rule. The sweeps over many records are in
benchmarks/calibration_diagnosis.py. Cost: about 4 s.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.special
import scipy.stats

from bearinglab.diagnosis.chain import chain_logp, chain_steps
from bearinglab.diagnosis.series import _window_max, series_test
from bearinglab.diagnosis.speed import line_near, shaft_multiple, supply_line
from bearinglab.diagnosis.tail import line_logp, reference_logp


def test_a_strong_line_is_not_floored_at_the_rank_of_the_largest_reference():
    # 500 reference readings of noise: the rank alone gives any value above them all
    # ln(1/501); the tail gives a line far above the floor a far smaller p-value
    ref = np.random.default_rng(0).chisquare(36, 500) / 36
    floor = math.log(1 / 501)
    lp = reference_logp(ref, np.array([ref.max() + 0.01, 5.0, 20.0]))
    assert lp[0] == pytest.approx(floor, abs=1.5)  # just above the largest: about the floor
    assert lp[1] < floor - 10 and lp[2] < lp[1] - 20  # and it keeps growing
    # the rank alone (tail=False) floors
    assert reference_logp(ref, np.array([20.0]), tail=False)[0] == pytest.approx(floor)
    # few exceedances, or clustered ones (a line reads at three positions), make the
    # tail heavier: its scale is less certain
    assert reference_logp(ref, np.array([5.0]), cluster=1 / 3)[0] > lp[1] + 2


def test_line_pvalues_are_uniform_on_white_noise():
    # each position of a noise spectrum read against all the others: KS at 1 % passes on
    # at least 95 % of the records, and the tail holds its levels pooled
    passed, pooled = 0, []
    for seed in range(40):
        z = np.random.default_rng(seed).chisquare(36, 700) / 36
        zmax, count, _ = _window_max(z, np.ones(z.size, bool))
        p = np.exp(line_logp(zmax, count, 650, 20, tail=True)[20:651])
        passed += scipy.stats.kstest(p, "uniform").pvalue > 0.01
        pooled.append(p)
    pooled = np.concatenate(pooled)
    assert passed >= 38
    assert np.mean(pooled < 1e-2) < 2e-2 and np.mean(pooled < 1e-3) < 3e-3


def test_line_pvalues_are_uniform_on_healthy_simulations():
    # a loaded healthy 6205 (rigid model, 1 m/s^2 of noise): every position of its raw
    # squared-envelope spectrum from 0.98 FTF to 5.5 BPFI read against all of them; the
    # varying-compliance lines at BPFO's harmonics are there, and KS at 1 % still passes
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis.methods import method_spectrum
    from bearinglab.diagnosis.statistics import normalised
    from bearinglab.dynamics import simulate
    from bearinglab.operating import OperatingCondition

    bearing, _ = bearing_from_designation("6205")
    condition = OperatingCondition(radial_load=2000.0, shaft_speed=1797 * math.pi / 30)
    passed = 0
    for seed in range(8):
        sim = simulate(bearing, condition, [], model="rigid", duration=1.0, noise=1.0, seed=seed)
        kin, fs = sim.kinematic, sim.signal.sample_rate
        top = 5.5 * kin.hz("bpfi")
        spec = method_spectrum(
            "raw", sim.signal.channel(), fs, kin.hz("ftf") / 10, None, top / 5.5, top
        )
        zmax, count, _ = _window_max(
            normalised(spec.power, spec.nu), np.ones(spec.power.size, bool)
        )
        lo, hi = int(0.98 * kin.hz("ftf") / spec.resolution), int(top / spec.resolution)
        p = np.exp(line_logp(zmax, count, hi, lo)[max(lo, 1) : hi + 1])
        passed += scipy.stats.kstest(p, "uniform").pvalue > 0.01
    assert passed >= 7


def _scan_minima(index: np.ndarray, draws: int, seed: int) -> np.ndarray:
    """ln of the best Fisher p-value of a scan over ``index`` (rows x lines of bins) on
    ``draws`` records of independent bins, each line read as the largest of three bins
    (its p-value exact: 1 - (1 - min u)^3 for the bins' uniforms u)."""
    rng = np.random.default_rng(seed)
    u = rng.random((draws, int(index.max()) + 3))
    third = np.minimum(np.minimum(u[:, :-2], u[:, 1:-1]), u[:, 2:])  # bins b-1, b, b+1
    lp = np.log1p(-np.exp(3.0 * np.log1p(-third)))  # ln P(max of 3 >= reading)
    stat = -2.0 * lp[:, index - 1].sum(axis=2)  # draws x rows
    return scipy.special.chdtrc(2 * index.shape[1], stat.max(axis=1))


def test_the_chain_bound_holds_and_is_tighter_than_bonferroni():
    # a scan of 4 harmonics of 20 Hz over +-3 % at 1 Hz bins (the grid moves the top
    # harmonic by half a bin): P(best p <= t) on 40 000 noise records against the bound
    f = np.arange(19.4, 20.6 + 1e-9, 1.0 / 8)
    index = np.rint(f[:, None] * np.arange(1, 5)[None, :]).astype(int)
    steps = chain_steps(index, np.ones(index.shape, bool))
    distinct = len({tuple(r) for r in index})
    best = _scan_minima(index, 40_000, 1)
    for t in (0.05, 0.01, 2e-3):
        truth = np.mean(best <= t)
        bound = math.exp(chain_logp(math.log(t), [steps]))
        assert truth <= bound * 1.1  # a bound (within the Monte Carlo's error)
        assert bound <= 0.75 * min(1.0, distinct * t)  # and tighter than Bonferroni
    # where the verdict's levels lie it is close to the truth
    assert math.exp(chain_logp(math.log(2e-3), [steps])) < 1.6 * np.mean(best <= 2e-3)


def test_the_chain_bound_counts_lines_that_come_and_go():
    # a line that comes into reach adds to the bound, less than a fresh test would
    index = np.tile(np.array([[3, 9]]), (3, 1))
    use = np.array([[True, False], [True, True], [True, True]])
    first, moves, pairs = chain_steps(index, use)
    assert (first, moves.size, pairs.tolist()) == (1, 0, [2])
    t = math.log(1e-3)
    assert t < chain_logp(t, [(first, moves, pairs)]) < t + math.log(2.0)


def _noise(seed: int, nu: float = 40.0, size: int = 2400):
    return np.random.default_rng(seed).chisquare(nu, size) / nu


def test_the_family_test_holds_its_level_on_noise():
    # the family's p-value (tail and chain) over 200 noise spectra: below 5 % and 1 % no
    # more often than that, and not piled at 1 as a Bonferroni count piles it
    p = np.array(
        [
            series_test(_noise(s), 0.5, 40.0, 47.3, 0.02, 0.02, 6, 300.0, 8.0, 2, tail=True).p_value
            for s in range(200)
        ]
    )
    assert np.mean(p < 0.05) <= 0.08 and np.mean(p < 0.01) <= 0.025
    assert np.mean(p < 0.5) > 0.1


def test_a_series_is_not_measured_against_its_own_lines():
    # CWRU 223's shape: one strong line and three moderate ones of the same family are
    # the largest readings of the spectrum; read against the positions that are not
    # the family's own they stand out (the support without the strongest line too), and
    # the reference beyond the search limit sharpens the tail
    z = _noise(3)
    for f, height in ((47.5, 16.0), (95.0, 4.8), (8.0, 4.9), (55.5, 4.2)):
        z[int(round(f / 0.5))] = height
    test = series_test(z, 0.5, 40.0, 47.3, 0.03, 0.02, 6, 300.0, 8.0, 2, tail=True)
    wide = series_test(
        z, 0.5, 40.0, 47.3, 0.03, 0.02, 6, 300.0, 8.0, 2, tail=True, reference=1100.0
    )
    assert test.support_p_value < 0.01 and wide.support_p_value < test.support_p_value
    assert wide.p_value < 1e-8


def test_clutter_below_the_search_limit_keeps_the_tail_heavy():
    # a raw envelope spectrum holds more lines at low cyclic frequencies: the positions
    # above the search limit, cleaner, do not lighten the tail of those below
    z = _noise(4)
    rng = np.random.default_rng(5)
    z[rng.integers(20, 600, 40)] = rng.uniform(4.0, 12.0, 40)  # clutter below 300 Hz
    z[[95, 190]] = 9.0  # two lines of a family at 47.5 and 95 Hz: clutter-sized
    near = series_test(z, 0.5, 40.0, 47.3, 0.02, 0.02, 6, 300.0, tail=True)
    wide = series_test(z, 0.5, 40.0, 47.3, 0.02, 0.02, 6, 300.0, tail=True, reference=1100.0)
    assert near.p_value > 1e-3 and wide.p_value > 0.5 * near.p_value


def test_mains_at_120_hz_is_not_a_shaft_at_4_times_the_speed():
    # CWRU 3006 (no tachometer, 1772 rpm given): 120 Hz mains and its harmonics made a
    # "shaft series at 4 x it" and, with the raw envelope, "the sample rate given may be
    # 4 times too high"
    fs, t = 12000.0, np.arange(120000) / 12000.0
    x = sum(np.sin(2 * np.pi * 120.0 * k * t) / k for k in (1, 2, 3))
    x = x + 0.3 * np.random.default_rng(0).standard_normal(t.size)
    assert supply_line(119.97, expected=4 * 1772 / 60)
    assert shaft_multiple(x, fs, 1772 / 60) is None
    # the same lines where the given speed puts its 4th harmonic are a shaft's
    assert shaft_multiple(x, fs, 30.0) == (4, pytest.approx(120.0, rel=1e-3))


def test_a_line_at_the_speed_given_is_found_in_a_busy_spectrum():
    # HIT-SM Normal_900's shape: the shaft line at 15.23 Hz (900 rpm given), stronger 2nd
    # and 4th harmonics, a strong 4.5 Hz line, the 50 Hz mains; in noise alone, no line
    fs, t = 5000.0, np.arange(25000) / 5000.0
    rng = np.random.default_rng(2)
    x = rng.standard_normal(t.size)
    for f, a in ((15.23, 0.3), (30.46, 0.6), (60.92, 0.6), (4.49, 1.5), (50.0, 0.7)):
        x = x + a * np.sin(2 * np.pi * f * t + rng.uniform(0, 6))
    found = line_near(x, fs, 15.0)
    assert found is not None and found[0] == pytest.approx(15.23, abs=0.25)
    assert line_near(rng.standard_normal(t.size), fs, 15.0) is None
