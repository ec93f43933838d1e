"""trend_records: the trend of a machine over a series of recordings (layer 3).

Steps: list the folder (:mod:`.series`); read the records in chunks, in this process or
on dask workers (:mod:`.tasks`), into their health indicators (:mod:`.indicators`); put
them in time order; learn the baseline after the settling time and test every indicator
of every channel against it (:mod:`.alarm`); when the bearing and the speed are given,
run the diagnosis over blocks of consecutive records and at the alarm; place the velocity
in the ISO 20816 zones when the unit and the machine group are given (:mod:`.severity`).

**The diagnosis of short records.** The diagnosis refuses a record shorter than three
cage revolutions (``MIN_CAGE_REVOLUTIONS`` of :mod:`bearinglab.diagnosis.analysis`): a
0.1 s PRONOSTIA snapshot of its bearing at 1800 rpm holds 1.3. A family's significance
is therefore computed over a block of the fewest consecutive records that hold three
cage revolutions, joined end to end, and every record of a block carries the block's
result; at the alarm, the block is the records ending at the alarm record. Joining
independent snapshots keeps each fault's lines (the envelope spectrum of the joined
record is close to the average of the snapshots' spectra, each line widened by the
snapshot's 1/T) and adds small steps at the joins; on simulated PRONOSTIA-like snapshots
(docs/capabilities/trend.md) it finds what a continuous record of the same length does.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ..errors import InputError
from .alarm import (
    FALSE_ALARM,
    MAX_PERSISTENCE_RECORDS,
    MIN_BASELINE_RECORDS,
    PERSISTENCE,
    STATISTICS,
    baseline_limits,
    check_false_alarm,
    first_alarms,
    persistence_count,
    rising_baselines,
)
from .indicators import INDICATORS, acceleration_unit
from .result import Alarm, BlockDiagnosis, TrendResult
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


def _runner(jobs, scheduler):
    """Where the work runs: this process, a LocalCluster of ``jobs`` workers, or a
    scheduler (:func:`bearinglab.study.execute.open_runner`)."""
    from ..machine import most_processes
    from ..study.execute import open_runner

    most = most_processes()
    if isinstance(jobs, bool) or not isinstance(jobs, (int, np.integer)) or not 1 <= jobs <= most:
        raise InputError("jobs", jobs, f"an integer in [1, {most}] (4 per core)")
    if scheduler is None:
        return open_runner("serial" if jobs == 1 else "local", workers=int(jobs))
    return open_runner(scheduler, workers=int(jobs) if scheduler == "local" else None)


def _sub(listing: Listing, part) -> Listing:
    """The records ``part`` (indices) of ``listing``."""
    times = None if listing.times is None else tuple(listing.times[i] for i in part)
    return Listing(listing.folder, listing.layout, tuple(listing.files[i] for i in part), times)


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


def _blocks(count: int, size: int) -> list[np.ndarray]:
    """Consecutive blocks of ``size`` of ``count`` records (the last one ends at the last
    record, so that every block holds ``size`` records).

    >>> [b.tolist() for b in _blocks(7, 3)]
    [[0, 1, 2], [3, 4, 5], [4, 5, 6]]
    """
    starts = list(range(0, count - size + 1, size))
    if starts and starts[-1] + size < count:
        starts.append(count - size)
    return [np.arange(s, s + size) for s in starts]


def _block_size(record: Record, frequencies) -> int:
    """Fewest consecutive records that hold the diagnosis' minimum of cage revolutions."""
    from ..diagnosis.analysis import MIN_CAGE_REVOLUTIONS

    duration = record.samples.shape[-1] / record.sample_rate
    return max(1, math.ceil(MIN_CAGE_REVOLUTIONS / (duration * frequencies.hz("ftf")) - 1e-9))


