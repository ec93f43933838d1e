"""How often healthy operation carries a test's level above a limit: the rate of excursions,
learned on real healthy operation, that turns a false-alarm rate per hour into a limit
(layer 1 data and arithmetic).

**What is counted.** A test's *level* is the median of its statistic over the last
persistence window (:mod:`.alarm`); its *deviation* z is the level's distance above the
baseline median in robust scales of the baseline (1.4826 median absolute deviations). On
a healthy stretch the deviation wanders: slowly (temperature, lubricant, load) and in
bursts; records a few seconds apart are not independent, so a model of independent records
cannot say how often it crosses a limit (docs/capabilities/trend.md measured the old rule
firing tens of times more often than it stated). What can be counted is the *excursions*:
each time the deviation rises above a threshold u and falls back is one excursion, however
many records it lasts (a cluster of exceedances counted once, as peaks over threshold are
declustered, [DavisonSmith1990] sec. 9; [Leadbetter1983] on clusters of dependent
exceedances), and its maximum. An alarm at limit x is raised by the excursions whose
maximum exceeds x: at a rate

    nu(x) = nu_u * (1 + (x - u) / (k theta))^(-k),    x >= u,

per hour of monitoring and test, where nu_u is the rate of excursions above u and the
excesses of their maxima over u are exponential with mean theta, estimated from k
excursions: the second factor is the predictive chance E[exp(-(x - u)/theta_hat')] with
theta_hat a Gamma(k, theta/k) mean ([Pickands1975] for the exponential excess). The limit
of a test at a rate lambda per hour solves nu(x) = lambda. Rates above nu_u are refused:
their limits would sit in the bulk of the healthy scatter, whose crossings depend on the
records' cadence and the persistence window rather than on the slow wander the tail
describes (the measured curve of excursion rates below u is kept for reporting).

**Where it is learned.** On healthy stretches of real runs: by default the first halves of
the six learning runs of the PHM 2012 challenge ([data-PRONOSTIA], every k-th snapshot as
kept in ../shared), with the rule's default settings, all indicators and channels pooled
(the deviation is in each test's own robust scale, so that tests are comparable). The
numbers are package data (``data/learned_runs.json``, made by
``benchmarks/trend_learn.py``); :func:`bearinglab.trend.learn_runs` learns them from a
user's own folder of runs to failure. Extrapolating from some tens of hours of healthy
operation to one false alarm in thousands of hours is the model's, not a measurement: the
JSON gives the measured rate beside it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError

#: Threshold u above which excursions are counted and their maxima modelled, in robust
#: scales of the baseline: about where a Gaussian bulk ends (2 sd: 2.3 % above).
THRESHOLD = 2.0
#: Deviations at which the measured curve of excursion rates is kept [robust scales].
CURVE = (0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 15.0, 20.0, 30.0)
#: Fewest excursions above the threshold a calibration is fitted from.
MIN_EXCURSIONS = 5


def excursion_maxima(z, threshold: float) -> np.ndarray:
    """The maxima of the excursions of ``z`` above ``threshold``: runs of consecutive
    finite values above it, each counted once (NaN ends a run and is skipped).

    >>> excursion_maxima([0, 3, 5, 1, 2.5, np.nan, 4, 4.5], 2.0).tolist()
    [5.0, 2.5, 4.5]
    """
    z = np.asarray(z, dtype=float)
    above = np.isfinite(z) & (z > threshold)
    if not above.any():
        return np.zeros(0)
    edges = np.diff(np.concatenate(([0], above.astype(int), [0])))
    starts, stops = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    return np.array([float(np.max(z[a:b])) for a, b in zip(starts, stops, strict=True)])


@dataclass(frozen=True)
class Calibration:
    """Excursion rates of healthy deviations: ``threshold`` u, ``excursions`` k above it,
    their maxima's mean excess ``mean_excess`` theta, their ``rate`` nu_u per test-hour,
    the ``test_hours`` observed, the measured ``curve`` ((deviation, rate per test-hour),
    ...) and where it was learned (``source``)."""

    threshold: float
    excursions: int
    mean_excess: float
    rate: float
    test_hours: float
    curve: tuple = field(default=())
    source: str = ""

    def rate_above(self, x: float) -> float:
        """Excursions per test-hour whose maximum exceeds ``x`` >= the threshold [robust
        scales] (the module's nu(x))."""
        u, k = self.threshold, self.excursions
        return self.rate * (1.0 + max(x - u, 0.0) / (k * self.mean_excess)) ** (-k)

    def limit(self, rate_per_hour: float) -> float:
        """The deviation [robust scales] that healthy excursions exceed at ``rate_per_hour``
        per test-hour; InputError above the rate of the excursions over the threshold (below
        it a limit would sit in the bulk of the healthy scatter, which depends on the
        records' cadence and not on the slow wander the tail model describes).

        >>> c = Calibration(2.0, 100, 1.0, 0.5, 200.0)
        >>> round(c.limit(0.5), 6), round(c.rate_above(c.limit(1e-4)) / 1e-4, 6)
        (2.0, 1.0)
        """
        if not (math.isfinite(rate_per_hour) and 0 < rate_per_hour <= self.rate):
            raise InputError(
                "false_alarm_per_hour",
                rate_per_hour,
                f"a rate in (0, {self.rate:.3g}] per hour and test: the rate of the healthy "
                f"excursions above {self.threshold:g} robust scales learned on {self.source}",
            )
        u, k, nu = self.threshold, self.excursions, self.rate
        return u + k * self.mean_excess * ((nu / rate_per_hour) ** (1.0 / k) - 1.0)

    def to_dict(self) -> dict:
        """JSON-ready (package data, and the rule's ``calibration``)."""
        return {
            "threshold": self.threshold,
            "excursions": self.excursions,
            "mean_excess": self.mean_excess,
            "rate_per_hour": self.rate,
            "test_hours": self.test_hours,
            "curve": [{"deviation": x, "rate_per_hour": r} for x, r in self.curve],
            "source": self.source,
        }

    @classmethod
    def from_dict(cls, d: dict) -> Calibration:
        """The inverse of :meth:`to_dict`.

        Parameters
        ----------
        d : dict
            What :meth:`to_dict` gave (as read from JSON).
        """
        return cls(
            float(d["threshold"]),
            int(d["excursions"]),
            float(d["mean_excess"]),
            float(d["rate_per_hour"]),
            float(d["test_hours"]),
            tuple((float(c["deviation"]), float(c["rate_per_hour"])) for c in d["curve"]),
            str(d.get("source", "")),
        )


def fit_calibration(stretches, source: str = "", threshold: float = THRESHOLD) -> Calibration:
    """The :class:`Calibration` of healthy ``stretches``: (deviations of one test over a
    healthy stretch [robust scales], its duration [h]) pairs; all pooled.

    >>> rng = np.random.default_rng(0)
    >>> z = rng.laplace(size=(200, 100))                       # 200 tests, 100 records each
    >>> c = fit_calibration([(row, 1.0) for row in z])
    >>> c.test_hours, c.excursions > 100, 0.7 < c.mean_excess < 1.3
    (200.0, True, True)
    """
    maxima: list[np.ndarray] = []
    hours = 0.0
    curve_counts = np.zeros(len(CURVE))
    for z, duration in stretches:
        z = np.asarray(z, dtype=float)
        hours += float(duration)
        maxima.append(excursion_maxima(z, threshold))
        for i, x in enumerate(CURVE):
            curve_counts[i] += excursion_maxima(z, x).size
    m = np.concatenate(maxima) if maxima else np.zeros(0)
    if hours <= 0 or m.size < MIN_EXCURSIONS:
        raise InputError(
            "learn_from",
            f"{m.size} excursions above {threshold:g} robust scales in {hours:.3g} test-hours",
            f"healthy stretches with at least {MIN_EXCURSIONS} excursions (longer or more runs)",
        )
    curve = tuple(
        (float(x), float(c / hours)) for x, c in zip(CURVE, curve_counts, strict=True) if c > 0
    )
    return Calibration(
        float(threshold),
        int(m.size),
        float(np.mean(m - threshold)),
        float(m.size / hours),
        float(hours),
        curve,
        source,
    )
