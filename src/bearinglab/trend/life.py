"""The remaining useful life at the latest record of a series, with an 80 % interval (layer
3, NumPy only).

**Method.** With what was learned from runs to failure holding their health indicators
(``life["trajectories"]``, as :func:`learn_life` writes since 2026-11-28), the estimate
comes from trajectory similarity (:mod:`.similarity`, [Wang2008]): the remaining lives of
the learned runs at the stretches whose health indicator matches the series' last 20
minutes, weighted by the match; its basis is survival before the alarm and degradation
from it on, and before the series has a level (inside its baseline) the lives' law below
given survival to its age. Measured leave one run out on the six PRONOSTIA learning runs,
it does better than what follows, and no better than a constant (docs/capabilities/
trend.md). What follows is the method used with a learned file without trajectories.

**Two bases.** Before any alarm the series shows no degradation, and the estimate rests on
*survival*: the lives of the runs to failure learned (:mod:`.learning`), given that the
bearing has survived to the series' age (its time since the first record, which is taken
as the bearing's start). From the alarm on it rests on the *degradation* seen: when the
r.m.s. level of the series rises significantly since the alarm (a Mann-Kendall test at 5 %,
[Mann1945], [Kendall1975]), its Theil-Sen slope ([Sen1968]) is extrapolated to the
end-of-life level learned on the runs (the level of their last records above their
baselines); otherwise the alarm itself is the degradation seen, and the estimate comes from
the times from the alarm to the failure learned on the runs, given the time since the
alarm.

**Distributions.** Lives and alarm-to-failure times are modelled as lognormal, a usual law
of fatigue lives beside the Weibull (both are fitted to ball-bearing lives in [Lawless2003]),
with the predictive distribution of a new run: the log of a
new time is a Student t with n - 1 degrees of freedom about the mean of the n learned logs,
scaled by their standard deviation times sqrt(1 + 1/n), so that the interval is as wide as
n runs make it ([Geisser1993] ch. 2). Conditioning on survival to t_0 truncates it there:
the remaining life's quantile q is exp(F^-1(1 - S(t_0)(1 - q))) - t_0.

**Estimate.** The 80 % interval is the 10 % and 90 % quantiles of the remaining life. The
estimate is the one that maximises the expected score of the PHM 2012 challenge under that
distribution ([Nectoux2012b]): with the error Er = 100 (actual - estimate) / actual, a run's
accuracy is exp(-ln(0.5) Er / 5) when the estimate is late (Er <= 0) and
exp(ln(0.5) Er / 20) when it is early, so a late estimate costs four times more per per
cent than an early one, and a wide distribution gives an early estimate. A trend
extrapolated is its own estimate, its interval from the spread of the end-of-life levels.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from .similarity import WINDOW

#: The 80 % interval's quantiles.
INTERVAL = (0.1, 0.9)
#: Quantiles of the remaining life over which the challenge's score is averaged.
QUANTILES = np.linspace(0.005, 0.995, 200)
#: Error halving the challenge's accuracy, late and early estimates [%] ([Nectoux2012b]).
LATE_HALVING, EARLY_HALVING = 5.0, 20.0
#: Significance of the Mann-Kendall test that the level rises since the alarm.
TREND_LEVEL = 0.05
#: Fewest levels after the alarm a trend is fitted to, and most (evenly spaced over the
#: time since the alarm: the pairwise tests cost the square of their number).
TREND_RECORDS = 5
TREND_MAX_RECORDS = 100
#: Points of the history of estimates drawn (evenly spaced records, the last one included).
HISTORY = 60
#: Cells of the log grid on which many weighted remaining lives are pooled (best_estimate).
POOLED = 128
#: Floor of the times learned [s] (an alarm at the last record has a lead of 0 s).
MIN_TIME = 1.0


def phm2012_accuracy(actual, estimate) -> np.ndarray:
    """The PHM 2012 challenge's accuracy of remaining-life ``estimate`` s against the
    ``actual`` ones [-] ([Nectoux2012b]): Er = 100 (actual - estimate) / actual,
    exp(-ln(0.5) Er / 5) for Er <= 0 (late), exp(ln(0.5) Er / 20) for Er > 0 (early). The
    challenge's score is their mean over the runs.

    >>> [round(float(a), 4) for a in phm2012_accuracy(100.0, [100.0, 80.0, 120.0])]
    [1.0, 0.5, 0.0625]
    """
    actual = np.asarray(actual, dtype=float)
    er = 100.0 * (actual - np.asarray(estimate, dtype=float)) / actual
    halvings = np.where(er <= 0, -er / LATE_HALVING, er / EARLY_HALVING)
    return np.exp(math.log(0.5) * halvings)


@lru_cache(maxsize=16)
def _t_table(df: int) -> tuple[np.ndarray, np.ndarray]:
    """(x, cdf) of Student's t with ``df`` degrees of freedom on a fine grid (its density
    integrated by the trapezoid rule; the tails beyond |x| = 200 hold < 1e-5 at df = 1)."""
    x = np.concatenate([-np.geomspace(200.0, 1e-3, 1500), [0.0], np.geomspace(1e-3, 200.0, 1500)])
    log_c = math.lgamma((df + 1) / 2) - math.lgamma(df / 2) - 0.5 * math.log(df * math.pi)
    pdf = np.exp(log_c - (df + 1) / 2 * np.log1p(x * x / df))
    cdf = np.concatenate([[0.0], np.cumsum(np.diff(x) * (pdf[1:] + pdf[:-1]) / 2)])
    cdf = cdf / cdf[-1] * (1 - 2 * _t_tail(df, 200.0)) + _t_tail(df, 200.0)
    return x, cdf


def _t_tail(df: int, x: float) -> float:
    """P(T > x) for large x, the leading term of Student's t tail."""
    log_c = math.lgamma((df + 1) / 2) - math.lgamma(df / 2) - 0.5 * math.log(df * math.pi)
    return math.exp(log_c + (df + 1) / 2 * math.log(df) - df * math.log(x)) / df