def trend_records(
    folder,
    *,
    channels=None,
    sample_rate: float | None = None,
    settle: float | None = SETTLE,
    settle_records: int | None = None,
    baseline: float | None = BASELINE,
    baseline_records: int | None = None,
    false_alarm: float = FALSE_ALARM,
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
    false_alarm : float
        Probability that the rule raises a false alarm at a given record, all tests
        together, in (0, 0.1] (:mod:`.alarm`).
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
        Worker processes (a dask LocalCluster); 1: this process.
    scheduler : str, optional
        A dask scheduler address (or "local", "serial") instead.
    progress : callable, optional
        Called with (work done, work in all), counted in records read, as it goes.

    Returns
    -------
    TrendResult

    Examples
    --------
    >>> from pathlib import Path
    >>> run = Path(__file__).resolve().parents[4] / "shared/data/run-to-failure/Bearing3_1"
    >>> if run.is_dir():  # doctest: +SKIP
    ...     result = trend_records(run)
    ...     result.alarm.indicator, round(result.times[result.alarm.record])
    """
    from ..study.execute import run_partitions

    rule_p = check_false_alarm(false_alarm)
    persist_s, persist_n = _length("persistence", persistence, persistence_records)
    if persist_n is not None and not 1 <= persist_n <= MAX_PERSISTENCE_RECORDS:
        raise InputError(
            "persistence_records",
            persist_n,
            f"a number of records in [1, {MAX_PERSISTENCE_RECORDS}]",
        )
    if persist_s is not None and persist_s <= 0:
        raise InputError("persistence", persistence, "a duration > 0 s")
    settle_s, settle_n = _length("settle", settle, settle_records)
    base_s, base_n = _length("baseline", baseline, baseline_records)
    if base_n is not None and base_n < MIN_BASELINE_RECORDS:
        raise InputError("baseline_records", base_n, f"at least {MIN_BASELINE_RECORDS} records")
    unit = acceleration_unit(unit)
    zones = None
    if machine is not None:
        from .severity import machine_zones

        zones = machine_zones(machine)
        if unit is None:
            raise InputError(
                "unit",
                None,
                f"the channels' unit (g or m/s2), to place their velocity in the zones of "
                f"{machine}",
            )
    if (bearing is None) != (shaft_speed is None):
        raise InputError(
            "shaft_speed" if bearing is not None else "bearing",
            None,
            "the bearing and the shaft speed together, for the diagnosis (or neither)",
        )
    kin = None
    if bearing is not None:
        from ..kinematics import defect_frequencies

        try:
            speed = float(shaft_speed)
        except (TypeError, ValueError):
            speed = math.nan
        if not (math.isfinite(speed) and speed > 0):
            raise InputError("shaft_speed", shaft_speed, "a speed > 0 rad/s")
        kin = defect_frequencies(bearing, speed)
    listing = list_records(folder)
    channels, probe = _probe(listing, channels, sample_rate)
    size = None if kin is None else _block_size(probe, kin)
    total = len(listing.files)
    work = total + (0 if size is None else total + size)
    warnings: list[str] = []
    if listing.unlisted:
        warnings.append(
            f"{len(listing.unlisted)} record file(s) of the folder are not in index.csv and "
            f"were left out (e.g. {listing.unlisted[0]})"
        )
    done = [0]

    def advance(n: int) -> None:
        done[0] += n
        if progress:
            progress(min(done[0], work), work)

    rows: list[dict] = []
    parts = [range(s, min(s + CHUNK, total)) for s in range(0, total, CHUNK)]
    tasks = [(_sub(listing, p), channels, sample_rate, unit, p.start) for p in parts]
    from .tasks import read_chunk

    with _runner(jobs, scheduler) as runner:
        run_partitions(
            runner,
            read_chunk,
            tasks,
            [len(p) for p in parts],
            lambda task, result: (rows.extend(result), advance(len(task[0].files))),
        )
        good = _good_rows(listing, rows, warnings, folder)
        clock = _clock(listing, good, warnings)
        order = np.lexsort((np.array([r["file"] for r in good]), clock))
        good = [good[i] for i in order]
        clock = clock[order]
        times = clock - clock[0]
        first, stop = _baseline(times, settle_s, settle_n, base_s, base_n)
        values = {
            name: np.array([r["values"][name] for r in good], dtype=float) for name in INDICATORS
        }
        spacing = float(np.median(np.diff(times))) if times.size > 1 else 0.0
        rule_r = persist_n if persist_n is not None else persistence_count(persist_s, spacing)
        tests = tuple((name, c) for name in INDICATORS for c in range(len(channels)))
        stats = np.column_stack([STATISTICS[name](values[name][:, c]) for name, c in tests])
        limits = baseline_limits(stats, slice(first, stop), rule_p / len(tests), rule_r)
        alarms = first_alarms(stats, limits, stop, rule_r)
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
        diagnosis = None
        if kin is not None:
            files = Listing(
                listing.folder,
                listing.layout,
                tuple(r["file"] for r in good),
                None if listing.times is None else tuple(r["time"] for r in good),
            )
            diagnosis = _diagnose(
                runner, files, channels[0], sample_rate, kin, size, alarm, advance
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
        false_alarm=rule_p,
        persistence=rule_r,
        record_spacing=spacing,
        tests=tests,
        limits=tuple(limits),
        first_alarms=tuple(alarms),
        alarm=alarm,
        diagnosis=diagnosis,
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


def _diagnose(runner, files: Listing, channel, sample_rate, kin, size, alarm, advance):
    """The diagnosis over blocks of ``size`` consecutive records of ``files`` (time order)
    and over the block ending at the alarm; None when the series is shorter than a block."""
    from ..study.execute import run_partitions
    from .tasks import diagnose_block

    count = len(files.files)
    if size > count:
        return None
    blocks = _blocks(count, size)
    extra = []
    if alarm is not None and alarm.record >= size - 1:
        extra = [np.arange(alarm.record - size + 1, alarm.record + 1)]
    tasks = [(_sub(files, b), channel, sample_rate, kin) for b in (*blocks, *extra)]
    outcome: dict[int, dict] = {}

    def collect(task, result):
        outcome[id(task)] = result
        advance(len(task[0].files))

    run_partitions(runner, diagnose_block, tasks, [size] * len(tasks), collect)
    results = [outcome[id(t)] for t in tasks]
    if all("error" in r for r in results):
        raise InputError(*results[0]["error"])
    return BlockDiagnosis.from_blocks(
        channel,
        size,
        kin,
        blocks,
        results[: len(blocks)],
        results[len(blocks)] if extra else None,
        count,
    )
