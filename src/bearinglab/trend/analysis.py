"""trend_records: the trend of a machine over a series of recordings (layer 3).

Steps: list the folder (:mod:`.series`); read the records in chunks, in this process or
on dask workers (:mod:`.tasks`), into their health indicators (:mod:`.indicators`); put
them in time order; learn the baseline after the settling time and test every indicator
of every channel against it (:mod:`.alarm`); when the bearing and the speed are given,
run the diagnosis over blocks of consecutive records and at the alarm (:mod:`.blocks`);
place the velocity in the ISO 20816 zones when the unit and the machine group are given
(:mod:`.severity`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ..errors import InputError
from ..operating import speed_error
from .alarm import (
    FALSE_ALARM_PER_HOUR,
    MAX_PERSISTENCE_RECORDS,
    MIN_BASELINE_RECORDS,
    PERSISTENCE,
    STATISTICS,
    baseline_limits,
    check_false_alarm_per_hour,
    first_alarms,
    level_per_record,
    persistence_count,
    rising_baselines,
)
from .blocks import block_size, diagnose_blocks
from .indicators import INDICATORS, acceleration_unit
from .result import Alarm, TrendResult
from .series import Listing, Record, list_records, read_record, snapshot_number, snapshot_times

#: Default settling time: the records of the first 10 minutes are not in the baseline [s].
SETTLE = 600.0
#: Default baseline length after the settling time [s]: 20 minutes, so that the baseline
#: sees some of the slow wander of a running machine, not only its record-to-record scatter.
BASELINE = 1200.0
#: Fewest records a baseline given as a duration holds: a shorter one is extended.
BASELINE_MIN_RECORDS = 30
#: Records read per task.
CHUNK = 64
#: Files named one by one in the warning about unreadable records.
NAMED = 10


def _length(name: str, seconds, records) -> tuple[float | None, int | None]:
    """A settling or baseline length: (duration [s], None) or (None, count); a count
    given wins."""
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


def _probe(listing: Listing, channels, sample_rate) -> tuple[tuple[str, ...], Record]:
    """The channels to trend (the user's, checked against the first readable record, or
    all of its channels) and that record."""
    first_error = None
    for i in range(len(listing.files)):
        try:
            record = read_record(listing, i, None, sample_rate)
        except InputError as exc:
            if exc.parameter in ("sample_rate", "sample_rate_hz"):
                raise
            first_error = first_error or str(exc)
            continue
        if channels is None:
            return record.channels, record
        wanted = (channels,) if isinstance(channels, str) else tuple(channels)
        if not wanted or len(set(wanted)) != len(wanted):
            raise InputError("channels", list(wanted), "one or more distinct channel names")
        for c in wanted:
            if c not in record.channels:
                raise InputError("channels", c, f"channels of the records: {list(record.channels)}")
        return wanted, record
    raise InputError(
        "folder",
        listing.folder,
        "a folder with at least one readable recording",
        hint=f"none of its {len(listing.files)} records could be read: {first_error}",
    )


def _skipped(failures: list[dict]) -> list[str]:
    """The warning about the records skipped, naming them."""
    if not failures:
        return []
    named = "; ".join(f["error"] for f in failures[:NAMED])
    more = f" (and {len(failures) - NAMED} more)" if len(failures) > NAMED else ""
    return [f"{len(failures)} record(s) skipped: {named}{more}"]


def _baseline(times, settle, settle_n, baseline, baseline_n) -> tuple[int, int]:
    """(first, stop) indices of the baseline in the time-ordered series."""
    n = times.size
    first = settle_n if settle is None else int(np.searchsorted(times, settle - 1e-9))
    if baseline is None:
        stop = first + baseline_n
        parameter, value = "baseline_records", baseline_n
    else:
        start = times[min(first, n - 1)]
        stop = max(
            int(np.searchsorted(times, start + baseline - 1e-9)), first + BASELINE_MIN_RECORDS
        )
        parameter, value = "baseline", baseline
    if stop >= n:
        asked = (
            f"{first} records of settling and {stop - first} of baseline; the series has {n} "
            f"records over {times[-1]:.6g} s"
        )
        raise InputError(
            parameter,
            value,
            "a baseline that ends before the series does (the records after it are the ones "
            "monitored)",
            hint=asked,
        )
    return first, stop


def _rule(rate, persistence, persistence_n, settle, settle_n, baseline, baseline_n) -> dict:
    """The rule's settings, checked: the false-alarm rate per hour, persistence (s or
    records), settle and baseline (s or records)."""
    p = check_false_alarm_per_hour(rate)
    persist_s, persist_n = _length("persistence", persistence, persistence_n)
    if persist_n is not None and not 1 <= persist_n <= MAX_PERSISTENCE_RECORDS:
        raise InputError(
            "persistence_records",
            persist_n,
            f"a number of records in [1, {MAX_PERSISTENCE_RECORDS}]",
        )
    if persist_s is not None and persist_s <= 0:
        raise InputError("persistence", persistence, "a duration > 0 s")
    settle_s, settle_count = _length("settle", settle, settle_n)
    base_s, base_count = _length("baseline", baseline, baseline_n)
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


def _severity(unit, machine):
    """(the channels' unit, the machine's ISO zones or None), checked together."""
    unit = acceleration_unit(unit)
    if machine is None:
        return unit, None
    from .severity import machine_zones

    zones = machine_zones(machine)
    if unit is None:
        raise InputError(
            "unit",
            None,
            f"the channels' unit (g or m/s2), to place their velocity in the zones of {machine}",
        )
    return unit, zones


def _frequencies(bearing, shaft_speed):
    """The bearing's kinematic frequencies at the shaft speed, or None without either."""
    if (bearing is None) != (shaft_speed is None):
        raise InputError(
            "shaft_speed" if bearing is not None else "bearing",
            None,
            "the bearing and the shaft speed together, for the diagnosis (or neither)",
        )
    if bearing is None:
        return None
    from ..kinematics import defect_frequencies

    try:
        speed = float(shaft_speed)
    except (TypeError, ValueError):
        speed = math.nan
    if not (math.isfinite(speed) and speed > 0):
        raise speed_error(shaft_speed, "a speed > 0 rpm")
    return defect_frequencies(bearing, speed)


