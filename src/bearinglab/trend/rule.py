"""The alarm rule applied to a series' indicators (layer 3, pure functions of arrays): the
settings checked, the baseline's records (shortened, with a warning, for a short series),
each test's reference and limit, the levels, the alarm, the crossings that did not persist,
and the rule's false-alarm rate measured on held-out healthy stretches of the series
itself (:mod:`.alarm` says what the rule is; :mod:`.calibration` where its limits come
from).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .alarm import (
    MAX_WINDOW_RECORDS,
    MIN_BASELINE_RECORDS,
    STATISTICS,
    Alarm,
    check_false_alarm_per_hour,
    crossing_runs,
    deviations,
    first_crossings,
    level_per_record,
    references,
    rising_baselines,
    window_count,
)
from .indicators import INDICATORS

#: Default settling time: the records of the first 10 minutes are not in the baseline [s].
SETTLE = 600.0
#: Default baseline length after the settling time [s]: 20 minutes, so that the baseline
#: sees some of the slow wander of a running machine, not only its record-to-record scatter.
BASELINE = 1200.0
#: Fewest records a baseline given as a duration holds: a shorter one is extended.
BASELINE_MIN_RECORDS = 30
#: A series too short for the settling and baseline asked for keeps this share of its
#: records for them (a sixth to settle, the next third as the baseline), so that half of
#: it is monitored.
SHORT_SETTLE, SHORT_BASELINE = 1.0 / 6.0, 1.0 / 3.0
#: Held-out measurement of the false-alarm rate: the healthy stretch ends this long before
#: the alarm [s], and at least this much monitoring must be in it [h].
MEASURE_GUARD = 3600.0
MEASURE_MIN_HOURS = 1.0
#: Chance of no event for a Poisson count at its 95 % upper bound: -ln 0.05 = 3.0 events.
UPPER_95 = -math.log(0.05)
#: Short crossings listed in the JSON at most (the first ones; their number is given).
MAX_SHORT_CROSSINGS = 200


def length(name: str, seconds, records) -> tuple[float | None, int | None]:
    """A settling, baseline or persistence length: (duration [s], None) or (None, count);
    a count given wins."""
    if records is not None:
        if isinstance(records, bool) or not isinstance(records, (int, np.integer)) or records < 0:
            raise InputError(f"{name}_records", records, "a number of records >= 0")
        return None, int(records)
    try:
        s = float(seconds)
    except (TypeError, ValueError):
        s = math.nan
    if isinstance(seconds, bool) or not (math.isfinite(s) and s >= 0):
        raise InputError(name, seconds, "a duration >= 0 s")
    return s, None


def settings(rate, persistence, persistence_n, settle, settle_n, baseline, baseline_n) -> dict:
    """The rule's settings, checked: the false-alarm rate per hour, persistence (s or
    records), settle and baseline (s or records)."""
    p = check_false_alarm_per_hour(rate)
    persist_s, persist_n = length("persistence", persistence, persistence_n)
    if persist_n is not None and not 1 <= persist_n <= MAX_WINDOW_RECORDS:
        raise InputError(
            "persistence_records",
            persist_n,
            f"a number of records in [1, {MAX_WINDOW_RECORDS}]",
        )
    if persist_s is not None and persist_s <= 0:
        raise InputError("persistence", persistence, "a duration > 0 s")
    settle_s, settle_count = length("settle", settle, settle_n)
    base_s, base_count = length("baseline", baseline, baseline_n)
    if base_count is not None and base_count < MIN_BASELINE_RECORDS:
        raise InputError("baseline_records", base_count, f"at least {MIN_BASELINE_RECORDS} records")
    return {
        "false_alarm_per_hour": p,
        "persistence": persist_s,
        "persistence_n": persist_n,
        "settle": settle_s,
        "settle_n": settle_count,
        "baseline": base_s,
        "baseline_n": base_count,
    }


def baseline_span(times, rule: dict, window: int, warnings: list[str]) -> tuple[int, int]:
    """(first, stop) indices of the baseline in the time-ordered series. A series too short
    for the settling and baseline asked for as durations gets a shortened baseline (a
    sixth of its records to settle, the next third, at least MIN_BASELINE_RECORDS, as the
    baseline) and a warning; counts, or durations longer than the defaults, asked for that
    do not fit are an InputError."""
    times = np.asarray(times, dtype=float)
    n = times.size
    settle, settle_n = rule["settle"], rule["settle_n"]
    first = settle_n if settle is None else int(np.searchsorted(times, settle - 1e-9))
    if rule["baseline"] is None:
        stop = first + rule["baseline_n"]
        parameter, value = "baseline_records", rule["baseline_n"]
    else:
        start = times[min(first, n - 1)]
        stop = max(
            int(np.searchsorted(times, start + rule["baseline"] - 1e-9)),
            first + BASELINE_MIN_RECORDS,
        )
        parameter, value = "baseline", rule["baseline"]
    if stop + window <= n:
        return first, stop
    # durations no longer than the defaults are shortened; a longer one asked for is refused
    by_duration = (
        rule["baseline"] is not None
        and rule["baseline"] <= BASELINE
        and (settle_n == 0 if settle is None else settle <= SETTLE)
    )
    short_first = min(first, int(SHORT_SETTLE * n))
    short_stop = short_first + max(int(SHORT_BASELINE * n), MIN_BASELINE_RECORDS)
    if by_duration and short_stop + min(window, MIN_BASELINE_RECORDS) <= n:
        warnings.append(
            f"the series is short ({n} records over {times[-1]:.6g} s) for the settling and "
            f"baseline asked for ({first} and {stop - first} records): the baseline was "
            f"shortened to records {short_first} to {short_stop - 1} ({times[short_first]:.6g} "
            f"to {times[short_stop - 1]:.6g} s), so its limits rest on fewer records and a "
            "running-in may still be in it"
        )
        return short_first, short_stop
    if stop < n:
        return first, stop
    asked = (
        f"{first} records of settling and {stop - first} of baseline; the series has {n} "
        f"records over {times[-1]:.6g} s"
    )
    raise InputError(
        parameter,
        value,
        "a baseline that ends before the series does (the records after it are the ones monitored)",
        hint=asked,
    )


def statistics(values: dict, tests) -> np.ndarray:
    """records x tests: the test statistics of the indicator ``values``."""
    return np.column_stack([STATISTICS[name](values[name][:, c]) for name, c in tests])


def spacing_of(times) -> float:
    """The records' spacing: the median time between consecutive records [s]."""
    times = np.asarray(times, dtype=float)
    return float(np.median(np.diff(times))) if times.size > 1 else 0.0


