"""The remaining life by trajectory similarity against runs to failure (layer 3, NumPy
only; [Wang2008]).

**Health indicator.** A record's health indicator is the largest deviation of the trend's
tests (every indicator of :mod:`.indicators` on every channel, the rule's statistics and
levels over the persistence window, :mod:`.alarm`) above the series' own baseline, in
robust scales, as log(1 + max(0, z)): 0 while every test sits at or below its baseline, 1.8
at 5 scales, 4.6 at 100. It reads the kurtosis, the spectral kurtosis, the peak and the
crest factor as well as the r.m.s., each normalised to the run's own baseline, so that
runs of different machines and sensors compare; the largest over the tests, so that a
change of any one shows. Its healthy level grows a little with the number of tests (for
independent ones, about 0.73 on one channel's 5 tests and 0.90 on two channels' 10): the
packaged runs have two channels, so a one-channel series reads somewhat healthier than
a two-channel one would (docs/capabilities/trend.md, Known limits).

**Similarity.** The indicator over the series' last :data:`WINDOW` seconds (or what there
is of it since the baseline) is compared with every stretch of the same length of each
learned run, ending at each of its records tau: the distance is the r.m.s. difference at
:data:`OFFSETS` points evenly spaced over the window. Each stretch gives a candidate
remaining life, the run's life minus tau, weighted by exp(-d^2 / 2 sigma^2), sigma the
median over the runs of each run's nearest distance (how close a good match is between
these runs; at least :data:`SCALE_FLOOR`); each run's weights are scaled to sum to its
best weight, so that a long run with many similar stretches counts once ([Wang2008]
weighs each run by its best match). A series whose
indicator is flat matches the learned runs' healthy stretches, and the candidates spread
over their remaining lives: the interval is as wide as the lives learned. A rising
indicator matches the stretches before their failures.

**Estimate.** The weighted candidates' 10 % and 90 % quantiles are the 80 % interval; the
estimate maximises their expected PHM 2012 score (:func:`.life.best_estimate`: a late
estimate costs four times more per per cent than an early one, so a wide law gives an
early estimate), held inside the interval (:func:`.life.estimate_at`).
"""

from __future__ import annotations

import numpy as np

#: Length of the indicator's history compared [s] (the default baseline's, 20 min).
WINDOW = 1200.0
#: Points compared over the window (100 s apart at the default window).
OFFSETS = 13
#: Floor of the similarity's scale sigma [health-indicator units].
SCALE_FLOOR = 0.02
#: Most records kept of a learned run's indicator (evenly spaced, its last one included).
MAX_RECORDS = 400


def health_indicator(values, tests, first: int, stop: int, window: int) -> np.ndarray:
    """records: log(1 + max(0, z)) of the largest deviation z over the ``tests`` of the
    indicator ``values``, their levels over ``window`` records against the baseline
    records ``first``..``stop``-1 (module docstring; NaN where there is no level yet).

    Parameters
    ----------
    values : dict
        Indicator name -> records x channels.
    tests : sequence of (str, int)
        The (indicator, channel) tests.
    first, stop : int
        The baseline records, ``first`` to ``stop`` - 1.
    window : int
        The persistence window [records].
    """
    from .alarm import deviations
    from .rule import statistics

    stats = statistics(values, tests)
    _, z = deviations(stats, slice(first, stop), window)
    out = np.full(z.shape[0], np.nan)
    seen = np.isfinite(z).any(axis=1)
    top = np.nan_to_num(z[seen], nan=-np.inf).max(axis=1)
    out[seen] = np.log1p(np.maximum(top, 0.0))
    return out


def trajectory(name: str, times, health) -> dict:
    """A learned run's indicator as kept in the learned file: ``run``, ``life_s`` (its last
    record's time), ``times_s`` and ``health`` (the records with a level, at most
    :data:`MAX_RECORDS` of them, evenly spaced, the last one included).

    Parameters
    ----------
    name : str
        The run's name.
    times : array_like
        Its record times [s]; the last is its life.
    health : array_like
        Its health indicator (:func:`health_indicator`; NaN where it has no level) [-].
    """
    times = np.asarray(times, dtype=float)
    health = np.asarray(health, dtype=float)
    life = float(times[-1])
    seen = np.isfinite(health)
    times, health = times[seen], health[seen]
    n = times.size
    keep = np.unique(np.linspace(0, n - 1, min(n, MAX_RECORDS)).round().astype(int))
    return {
        "run": name,
        "life_s": life,
        "times_s": [round(float(t), 3) for t in times[keep]],
        "health": [round(float(h), 4) for h in health[keep]],
    }


