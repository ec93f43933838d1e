"""The remaining life by trajectory similarity (issue 29, trend/similarity.py): the health
indicator reads every indicator, not the r.m.s. alone; a series matched to learned runs
gets the remaining life of the stage it matches, and a flat one an interval as wide as
the lives; the weighted estimate and quantiles; what the package learned. Synthetic and
packaged data only: about 0.5 s in all."""

import numpy as np
import pytest

from bearinglab.trend.learning import packaged_learned
from bearinglab.trend.life import best_estimate, health_index, phm2012_accuracy
from bearinglab.trend.similarity import (
    candidates,
    health_indicator,
    trajectory,
    weighted_quantile,
)

TESTS = tuple((n, c) for n in ("rms", "kurtosis") for c in range(2))


def indicator_values(records: int, step_at: int | None, seed: int = 0) -> dict:
    """rms and kurtosis of 2 channels, steady noise; from ``step_at`` on the kurtosis of
    channel 1 doubles (impacts that the r.m.s. does not show)."""
    rng = np.random.default_rng(seed)
    rms = 0.3 * np.exp(rng.normal(0, 0.02, (records, 2)))
    kurt = 3.0 * np.exp(rng.normal(0, 0.02, (records, 2)))
    if step_at is not None:
        kurt[step_at:, 1] *= 2.0
    return {"rms": rms, "kurtosis": kurt}


def test_the_health_indicator_reads_the_kurtosis_that_the_rms_misses():
    values = indicator_values(120, step_at=80)
    h = health_indicator(values, TESTS, 5, 35, 3)
    assert np.isnan(h[:36]).all() and np.isfinite(h[37:]).all()  # a level from stop + window - 1
    before, after = np.nanmedian(h[40:78]), np.median(h[85:])
    # the doubled kurtosis sits ln 2 / (0.02 x 1.4826 / 1.4826...) ~ 35 scales above its baseline
    assert after > before + 2.0 and after == pytest.approx(np.log1p(np.log(2) / 0.02), rel=0.3)
    rms_only = health_index(values, np.arange(120) * 10.0, 5, 35, 3)
    assert abs(np.median(rms_only[85:]) - np.nanmedian(rms_only[40:78])) < 0.05


def ramp(times, onset: float, life: float) -> np.ndarray:
    """A health indicator flat at 0.5 up to ``onset``, rising linearly to 4 at ``life``."""
    return np.where(times < onset, 0.5, 0.5 + 3.5 * (times - onset) / (life - onset))


@pytest.fixture
def learned_runs():
    out = []
    for k, life in enumerate((5000.0, 8000.0, 12000.0)):
        t = np.arange(0.0, life + 1, 100.0)
        noise = np.random.default_rng(k).normal(0, 0.05, t.size)
        out.append(trajectory(f"run{k}", t, ramp(t, life - 2000.0, life) + noise))
    return out


def estimate(trs, times, health):
    r, w = candidates(trs, times, health, len(times) - 1)
    lo, hi = weighted_quantile(r, w, [0.1, 0.9])
    return best_estimate(r, w), lo, hi


def test_a_degrading_series_gets_the_remaining_life_of_the_stage_it_matches(learned_runs):
    # a new run of life 10,000 s, 1,000 s before its failure: half way up the rise
    t = np.arange(0.0, 9001.0, 100.0)
    e, lo, hi = estimate(learned_runs, t, ramp(t, 8000.0, 10000.0))
    assert lo <= 1000.0 <= hi and hi - lo < 1000.0
    assert e == pytest.approx(1000.0, rel=0.2)
    # later on the rise, less left
    t2 = np.arange(0.0, 9601.0, 100.0)
    assert estimate(learned_runs, t2, ramp(t2, 8000.0, 10000.0))[0] < 0.6 * e


def test_a_flat_series_gets_an_interval_as_wide_as_the_lives(learned_runs):
    t = np.arange(0.0, 4001.0, 100.0)
    e, lo, hi = estimate(learned_runs, t, np.full(t.size, 0.5))
    assert hi > 5000.0 and lo > 1500.0 and hi / lo > 2.5
    # the challenge's score makes the estimate early in a wide law
    assert lo <= e < np.sqrt(lo * hi)


def test_no_level_yet_gives_no_candidates(learned_runs):
    t = np.arange(0.0, 1001.0, 100.0)
    assert candidates(learned_runs, t, np.full(t.size, np.nan), t.size - 1) is None


def test_the_weighted_estimate_and_quantiles():
    r = np.array([100.0, 500.0, 10000.0])
    assert best_estimate(r, [0.0, 1.0, 0.0]) == pytest.approx(500.0)
    assert weighted_quantile(r, [1.0, 1.0, 1.0], 0.5) == pytest.approx(500.0)
    # many samples are pooled on a log grid: the estimate's expected score stays within
    # 0.002 of the best found by an exhaustive search (the score is flat near its top)
    s = np.random.default_rng(3).lognormal(7.0, 0.8, 1000)
    w = np.random.default_rng(4).uniform(0.1, 1.0, s.size)
    grid = np.geomspace(s.min(), s.max(), 2000)
    expected = phm2012_accuracy(s[None, :], grid[:, None]) @ w / w.sum()
    mine = phm2012_accuracy(s, best_estimate(s, w)) @ w / w.sum()
    assert expected.max() - 0.002 < mine <= expected.max() + 1e-9


def test_the_packaged_defaults_hold_each_learning_runs_indicator():
    learned = packaged_learned()
    trs = learned.life["trajectories"]
    assert [tr["run"] for tr in trs] == [row["run"] for row in learned.runs]
    for tr, row in zip(trs, learned.runs, strict=True):
        assert tr["life_s"] == pytest.approx(row["life_s"])
        t, h = np.array(tr["times_s"]), np.array(tr["health"])
        assert np.all(np.diff(t) > 0) and t[-1] == pytest.approx(row["life_s"])
        # each run ends well above its baseline (the 20 g stop)
        assert np.isfinite(h).all() and h[-1] > 1.0 and h[-1] > np.median(h) + 0.3


@pytest.mark.parametrize(
    "samples, weights, parameter",
    [([], [], "samples"), ([1.0, 2.0], [1.0], "samples"), ([1.0, 2.0], [0.0, 0.0], "weights")],
)
def test_weighted_quantile_refuses_what_has_no_law(samples, weights, parameter):
    from bearinglab.errors import InputError

    with pytest.raises(InputError) as err:
        weighted_quantile(samples, weights, 0.5)
    assert err.value.parameter == parameter
