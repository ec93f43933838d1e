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

from ..errors import InputError
from ..operating import speed_error
from .alarm import FALSE_ALARM_PER_HOUR, PERSISTENCE
from .blocks import block_size, diagnose_blocks
from .indicators import acceleration_unit, band_top
from .result import TrendResult
from .rule import BASELINE, SETTLE, baseline_span, evaluate, settings
from .series import list_records


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
    max_frequency: float | None = None,
    unit: str | None = None,
    machine: str | None = None,
    bearing=None,
    shaft_speed: float | None = None,
    learn_from=None,
    jobs: int = 1,
    scheduler: str | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> TrendResult:
    """The trend of a machine over the recordings of ``folder``: indicators, baseline,
    alarm, diagnosis, severity and remaining life.

    Parameters
    ----------
    folder : str or Path
        PRONOSTIA snapshots (``acc_NNNNN.csv``), or records ``analyze`` reads with an
        ``index.csv`` (file, time_s) or a time in their metadata (:mod:`.series`).
    channels : str or sequence of str, optional
        Channels to trend (PRONOSTIA: ``horizontal``, ``vertical``); default all.
    sample_rate : float, optional
        Sample rate [Hz] where the files do not store it (PRONOSTIA: 25600); a rate
        that differs from the one the files store is used, with a warning.
    settle, settle_records : float or int
        The records of the first ``settle`` seconds (or the first ``settle_records``
        records) are not in the baseline: a new bearing runs in [s]. A count wins.
    baseline, baseline_records : float or int
        The baseline after the settling: a duration [s] (holding at least 30 records:
        it is extended when the records are sparse), or a count of records (at least
        10). A count wins. A series too short for durations gets a shortened baseline,
        with a warning.
    false_alarm_per_hour : float
        Rate of false alarms of the rule per hour of monitoring, all tests together
        [1/h]: the limits come from the excursion rates of healthy operation learned on
        runs to failure (:mod:`.calibration`); the level per record is this times the
        records' spacing over 3600 s (at most 0.1).
    persistence, persistence_records : float or int
        The persistence window: each test's level is the median of its records over the
        last ``persistence`` seconds [s] (at least 3 records), or over the last
        ``persistence_records`` records (1 to 360). A count wins.
    max_frequency : float, optional
        Top of the indicators' band [Hz]; default a quarter of the sample rate
        (:mod:`.indicators`).
    unit : str, optional
        The channels' unit, ``g`` or ``m/s2``: adds their r.m.s. velocity over 10-1000 Hz.
    machine : str, optional
        Machine group of the ISO 20816 zones (:data:`.severity.MACHINES`); needs ``unit``.
    bearing : BallBearing, optional
        With ``shaft_speed``: each fault family's significance, by the diagnosis.
    shaft_speed : float, optional
        Shaft speed [rad/s].
    learn_from : str, Path or LearnedRuns, optional
        Runs to failure to learn the alarm's calibration and the lives from: a folder of
        runs (one sub-folder each), a file written by ``LearnedRuns.write``, or a
        :class:`~.learning.LearnedRuns`; default the six PRONOSTIA learning runs
        (package data, :mod:`.learning`).
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
    from ..engine import check_progress, open_jobs
    from .learning import learned_from
    from .reading import probe, read_series
    from .rule import measured_false_alarm, statistics

    rule = settings(
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
    learned = learned_from(learn_from)
    listing = list_records(folder)
    channels, first_record = probe(listing, channels, sample_rate)
    top = band_top(first_record.sample_rate, max_frequency)
    size = None if kin is None else block_size(first_record, kin)
    total = len(listing.files)
    work = total + (0 if size is None else total + size)
    progress = check_progress(progress)
    with open_jobs(jobs, scheduler) as runner:
        series = read_series(listing, channels, sample_rate, unit, top, runner, (progress, work))
        warnings = list(series.warnings)
        times, values = series.times, series.values
        window = _window(rule, times)
        first, stop = baseline_span(times, rule, window, warnings)
        evaluation = evaluate(
            times, values, channels, first, stop, rule, learned.calibration, warnings
        )
        alarm = evaluation["alarm"]
        measured = measured_false_alarm(
            times,
            statistics(values, evaluation["tests"]),
            first,
            stop,
            evaluation["persistence"],
            evaluation["limits"][0].excess,
            None if alarm is None else alarm.record,
        )
        diagnosis = None
        if kin is not None:
            diagnosis = diagnose_blocks(
                runner,
                series.listing,
                channels[0],
                sample_rate,
                kin,
                size,
                alarm,
                (progress, total, work),
            )
            if diagnosis is None:
                warnings.append(
                    f"no diagnosis: three cage revolutions need {size} consecutive records and "
                    f"the series has {len(series.files)}"
                )
    result = TrendResult(
        folder=str(folder),
        layout=listing.layout,
        channels=tuple(channels),
        sample_rate=series.sample_rate,
        record_samples=series.record_samples,
        unit=unit,
        start=series.start,
        files=series.files,
        times=times,
        values=values,
        velocity=series.velocity,
        zones=zones,
        settle_records=first,
        baseline_stop=stop,
        false_alarm_per_hour=rule["false_alarm_per_hour"],
        max_frequency=top,
        learned=learned,
        measured=measured,
        diagnosis=diagnosis,
        **evaluation,
        warnings=tuple(warnings),
    )
    return _with_life(result)


def _with_life(result: TrendResult) -> TrendResult:
    """``result`` with its remaining-life estimate (:mod:`.life`)."""
    from dataclasses import replace

    from .life import remaining_life

    estimate = remaining_life(result)
    return replace(result, remaining_life=estimate)


def _window(rule: dict, times) -> int:
    """Records in the persistence window at the records' spacing."""
    from .alarm import window_count
    from .rule import spacing_of

    if rule["persistence_n"] is not None:
        return rule["persistence_n"]
    return window_count(rule["persistence"], spacing_of(times))