def _evaluate(times, values, channels, first, stop, rule, warnings) -> dict:
    """The tests, their limits from the baseline records first..stop-1, their first
    alarms and the alarm (with the record spacing, the level per record and the
    persistence they give)."""
    spacing = float(np.median(np.diff(times))) if times.size > 1 else 0.0
    level = level_per_record(rule["false_alarm_per_hour"], spacing)
    r = rule["persistence_n"]
    if r is None:
        r = persistence_count(rule["persistence"], spacing)
    tests = tuple((name, c) for name in INDICATORS for c in range(len(channels)))
    stats = np.column_stack([STATISTICS[name](values[name][:, c]) for name, c in tests])
    limits = baseline_limits(stats, slice(first, stop), level / len(tests), r)
    alarms = first_alarms(stats, limits, stop, r)
    for j, p, rise in rising_baselines(times, stats, slice(first, stop), limits):
        name, c = tests[j]
        warnings.append(
            f"the baseline of {name} ({channels[c]}) still rises (Mann-Kendall p = {p:.2g}, "
            f"{math.expm1(rise):+.0%} over it): a running-in that goes on may raise the "
            "alarm; a longer settling time avoids it"
        )
    hits = [(a, j) for j, a in enumerate(alarms) if a is not None]
    alarm = None
    if hits:
        index, j = min(hits)
        name, c = tests[j]
        alarm = Alarm(index, name, channels[c], float(values[name][index, c]))
    return {
        "false_alarm": level,
        "persistence": r,
        "record_spacing": spacing,
        "tests": tests,
        "limits": tuple(limits),
        "first_alarms": tuple(alarms),
        "alarm": alarm,
    }


