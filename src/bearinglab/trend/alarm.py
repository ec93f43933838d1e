"""The alarm rule: a baseline from the start of the series, an upper limit per test
(indicator x channel) at a stated false-alarm probability, persistence, one latched
alarm for all tests together.

**Statistic.** Each indicator is tested on a log scale (:data:`STATISTICS`): scale
indicators (rms, peak) and ratios (crest factor, kurtosis) are positive and skewed, and
their changes multiplicative; the spectral kurtosis SK >= -1 is tested as log(SK + 2),
the log of the band's normalised fourth moment.

**Tail model.** Vibration indicators are heavy-tailed (impacts come and go while a
bearing is healthy) and a Gaussian limit such as mean + 6 sigma flags far more records
than it promises. The upper half of each statistic's baseline distribution is modelled as
exponential above the baseline median (a peaks-over-threshold model with an exponential
excess, [Pickands1975], [DavisonSmith1990]; on the log scale, a power-law tail of the
indicator): its scale beta is the mean excess of the k = floor(n/2) largest of the n
baseline values over the next one, u. A light (Gaussian) tail makes the rule
conservative; a heavy one widens beta and the limit with it.

**Persistence.** A test alarms when ``r`` consecutive records exceed its limit
u + c beta. Persistence is a duration: a fault that has come stays, an impact burst
lasts seconds; ``r`` is the number of records that span it at the series' cadence
(30 s: 3 records of PRONOSTIA's 10 s cadence, as the reference rule asks), and never
fewer than two, so that no single record raises the alarm. For records independent of
each other and of the n baseline records, with the model's tail, the chance that r
given records all exceed the limit is exactly

    P_r(c) = prod_{m=0}^{r-1} (k + 1 + m) / (n + 1 + m) * (1 + r c / k)^(-k)

(the first factor is E[F'(u)^r], F'(u) ~ Beta(k + 1, n - k) being the share of the tail
above the order statistic u; the second is E[exp(-r c beta_hat / beta)] for the mean
beta_hat of k exponential excesses, a Gamma(k, beta / k) variable independent of u).
The estimation of u and beta from the baseline is thus accounted for, as a prediction
interval does for a Gaussian sample: :func:`tail_constant` solves P_r(c) = level.

**Running-in.** The baseline starts after a settling time, and a baseline that still
rises is reported: a Mann-Kendall test ([Mann1945], [Kendall1975]) of each statistic
against time, at 1 % over all tests, whose Theil-Sen rise over the baseline ([Sen1968])
exceeds the scale of its upper tail (:func:`rising_baselines`).

**Combination.** With J tests (indicators x channels) each at level alpha / J
(Bonferroni, valid however the tests depend on each other), the probability that the rule
raises a false alarm at a given record is at most alpha, and over a run of N monitored
records at most (N - r + 1) alpha. The alarm is latched: once raised it stays.

**Rate in time.** The user states the false-alarm rate per hour of monitoring, lambda:
the cost of a false alarm is counted in time, not in records, and a series recorded
sparsely (PRONOSTIA's every 10th snapshot, 100 s apart) must not be held to a stricter
rule per hour than the same machine recorded every 10 s. At a cadence of one record
every Delta t seconds the level per record is alpha = lambda Delta t / 3600 (the union
bound over the 3600 / Delta t records of an hour).

The statement rests on independent records and the exponential tail; slow drifts and
correlated records make real rates higher (docs/capabilities/trend.md measures them on
healthy simulated series and on the healthy stretches of real runs).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError

#: Indicator -> the statistic tested.
STATISTICS = {
    "rms": np.log,
    "peak": np.log,
    "crest_factor": np.log,
    "kurtosis": np.log,
    "spectral_kurtosis": lambda v: np.log(np.asarray(v) + 2.0),
}
#: Default false-alarm rate of the rule, all tests together, per hour of monitoring
#: [1/h]: 1e-6 per record at PRONOSTIA's cadence of a record every 10 s, the level per
#: record set low because real indicators drift and the rule fires on healthy stretches
#: of real runs tens of times more often than its model says (docs/capabilities/trend.md).
FALSE_ALARM_PER_HOUR = 3.6e-4
#: Largest level per record the tail model is used at [-].
MAX_LEVEL_PER_RECORD = 0.1
#: Default persistence: how long the records above a limit must last to raise the alarm [s].
PERSISTENCE = 30.0
#: Fewest consecutive records a persistence given as a duration asks for.
MIN_PERSISTENCE_RECORDS = 2
#: Most consecutive records a persistence asks for.
MAX_PERSISTENCE_RECORDS = 50
#: Level of the test that the baseline rises, over all tests [-].
TREND_LEVEL = 0.01
#: Fewest baseline records (the tail scale is the mean of the upper half's excesses).
MIN_BASELINE_RECORDS = 10


def window_probability(n: int, k: int, r: int, c: float) -> float:
    """P_r(c): chance that ``r`` new records all exceed u + c beta_hat (module docstring)
    for a baseline of ``n`` records whose ``k`` largest set beta_hat [-].

    >>> round(window_probability(60, 30, 1, 0.0), 4)     # above the median: (k+1)/(n+1)
    0.5082
    """
    share = math.prod((k + 1 + m) / (n + 1 + m) for m in range(r))
    return share * (1.0 + r * c / k) ** (-k)


def tail_constant(n: int, k: int, r: int, level: float) -> float:
    """The c >= 0 with :func:`window_probability` (n, k, r, c) = ``level`` (0 when even
    the order statistic u alone is rarer than that).

    >>> c = tail_constant(60, 30, 3, 1e-6)
    >>> round(window_probability(60, 30, 3, c) / 1e-6, 9)
    1.0
    """
    share = math.prod((k + 1 + m) / (n + 1 + m) for m in range(r))
    if share <= level:
        return 0.0
    return (k / r) * ((share / level) ** (1.0 / k) - 1.0)


@dataclass(frozen=True)
class TailLimit:
    """The limit of one test: the baseline's ``median``, the order statistic ``u`` the
    tail starts above, the tail scale ``beta``, ``c`` and ``limit`` = u + c beta (all in
    the statistic's units), from ``n`` baseline records and the ``k`` largest."""

    median: float
    u: float
    beta: float
    c: float
    limit: float
    n: int
    k: int


def tail_limit(baseline, level: float, persistence: int) -> TailLimit:
    """The upper limit of a test at ``level`` for runs of ``persistence`` records.

    >>> rng = np.random.default_rng(0)
    >>> t = tail_limit(rng.exponential(1.0, 200), 1e-3, 1)
    >>> round(t.limit, 1), round(-math.log(1e-3), 1)  # exponential: near -ln p, above it
    (7.7, 6.9)
    """
    x = np.sort(np.asarray(baseline, dtype=float))
    n = x.size
    if n < MIN_BASELINE_RECORDS:
        raise InputError("baseline", n, f"at least {MIN_BASELINE_RECORDS} records")
    k = n // 2
    u = float(x[n - k - 1])
    beta = float(np.mean(x[n - k :] - u))
    c = tail_constant(n, k, persistence, level)
    return TailLimit(float(np.median(x)), u, beta, c, u + c * beta, n, k)


def first_run(exceed, persistence: int) -> int | None:
    """Index of the record that completes the first run of ``persistence`` consecutive
    True values, or None.

    >>> first_run([0, 1, 1, 0, 1, 1, 1, 1], 3)
    6
    """
    e = np.asarray(exceed, dtype=bool)
    if persistence <= 0 or e.size < persistence:
        return None
    runs = np.convolve(e.astype(int), np.ones(persistence, dtype=int), mode="valid")
    hits = np.flatnonzero(runs >= persistence)
    return int(hits[0]) + persistence - 1 if hits.size else None


def check_false_alarm_per_hour(rate) -> float:
    """The rule's false-alarm rate per hour of monitoring, > 0 and finite, else InputError
    (its level per record is checked by :func:`level_per_record`)."""
    try:
        p = float(rate)
    except (TypeError, ValueError):
        p = math.nan
    if isinstance(rate, bool) or not (math.isfinite(p) and p > 0.0):
        raise InputError("false_alarm_per_hour", rate, "a rate > 0 per hour of monitoring")
    return p


def level_per_record(rate_per_hour: float, spacing: float) -> float:
    """The rule's level per record for ``rate_per_hour`` [1/h] at a record every
    ``spacing`` [s] (module docstring); InputError when the records are not spaced in
    time or the level exceeds MAX_LEVEL_PER_RECORD.

    >>> [float(f"{level_per_record(3.6e-4, s):.3g}") for s in (10.0, 100.0)]
    [1e-06, 1e-05]
    """
    if not (math.isfinite(spacing) and spacing > 0):
        raise InputError(
            "folder",
            spacing,
            "records at distinct times (a median spacing > 0 s)",
            hint="most records share their time with another: duplicated time stamps?",
        )
    alpha = rate_per_hour * spacing / 3600.0
    if alpha > MAX_LEVEL_PER_RECORD:
        raise InputError(
            "false_alarm_per_hour",
            rate_per_hour,
            f"at most {MAX_LEVEL_PER_RECORD * 3600.0 / spacing:.3g} per hour at a record every "
            f"{spacing:.3g} s ({MAX_LEVEL_PER_RECORD:g} per record)",
        )
    return alpha


def persistence_count(duration: float, spacing: float) -> int:
    """Consecutive records spanning ``duration`` [s] at a cadence of one record every
    ``spacing`` [s]: at least MIN_PERSISTENCE_RECORDS, at most MAX_PERSISTENCE_RECORDS.

    >>> persistence_count(30.0, 10.0), persistence_count(30.0, 100.0)
    (3, 2)
    """
    wanted = math.ceil(duration / spacing - 1e-9) if spacing > 0 else MAX_PERSISTENCE_RECORDS
    return int(min(max(wanted, MIN_PERSISTENCE_RECORDS), MAX_PERSISTENCE_RECORDS))


def mann_kendall(t, y) -> float:
    """One-sided p-value of the Mann-Kendall test that ``y`` rises with ``t``: S = sum over
    pairs of sign(dt) sign(dy), its variance n(n - 1)(2n + 5)/18 without ties, a normal
    tail with continuity correction ([Kendall1975] ch. 4).

    >>> t = np.arange(20.0)
    >>> mann_kendall(t, t) < 1e-8, mann_kendall(t, -t) > 0.99
    (True, True)
    """
    t, y = np.asarray(t, dtype=float), np.asarray(y, dtype=float)
    n = t.size
    i, j = np.triu_indices(n, 1)
    s = float(np.sum(np.sign(t[j] - t[i]) * np.sign(y[j] - y[i])))
    var = n * (n - 1) * (2 * n + 5) / 18.0
    z = (s - 1.0) / math.sqrt(var) if s > 0 else (s + 1.0) / math.sqrt(var) if s < 0 else 0.0
    return 0.5 * math.erfc(z / math.sqrt(2.0))


def theil_sen(t, y) -> float:
    """Median of the pairwise slopes of ``y`` against ``t`` ([Sen1968]) [y's unit / t's]."""
    t, y = np.asarray(t, dtype=float), np.asarray(y, dtype=float)
    i, j = np.triu_indices(t.size, 1)
    dt = t[j] - t[i]
    keep = dt != 0
    return float(np.median((y[j] - y[i])[keep] / dt[keep]))


def rising_baselines(times, statistics, baseline: slice, limits) -> list[tuple[int, float, float]]:
    """The tests whose baseline still rises: (test, Mann-Kendall p-value, Theil-Sen rise
    over the baseline in the statistic's units) where the one-sided p-value is below
    TREND_LEVEL over all tests and the rise exceeds the tail scale beta."""
    t = np.asarray(times, dtype=float)[baseline]
    s = np.asarray(statistics, dtype=float)[baseline]
    out = []
    for j, lim in enumerate(limits):
        y = s[:, j]
        p = mann_kendall(t, y)
        if p < TREND_LEVEL / len(limits):
            rise = theil_sen(t, y) * float(t[-1] - t[0])
            if rise > lim.beta:
                out.append((j, p, rise))
    return out


def baseline_limits(statistics, baseline: slice, level: float, persistence: int) -> list[TailLimit]:
    """The limit of each column of ``statistics`` (records x tests) from its ``baseline``
    rows."""
    s = np.asarray(statistics, dtype=float)
    return [tail_limit(s[baseline, j], level, persistence) for j in range(s.shape[1])]


def first_alarms(statistics, limits, start: int, persistence: int) -> list[int | None]:
    """Per test, the record that completes its first run of ``persistence`` exceedances
    among the records from ``start`` on (None: it never alarms)."""
    s = np.asarray(statistics, dtype=float)
    out = []
    for j, lim in enumerate(limits):
        exceed = s[:, j] > lim.limit
        exceed[:start] = False
        out.append(first_run(exceed, persistence))
    return out


def plain_rule(rms, fraction: float = 0.1, sigmas: float = 6.0, run: int = 3) -> int | None:
    """The issue's reference rule, for comparison only: the record that completes the first
    run of ``run`` values of ``rms`` above mean + ``sigmas`` standard deviations of the
    first ``fraction`` of the series (which a live monitor cannot know), or None.

    >>> plain_rule([1.0, 1.1, 0.9, 1.0, 1.05, 0.95, 1.0, 1.0, 1.1, 0.9] * 3 + [5.0] * 3)
    32
    """
    x = np.asarray(rms, dtype=float)
    n = max(2, math.ceil(fraction * x.size))
    limit = x[:n].mean() + sigmas * x[:n].std(ddof=1)
    exceed = x > limit
    exceed[:n] = False
    return first_run(exceed, run)