@dataclass(frozen=True)
class Predictive:
    """The predictive lognormal-t law of a new run's time from ``n`` learned times: the log
    is Student t (n - 1 degrees of freedom) about ``mean`` with ``scale`` (module
    docstring).

    >>> p = Predictive.of([100.0, 200.0, 400.0])
    >>> round(float(p.quantiles(0.0, [0.5])[0]), 6)         # the geometric mean
    200.0
    >>> bool(p.quantiles(150.0, [0.5])[0] < p.quantiles(0.0, [0.5])[0])
    True
    """

    mean: float
    scale: float
    n: int

    @classmethod
    def of(cls, times) -> Predictive:
        logs = np.log(np.maximum(np.asarray(times, dtype=float), MIN_TIME))
        n = logs.size
        spread = float(np.std(logs, ddof=1)) if n > 1 else 1.0
        return cls(float(np.mean(logs)), max(spread, 1e-3) * math.sqrt(1 + 1 / n), n)

    def _cdf(self, z):
        x, cdf = _t_table(max(self.n - 1, 1))
        return np.interp(z, x, cdf)

    def _ppf(self, p):
        x, cdf = _t_table(max(self.n - 1, 1))
        return np.interp(p, cdf, x)

    def quantiles(self, elapsed: float, q) -> np.ndarray:
        """Quantiles ``q`` of the remaining time given survival to ``elapsed`` [s]."""
        q = np.asarray(q, dtype=float)
        z0 = (math.log(max(elapsed, MIN_TIME)) - self.mean) / self.scale if elapsed > 0 else -np.inf
        survive = 1.0 - float(self._cdf(z0)) if np.isfinite(z0) else 1.0
        survive = max(survive, 1e-9)
        p = 1.0 - survive * (1.0 - q)
        t = np.exp(self.mean + self.scale * self._ppf(p))
        return np.maximum(t - elapsed, 0.0)


def best_estimate(samples, weights=None) -> float:
    """The estimate maximising the mean PHM 2012 accuracy over remaining lives
    ``samples`` [s], equally likely or under ``weights`` (module docstring).

    Parameters
    ----------
    samples : array
        Remaining lives [s].
    weights : array, optional
        Their weights (equal when not given).
    """
    r = np.maximum(np.asarray(samples, dtype=float), MIN_TIME)
    w = np.ones(r.size) if weights is None else np.asarray(weights, dtype=float)
    if r.size > POOLED and r.max() > r.min():
        # pooled on a log grid (cells 3.6 % wide at a 100x spread), the weighted mean of each cell
        cell = np.minimum((np.log(r / r.min()) / np.log(r.max() / r.min()) * POOLED), POOLED - 1)
        cell = cell.astype(int)
        total = np.bincount(cell, w, POOLED)
        keep = total > 0
        r = np.bincount(cell, w * r, POOLED)[keep] / total[keep]
        w = total[keep]
    # each sample's accuracy is convex in the estimate on either side of it, so their mean
    # is convex between two samples and greatest at one of them
    mean = phm2012_accuracy(r[None, :], r[:, None]) @ w
    return float(r[int(np.argmax(mean))])