def trend_records(
    folder,
    *,
    channels=None,
    sample_rate: float | None = None,
    settle: float | None = SETTLE,
    settle_records: int | None = None,
    baseline: float | None = BASELINE,
    baseline_records: int | None = None,
    false_alarm_per_hour: float = FALSE_ALARM_PER_HOUR,
    persistence: float | None = PERSISTENCE,
    persistence_records: int | None = None,
    unit: str | None = None,
    machine: str | None = None,
    bearing=None,
    shaft_speed: float | None = None,
    jobs: int = 1,
    scheduler: str | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> TrendResult:
    """The trend of a machine over the recordings of ``folder``: indicators, baseline,
    alarm, diagnosis and severity.

    Parameters
    ----------
    folder : str or Path
        PRONOSTIA snapshots (``acc_NNNNN.csv``), or records ``analyze`` reads with an
        ``index.csv`` (file, time_s) or a time in their metadata (:mod:`.series`).
    channels : str or sequence of str, optional
        Channels to trend (PRONOSTIA: ``horizontal``, ``vertical``); default all.
    sample_rate : float, optional
        Sample rate [Hz] where the files do not store it (PRONOSTIA: 25600).
    settle, settle_records : float or int
        The records of the first ``settle`` seconds (or the first ``settle_records``
        records) are not in the baseline: a new bearing runs in [s]. A count wins.
    baseline, baseline_records : float or int
        The baseline after the settling: a duration [s] (holding at least 30 records:
        it is extended when the records are sparse), or a count of records (at least
        10). A count wins.
    false_alarm_per_hour : float
        Rate of false alarms of the rule per hour of monitoring, all tests together, in
        (0, 1] [1/h]: the level per record is this times the records' spacing over 3600 s
        (:mod:`.alarm`).
    persistence, persistence_records : float or int
        How long records above a limit must last to raise the alarm: a duration [s]
        (the records spanning it at the series' cadence, at least 2), or a count of
        consecutive records (1 to 50). A count wins.
    unit : str, optional
        The channels' unit, ``g`` or ``m/s2``: adds their r.m.s. velocity over 10-1000 Hz.
    machine : str, optional
        Machine group of the ISO 20816 zones (:data:`.severity.MACHINES`); needs ``unit``.
    bearing : BallBearing, optional
        With ``shaft_speed``: each fault family's significance, by the diagnosis.
    shaft_speed : float, optional
        Shaft speed [rad/s].
    jobs : int
        Worker processes (a pool, :func:`bearinglab.engine.open_jobs`); 1: this process.
    scheduler : str, optional
        A dask scheduler address (or "local", "serial") instead.
    progress : callable, optional
        ``progress(done, total)``, counted in records read (and, with the diagnosis, in
        records diagnosed), as it goes (:mod:`bearinglab.engine`).

    Returns
    -------
    TrendResult
    """
    from ..engine import check_progress, open_jobs, run_partitions
    from .tasks import read_chunk

    rule = _rule(
        false_alarm_per_hour,
        persistence,
        persistence_records,
        settle,
        settle_records,
        baseline,
        baseline_records,
    )
    unit, zones = _severity(unit, machine)
    kin = _frequencies(bearing, shaft_speed)
    listing = list_records(folder)
    channels, probe = _probe(listing, channels, sample_rate)
    size = None if kin is None else block_size(probe, kin)
    total = len(listing.files)
    work = total + (0 if size is None else total + size)
    warnings: list[str] = []
    if listing.unlisted:
        warnings.append(
            f"{len(listing.unlisted)} record file(s) of the folder are not in index.csv and "
            f"were left out (e.g. {listing.unlisted[0]})"
        )
    progress = check_progress(progress)
    rows: list[dict] = []
    parts = [range(s, min(s + CHUNK, total)) for s in range(0, total, CHUNK)]
    tasks = [(listing.subset(p), channels, sample_rate, unit, p.start) for p in parts]
    with open_jobs(jobs, scheduler) as runner:
        run_partitions(
            runner,
            read_chunk,
            tasks,
            [len(p) for p in parts],
            lambda task, result: rows.extend(result),
            progress=progress,
            total=work,
        )
        good = _good_rows(listing, rows, warnings, folder)
        clock = _clock(listing, good, warnings)
        order = np.lexsort((np.array([r["file"] for r in good]), clock))
        good = [good[i] for i in order]
        clock = clock[order]
        times = clock - clock[0]
        first, stop = _baseline(
            times, rule["settle"], rule["settle_n"], rule["baseline"], rule["baseline_n"]
        )
        values = {
            name: np.array([r["values"][name] for r in good], dtype=float) for name in INDICATORS
        }
        evaluation = _evaluate(times, values, channels, first, stop, rule, warnings)
        diagnosis = None
        if kin is not None:
            files = Listing(
                listing.folder,
                listing.layout,
                tuple(r["file"] for r in good),
                None if listing.times is None else tuple(r["time"] for r in good),
            )
            alarm = evaluation["alarm"]
            diagnosis = diagnose_blocks(
                runner, files, channels[0], sample_rate, kin, size, alarm, (progress, total, work)
            )
            if diagnosis is None:
                warnings.append(
                    f"no diagnosis: three cage revolutions need {size} consecutive records and "
                    f"the series has {len(good)}"
                )
    velocity = None if unit is None else np.array([r["velocity"] for r in good], dtype=float)
    return TrendResult(
        folder=str(folder),
        layout=listing.layout,
        channels=tuple(channels),
        sample_rate=float(good[0]["sample_rate"]),
        record_samples=int(good[0]["samples"]),
        unit=unit,
        start=float(clock[0]),
        files=tuple(r["file"] for r in good),
        times=times,
        values=values,
        velocity=velocity,
        zones=zones,
        settle_records=first,
        baseline_stop=stop,
        false_alarm_per_hour=rule["false_alarm_per_hour"],
        diagnosis=diagnosis,
        **evaluation,
        warnings=tuple(warnings),
    )


def _clock(listing: Listing, good: list[dict], warnings: list[str]) -> np.ndarray:
    """The records' times [s]: PRONOSTIA clocks in the order of the snapshot numbers (a
    clock out of that order replaced, with a warning naming the file), or the index's or
    files' own times (put in time order, with a note when the listing was not)."""
    clock = np.array([r["time"] for r in good])
    if listing.layout == "pronostia":
        numbers = [snapshot_number(r["file"]) for r in good]
        clock, bad = snapshot_times(numbers, clock)
        if bad.size:
            from .series import time_of_day

            named = ", ".join(
                f"{good[i]['file']} (its clock reads {time_of_day(good[i]['time'])})"
                for i in bad[:NAMED]
            )
            warnings.append(
                f"{bad.size} snapshot(s) with a clock out of the order of their numbers, timed "
                f"by their number between their neighbours instead: {named}"
            )
    elif np.any(np.diff(clock) < 0):
        warnings.append(
            "the records are not in time order in the folder listing: they were put in time order"
        )
    return clock


def _good_rows(listing: Listing, rows: list[dict], warnings: list[str], folder) -> list[dict]:
    """The records read (in listing order), after warning about those skipped; InputError
    when none was read or their sample rates differ."""
    failures = sorted((r for r in rows if "error" in r), key=lambda r: r["index"])
    good = sorted((r for r in rows if "error" not in r), key=lambda r: r["index"])
    warnings += _skipped(failures)
    if not good:
        raise InputError(
            "folder",
            str(folder),
            "a folder with at least one readable recording",
            hint=failures[0]["error"] if failures else "",
        )
    fs = good[0]["sample_rate"]
    for r in good:
        if not math.isclose(r["sample_rate"], fs, rel_tol=1e-9):
            raise InputError(
                "folder",
                r["file"],
                f"records of one sample rate ({fs:g} Hz, as {good[0]['file']})",
                hint=f"{r['file']} is at {r['sample_rate']:g} Hz",
            )
    return good