def weighted_quantile(samples, weights, q) -> np.ndarray:
    """Quantiles ``q`` of ``samples`` under ``weights`` (the weighted empirical law,
    interpolated between the samples' cumulative weights).

    Parameters
    ----------
    samples : array_like
        The values (at least one).
    weights : array_like
        Their weights, >= 0 and not all 0 [-].
    q : float or array_like
        Quantiles in [0, 1] [-].

    Examples
    --------
    >>> float(weighted_quantile([1.0, 2.0, 3.0], [1.0, 0.0, 1.0], 0.5))
    2.0
    """
    from ..errors import InputError

    x = np.asarray(samples, dtype=float)
    w = np.asarray(weights, dtype=float)
    if x.size == 0 or w.shape != x.shape:
        raise InputError("samples", x.size, "at least one value, with one weight each")
    if not (np.all(w >= 0.0) and w.sum() > 0.0):
        raise InputError("weights", "all 0 or some negative", "weights >= 0, not all 0")
    order = np.argsort(x)
    cum = np.cumsum(w[order])
    mid = (cum - 0.5 * w[order]) / cum[-1]
    return np.interp(q, mid, x[order])


def candidates(trajectories, times, health, i: int, window: float = WINDOW):
    """(remaining lives [s], weights) of every learned stretch matched to the ``health``
    of a series at its record ``i`` (module docstring), or None when the series has no
    level yet at ``i`` or nothing learned is as long as its history.

    Parameters
    ----------
    trajectories : sequence of dict
        The learned runs (:func:`trajectory`).
    times, health : array
        The series' record times [s] and health indicator.
    i : int
        The record at which the remaining life is wanted.
    window : float
        The history compared [s].
    """
    times = np.asarray(times, dtype=float)[: i + 1]
    health = np.asarray(health, dtype=float)[: i + 1]
    seen = np.isfinite(health)
    if not seen[-1]:
        return None
    times, health = times[seen], health[seen]
    now = float(times[-1])
    span = min(window, now - float(times[0]))
    offsets = np.linspace(0.0, span, OFFSETS)
    mine = np.interp(now - offsets, times, health)
    found = _stretches(trajectories, span, offsets)
    if found is None:
        return None
    theirs, lives, runs_ = found
    d = np.sqrt(np.mean((theirs - mine[None, :]) ** 2, axis=1))
    nearest = np.full(int(runs_.max()) + 1, np.inf)
    np.minimum.at(nearest, runs_, d)
    sigma = max(float(np.median(nearest[np.isfinite(nearest)])), SCALE_FLOOR)
    w = np.exp(-0.5 * (d / sigma) ** 2)
    total = np.bincount(runs_, w)
    best = np.zeros(total.size)
    np.maximum.at(best, runs_, w)
    w = w * np.divide(best, total, out=np.zeros_like(best), where=total > 0)[runs_]
    if w.sum() <= 0:
        w = np.ones_like(w)
    return lives, w


_STRETCHES: list = []


def _stretches(trajectories, span: float, offsets):
    """(learned indicators at ``offsets`` before each record tau, stretches x offsets; the
    remaining lives life - tau; the run of each) over the learned ``trajectories``, or None
    when none is as long as ``span``; the last few are kept, since a series' history asks
    for the same ones at every record once it is longer than the window (keyed on the
    ``trajectories`` object: a learned file's, never changed in place)."""
    for key, value in _STRETCHES:
        if key[0] is trajectories and key[1] == span:
            return value
    blocks, lives, runs = [], [], []
    for k, tr in enumerate(trajectories):
        t = np.asarray(tr["times_s"], dtype=float)
        h = np.asarray(tr["health"], dtype=float)
        taus = t[t >= t[0] + span] if t.size >= 2 else t[:0]
        if taus.size == 0:
            continue
        blocks.append(np.interp(taus[:, None] - offsets[None, :], t, h))
        lives.append(float(tr["life_s"]) - taus)
        runs.append(np.full(taus.size, k))
    value = (
        (np.concatenate(blocks), np.concatenate(lives), np.concatenate(runs)) if blocks else None
    )
    for a in value or ():  # shared by every later call: read-only
        a.setflags(write=False)
    _STRETCHES.insert(0, ((trajectories, span), value))
    del _STRETCHES[4:]
    return value
