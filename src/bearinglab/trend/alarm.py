"""The alarm rule: a robust baseline from the start of the series, each test's level over a
persistence window, a limit from the excursion rates of healthy operation at a stated
false-alarm rate per hour, one latched alarm for all tests together.

**Statistic.** Each indicator (over the band of :mod:`.indicators`) is tested on a log
scale (:data:`STATISTICS`): scale indicators (rms, peak) and ratios (crest factor,
kurtosis) are positive and skewed, and their changes multiplicative; the spectral
kurtosis SK >= -1 is tested as log(SK + 2), the log of the band's normalised fourth
moment. A test is one indicator of one channel.

**Baseline.** After a settling time (a new bearing runs in), the baseline records give each
test a robust location and scale: the median m and 1.4826 median absolute deviations s
(the standard deviation for Gaussian data, [RousseeuwCroux1993]),
which a burst of impacts inside the baseline moves little. The baseline stays the initial
learning window; nothing after it enters it.

**Level and persistence.** A fault that has formed stays: a spall is struck at every
passage of the balls, so it is in every record from then on, while a burst of impacts from
debris, an electrical spike or a knock on the machine lasts seconds to a minute or two. A
test's *level* at a record is therefore the median of its statistic over the records of
the last persistence window (``persistence``, default 120 s, at least 3 records): the
q = floor(m/2) + 1 largest of the m records, so that the level is above a limit only when
most of the window's records are. A burst shorter than half the window never moves it;
the records above a limit that did not move it are reported as short crossings.

**Limit at a rate per hour.** The level's deviation z = (level - m) / s is compared with a
limit x: the alarm is raised at the first record where some test's deviation exceeds its
limit, and it stays raised. The limit is set so that healthy operation carries a test
above it at the stated rate per hour of monitoring: ``false_alarm_per_hour`` lambda over
the J tests (Bonferroni, valid however the tests depend on each other), each test at
lambda / J, through the excursion rates of :mod:`.calibration`, learned on healthy
stretches of real runs, not from a model of independent records - records seconds apart
are not independent and healthy indicators drift, so such a model fires tens of times more
often than it states (measured on the old rule, docs/capabilities/trend.md). The level
per record that the rate gives, lambda Delta t / 3600 at a record every Delta t seconds,
is also stated (the union bound over an hour's records).

**Running-in.** A baseline that still rises is reported: a Mann-Kendall test ([Mann1945],
[Kendall1975]) of each statistic against time, at 1 % over all tests, whose Theil-Sen rise
over the baseline ([Sen1968]) exceeds its robust scale (:func:`rising_baselines`).
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
#: Default false-alarm rate of the rule, all tests together, per hour of monitoring [1/h]:
#: one in about 280 hours (12 days) of monitoring, 1e-5 per record at PRONOSTIA's cadence of
#: 10 s. Chosen among 3.6e-4, 3.6e-3 and 3.6e-2 on the six learning runs, each limit learned
#: from the other five: the largest without an alarm in a run's first half
#: (docs/capabilities/trend.md).
FALSE_ALARM_PER_HOUR = 3.6e-3
#: Largest level per record the rate may give [-].
MAX_LEVEL_PER_RECORD = 0.1
#: Default persistence window: the level is the median of the records of the last 120 s
#: [s]. It ignores bursts up to 60 s (a burst must cover more than half the window to move
#: the level; issue 27 measured bursts of 30 s and more on healthy machines) and is shorter
#: than half the fastest failure seen (Bearing3_1: 250 s from its first impacts to 20 g).
PERSISTENCE = 120.0
#: Fewest and most records in a persistence window.
MIN_WINDOW_RECORDS = 3
MAX_WINDOW_RECORDS = 360
#: Level of the test that the baseline rises, over all tests [-].
TREND_LEVEL = 0.01
#: Fewest baseline records.
MIN_BASELINE_RECORDS = 10
#: Median absolute deviation -> standard deviation of Gaussian data.
MAD_TO_SD = 1.482602218505602
#: Smallest robust scale of a statistic [log units]: 0.1 % (a quantised or nearly constant
#: indicator would otherwise make every change infinitely significant).
SCALE_FLOOR = 1e-3


@dataclass(frozen=True)
class Alarm:
    """The alarm: the ``record`` (index in time order) that completed the first run of
    exceedances, the ``indicator`` and ``channel`` whose test raised it, and its ``value``
    there (in the indicator's unit)."""

    record: int
    indicator: str
    channel: str
    value: float


@dataclass(frozen=True)
class Reference:
    """A test's baseline: its ``median`` m and robust ``scale`` s (statistic units) from
    ``n`` records, the ``excess`` x (robust scales) its level may reach, and ``limit`` =
    m + x s."""

    median: float
    scale: float
    n: int
    excess: float

    @property
    def limit(self) -> float:
        return self.median + self.excess * self.scale


def robust_location_scale(x) -> tuple[float, float]:
    """(median, 1.4826 median absolute deviations, at least SCALE_FLOOR) of ``x``.

    >>> m, s = robust_location_scale(np.random.default_rng(0).standard_normal(20001))
    >>> abs(m) < 0.02, abs(s - 1.0) < 0.03
    (True, True)
    >>> robust_location_scale([1.0] * 9 + [5.0])
    (1.0, 0.001)
    """
    x = np.asarray(x, dtype=float)
    if x.size < MIN_BASELINE_RECORDS:
        raise InputError("baseline", x.size, f"at least {MIN_BASELINE_RECORDS} records")
    m = float(np.median(x))
    return m, max(MAD_TO_SD * float(np.median(np.abs(x - m))), SCALE_FLOOR)


def references(statistics, baseline: slice, excess) -> list[Reference]:
    """Each column's :class:`Reference` from its ``baseline`` rows of ``statistics``
    (records x tests), with the limit ``excess`` (one for all, or one per test)."""
    s = np.asarray(statistics, dtype=float)[baseline]
    excess = np.broadcast_to(np.asarray(excess, dtype=float), (s.shape[1],))
    out = []
    for j in range(s.shape[1]):
        m, scale = robust_location_scale(s[:, j])
        out.append(Reference(m, scale, s.shape[0], float(excess[j])))
    return out


def deviations(statistics, baseline: slice, window: int) -> tuple[list, np.ndarray]:
    """The robust (median, scale) of each test over its ``baseline`` rows and the
    deviations of the levels (:func:`window_levels`, windows after the baseline) from
    them, records x tests [robust scales; NaN where there is no level]."""
    s = np.asarray(statistics, dtype=float)
    base = [robust_location_scale(s[baseline, j]) for j in range(s.shape[1])]
    levels = window_levels(s, window, baseline.stop)
    m = np.array([b[0] for b in base])
    scale = np.array([b[1] for b in base])
    return base, (levels - m) / scale


def window_count(duration: float, spacing: float) -> int:
    """Records in a persistence window of ``duration`` [s] at one record every ``spacing``
    [s]: at least MIN_WINDOW_RECORDS, at most MAX_WINDOW_RECORDS.

    >>> window_count(120.0, 10.0), window_count(120.0, 100.0), window_count(300.0, 50.0)
    (12, 3, 6)
    """
    wanted = math.ceil(duration / spacing - 1e-9) if spacing > 0 else MAX_WINDOW_RECORDS
    return int(min(max(wanted, MIN_WINDOW_RECORDS), MAX_WINDOW_RECORDS))


def window_levels(statistics, window: int, start: int = 0) -> np.ndarray:
    """records x tests: each test's level, the q = floor(window/2) + 1 largest of the
    ``window`` records ending at each record (NaN where the window reaches before
    ``start``); a level is above a value exactly when q of the window's records are.

    >>> window_levels(np.array([[1.0], [9.0], [2.0], [8.0], [7.0]]), 3)[:, 0].tolist()
    [nan, nan, 2.0, 8.0, 7.0]
    """
    s = np.asarray(statistics, dtype=float)
    out = np.full(s.shape, np.nan)
    m = int(window)
    if s.shape[0] - start < m:
        return out
    q = m // 2 + 1
    views = np.lib.stride_tricks.sliding_window_view(s[start:], m, axis=0)
    out[start + m - 1 :] = np.partition(views, m - q, axis=-1)[..., m - q]
    return out


def first_crossings(deviations, excess) -> list[int | None]:
    """Per test (column of ``deviations``), the first record whose deviation exceeds its
    ``excess``, or None."""
    z = np.asarray(deviations, dtype=float)
    excess = np.broadcast_to(np.asarray(excess, dtype=float), (z.shape[1],))
    out: list[int | None] = []
    for j in range(z.shape[1]):
        hit = np.flatnonzero(np.nan_to_num(z[:, j], nan=-np.inf) > excess[j])
        out.append(int(hit[0]) if hit.size else None)
    return out


def crossing_runs(above) -> list[tuple[int, int]]:
    """(first, last) record of each run of consecutive True values of ``above``.

    >>> crossing_runs([0, 1, 1, 0, 1, 0, 0, 1])
    [(1, 2), (4, 4), (7, 7)]
    """
    a = np.asarray(above, dtype=bool).astype(int)
    edges = np.diff(np.concatenate(([0], a, [0])))
    starts, stops = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    return [(int(s), int(e) - 1) for s, e in zip(starts, stops, strict=True)]


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


def rising_baselines(times, statistics, baseline: slice, refs) -> list[tuple[int, float, float]]:
    """The tests whose baseline still rises: (test, Mann-Kendall p-value, Theil-Sen rise
    over the baseline in the statistic's units) where the one-sided p-value is below
    TREND_LEVEL over all tests and the rise exceeds the robust scale."""
    t = np.asarray(times, dtype=float)[baseline]
    s = np.asarray(statistics, dtype=float)[baseline]
    out = []
    for j, ref in enumerate(refs):
        y = s[:, j]
        p = mann_kendall(t, y)
        if p < TREND_LEVEL / len(refs):
            rise = theil_sen(t, y) * float(t[-1] - t[0])
            if rise > ref.scale:
                out.append((j, p, rise))
    return out


def plain_rule(rms, fraction: float = 0.1, sigmas: float = 6.0, run: int = 3) -> int | None:
    """The issue's reference rule, for comparison only: the record that completes the first
    run of ``run`` values of ``rms`` above mean + ``sigmas`` standard deviations of the
    first ``fraction`` of the series (which a live monitor cannot know), or None.

    Parameters
    ----------
    rms : array_like
        The indicator's series, one value per record (e.g. RMS [m/s^2]).
    fraction : float
        Share of the series at its start taken as the baseline [-] (at least 2 records
        are). Default 0.1.
    sigmas : float
        The limit is the baseline mean + ``sigmas`` standard deviations [-]. Default 6.
    run : int
        How many successive records must exceed the limit. Default 3.

    Returns
    -------
    int or None
        The index of the record that completes the first run (records in the baseline do
        not count), or None when no run occurs.

    Examples
    --------
    >>> plain_rule([1.0, 1.1, 0.9, 1.0, 1.05, 0.95, 1.0, 1.0, 1.1, 0.9] * 3 + [5.0] * 3)
    32
    """
    if not 0.0 < fraction < 1.0:
        raise InputError("fraction", fraction, "a share of the series between 0 and 1")
    if not sigmas > 0.0:
        raise InputError("sigmas", sigmas, "a number of standard deviations > 0")
    if isinstance(run, bool) or not isinstance(run, int | np.integer) or run < 1:
        raise InputError("run", run, "a whole number of records >= 1")
    x = np.asarray(rms, dtype=float)
    n = max(2, math.ceil(fraction * x.size))
    limit = x[:n].mean() + sigmas * x[:n].std(ddof=1)
    exceed = x > limit
    exceed[:n] = False
    runs = np.convolve(exceed.astype(int), np.ones(run, dtype=int), mode="valid")
    hits = np.flatnonzero(runs >= run)
    return int(hits[0]) + run - 1 if hits.size else None