def evaluate(times, values, channels, first, stop, rule, calibration, warnings) -> dict:
    """The tests, their references and limits from the baseline records first..stop-1,
    the levels' deviations, each test's first crossing, the alarm and the short crossings
    (with the records' spacing, the level per record and the persistence window)."""
    spacing = spacing_of(times)
    level = level_per_record(rule["false_alarm_per_hour"], spacing)
    window = rule["persistence_n"]
    if window is None:
        window = window_count(rule["persistence"], spacing)
    tests = tuple((name, c) for name in INDICATORS for c in range(len(channels)))
    stats = statistics(values, tests)
    try:
        excess = calibration.limit(rule["false_alarm_per_hour"] / len(tests))
    except InputError:
        raise InputError(
            "false_alarm_per_hour",
            rule["false_alarm_per_hour"],
            f"a rate of at most {calibration.rate * len(tests):.3g} per hour over the "
            f"{len(tests)} tests: the rate of the healthy excursions above "
            f"{calibration.threshold:g} robust scales learned on {calibration.source}",
        ) from None
    refs = references(stats, slice(first, stop), excess)
    _, z = deviations(stats, slice(first, stop), window)
    crossings = first_crossings(z, excess)
    for j, p, rise in rising_baselines(times, stats, slice(first, stop), refs):
        name, c = tests[j]
        warnings.append(
            f"the baseline of {name} ({channels[c]}) still rises (Mann-Kendall p = {p:.2g}, "
            f"{math.expm1(rise):+.0%} over it): a running-in that goes on may raise the "
            "alarm; a longer settling time avoids it"
        )
    hits = [(a, j) for j, a in enumerate(crossings) if a is not None]
    alarm = None
    if hits:
        index, j = min(hits)
        name, c = tests[j]
        alarm = Alarm(index, name, channels[c], float(values[name][index, c]))
    monitored = len(times) - stop
    if monitored < window:
        warnings.append(
            f"no alarm can be raised: the persistence window holds {window} records and only "
            f"{monitored} are monitored after the baseline"
        )
    return {
        "false_alarm": level,
        "persistence": window,
        "record_spacing": spacing,
        "tests": tests,
        "limits": tuple(refs),
        "first_alarms": tuple(crossings),
        "alarm": alarm,
        "short_crossings": short_crossings(stats, refs, stop, alarm),
    }


def short_crossings(stats, refs, stop, alarm) -> tuple:
    """Runs of monitored records above a test's limit, before the alarm, that did not last
    long enough to carry the test's level over it: (first record, last record, test)."""
    end = stats.shape[0] if alarm is None else alarm.record + 1
    out = []
    for j, ref in enumerate(refs):
        above = stats[:end, j] > ref.limit
        above[:stop] = False
        for a, b in crossing_runs(above):
            if alarm is not None and b == alarm.record:
                continue  # the run that raised the alarm (or ended at it)
            out.append((a, b, j))
    out.sort()
    return tuple(out)


def measured_false_alarm(times, stats, first, stop, window, excess, alarm) -> dict | None:
    """The rule's false alarms counted on held-out healthy stretches of the series itself:
    baselines of the same number of records slid over the records before the alarm (less
    MEASURE_GUARD) or over all of them, each followed by the rest of that stretch; a firing
    is an excursion of some test's level above its limit. None when the stretch holds
    less than MEASURE_MIN_HOURS of monitoring."""
    times = np.asarray(times, dtype=float)
    n_base = stop - first
    end = times.size if alarm is None else int(np.searchsorted(times, times[alarm] - MEASURE_GUARD))
    fired = 0
    seconds = 0.0
    positions = 0
    for start in range(first, end, n_base):
        base = slice(start, start + n_base)
        if base.stop + window > end:
            break
        _, z = deviations(stats[:end], base, window)
        above = np.nan_to_num(z, nan=-np.inf) > np.asarray(excess)
        runs = crossing_runs(above.any(axis=1))
        fired += len(runs)
        seconds += float(times[end - 1] - times[base.stop + window - 1])
        positions += 1
    hours = seconds / 3600.0
    if hours < MEASURE_MIN_HOURS:
        return None
    return {
        "firings": fired,
        "hours": hours,
        "baselines": positions,
        "end": float(times[end - 1]),
    }