@dataclass(frozen=True, eq=False)
class RemainingLife:
    """The remaining useful life at ``at_time`` [s]: ``estimate``, ``low`` and ``high`` (the
    80 % interval) [s], what it was ``learned_from``, its ``method`` and ``basis``
    (survival or degradation), and its ``history``: (times, estimates, lows, highs) at
    evenly spaced records [s]."""

    estimate: float
    low: float
    high: float
    at_time: float
    learned_from: str
    method: str
    basis: str
    history: tuple = field(default=((), (), (), ()))

    def to_dict(self) -> dict:
        return {
            "estimate_s": self.estimate,
            "low_s": self.low,
            "high_s": self.high,
            "at_time_s": self.at_time,
            "learned_from": self.learned_from,
            "method": self.method,
            "basis": self.basis,
        }


SURVIVAL_METHOD = (
    "the lives learned, lognormal-t predictive, given survival to the series' age; the "
    "estimate maximises the expected PHM 2012 score"
)
LEAD_METHOD = (
    "the times from the alarm to the failure learned, lognormal-t predictive, given the time "
    "since the alarm; the estimate maximises the expected PHM 2012 score"
)
SIMILARITY_METHOD = (
    "the remaining lives of the learning runs at the moments their health indicator (the "
    "largest deviation of every indicator and channel above its baseline) matched this "
    f"series' history (up to its last {WINDOW / 60:g} min), weighted by the match; the "
    "estimate maximises the expected PHM 2012 score"
)
TREND_METHOD = (
    "the r.m.s. level's rise since the alarm (Theil-Sen, Mann-Kendall p < 0.05) extrapolated "
    "to the end-of-life levels learned"
)


def health_index(values, times, first: int, stop: int, window: int) -> np.ndarray:
    """records: the r.m.s. level (median over the persistence window) above its baseline
    median, the largest over the channels, in natural-log units (NaN where no window)."""
    from .alarm import window_levels

    s = np.log(np.asarray(values["rms"], dtype=float))
    levels = window_levels(s, window, stop)
    base = np.median(s[first:stop], axis=0)
    out = np.nan_to_num(levels - base, nan=-np.inf).max(axis=1)
    return np.where(np.isfinite(out), out, np.nan)


def _trend(times, hi, alarm: int, i: int):
    """(slope [1/s], level now) of the health index since the alarm up to record ``i`` when
    it rises significantly, else None."""
    from .alarm import mann_kendall, theil_sen

    t, h = np.asarray(times[alarm : i + 1]), np.asarray(hi[alarm : i + 1])
    keep = np.isfinite(h)
    t, h = t[keep], h[keep]
    if t.size > TREND_MAX_RECORDS:
        pick = np.unique(np.linspace(0, t.size - 1, TREND_MAX_RECORDS).round().astype(int))
        t, h = t[pick], h[pick]
    if t.size < TREND_RECORDS or mann_kendall(t, h) >= TREND_LEVEL:
        return None
    slope = theil_sen(t, h)
    return (slope, float(h[-1])) if slope > 0 else None


def estimate_at(life: dict, times, hi, alarm: int | None, i: int) -> tuple:
    """(estimate, low, high, method, basis) [s] at record ``i`` from the learned ``life``
    parameters (:func:`learn_life`)."""
    now = float(times[i])
    if life.get("trajectories"):
        return _similar(life["trajectories"], times, hi, alarm, i)
    if alarm is None or i < alarm:
        p = Predictive(**life["lives"])
        r = p.quantiles(now, QUANTILES)
        lo, hi_ = p.quantiles(now, INTERVAL)
        return best_estimate(r), float(lo), float(hi_), SURVIVAL_METHOD, "survival"
    trend = _trend(times, hi, alarm, i)
    if trend is not None:
        slope, level = trend
        ends = np.asarray(life["end_levels"], dtype=float)
        to_go = np.maximum(np.quantile(ends, [0.5, *INTERVAL]) - level, 0.0) / slope
        return float(to_go[0]), float(to_go[1]), float(to_go[2]), TREND_METHOD, "degradation"
    p = Predictive(**life["leads"])
    since = now - float(times[alarm])
    r = p.quantiles(since, QUANTILES)
    lo, hi_ = p.quantiles(since, INTERVAL)
    return best_estimate(r), float(lo), float(hi_), LEAD_METHOD, "degradation"


def _similar(trajectories, times, health, alarm, i: int) -> tuple:
    """:func:`estimate_at` by trajectory similarity (:mod:`.similarity`); ``health`` is
    its health indicator. The basis is a label: survival before the alarm, degradation from
    it on (the match itself reads the indicator, not the alarm); survival too where nothing
    learned can be matched yet (the lives' law given the series' age)."""
    from .similarity import candidates, weighted_quantile

    basis = "survival" if alarm is None or i < alarm else "degradation"
    found = candidates(trajectories, times, health, i)
    if found is None:
        p = Predictive.of([float(tr["life_s"]) for tr in trajectories])
        r = p.quantiles(float(times[i]), QUANTILES)
        lo, hi_ = p.quantiles(float(times[i]), INTERVAL)
        return best_estimate(r), float(lo), float(hi_), SURVIVAL_METHOD, "survival"
    r, w = found
    lo, hi_ = weighted_quantile(r, w, INTERVAL)
    est = min(max(best_estimate(r, w), float(lo)), float(hi_))
    return est, float(lo), float(hi_), SIMILARITY_METHOD, basis


def remaining_life(result) -> RemainingLife | None:
    """The remaining useful life at the latest record of a trend ``result`` (a
    :class:`~.result.TrendResult`), with its history over the series; None when what was
    learned holds no lives."""
    return life_of(
        result.learned,
        result.times,
        result.values,
        result.settle_records,
        result.baseline_stop,
        result.persistence,
        None if result.alarm is None else result.alarm.record,
    )


def life_of(learned, times, values, first, stop, window, alarm, history: int = HISTORY):
    """:func:`remaining_life` from the parts of a trend: what was ``learned``, the records'
    ``times`` [s] and indicator ``values``, the baseline records ``first``..``stop``-1, the
    persistence ``window`` and the ``alarm`` record (or None)."""
    life = {} if learned is None else learned.life
    if not life:
        return None
    if life.get("trajectories"):
        from .similarity import health_indicator

        hi = health_indicator(values, _tests(values), first, stop, window)
    else:
        hi = health_index(values, times, first, stop, window)
    n = len(times)
    spaced = np.linspace(0, n - 1, max(min(history, n), 1)).round().astype(int)
    picks = np.unique(np.append(spaced, n - 1))
    history = [estimate_at(life, times, hi, alarm, int(i)) for i in picks]
    last = history[-1]
    return RemainingLife(
        last[0],
        last[1],
        last[2],
        float(times[-1]),
        life.get("learned_from", learned.source),
        last[3],
        last[4],
        (
            tuple(float(times[i]) for i in picks),
            tuple(h[0] for h in history),
            tuple(h[1] for h in history),
            tuple(h[2] for h in history),
        ),
    )


def _tests(values) -> tuple:
    """The (indicator, channel) tests of the indicator ``values`` (all that are given)."""
    from .indicators import INDICATORS

    channels = np.asarray(values["rms"]).shape[1]
    return tuple((n, c) for n in INDICATORS if n in values for c in range(channels))


def learn_life(learned, runs: dict):
    """``learned`` (a :class:`~.learning.LearnedRuns`) with the remaining-life parameters of
    its ``runs`` (name -> :class:`~.learning.RunSeries`): the lives, the times from each
    run's alarm (with ``learned``'s calibration) to its failure, and the end-of-life levels
    of the health index."""
    from dataclasses import replace

    from .rule import evaluate
    from .similarity import health_indicator, trajectory

    lives, leads, ends = [], [], []
    rows, trajectories = [], []
    for row in learned.runs:
        r = runs[row["run"]]
        warnings: list[str] = []
        ev = evaluate(
            r.times,
            r.values,
            r.channels,
            r.settle_records,
            r.baseline_stop,
            r.rule,
            learned.calibration,
            warnings,
        )
        life_s = float(r.times[-1])
        alarm = ev["alarm"]
        alarm_s = None if alarm is None else float(r.times[alarm.record])
        hi = health_index(r.values, r.times, r.settle_records, r.baseline_stop, r.persistence)
        lives.append(life_s)
        if alarm_s is not None:
            leads.append(max(life_s - alarm_s, MIN_TIME))
        ends.append(float(hi[-1]))
        health = health_indicator(
            r.values, _tests(r.values), r.settle_records, r.baseline_stop, r.persistence
        )
        trajectories.append(trajectory(row["run"], r.times, health))
        rows.append({**row, "alarm_s": alarm_s, "end_level": float(hi[-1])})
    life = {
        "learned_from": learned.source,
        "lives": Predictive.of(lives).__dict__,
        "leads": Predictive.of(leads if len(leads) >= 2 else lives).__dict__,
        "end_levels": ends,
        "trajectories": trajectories,
    }
    return replace(learned, runs=tuple(rows), life=life)
