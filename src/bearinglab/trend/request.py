"""The ``trend`` request: its inputs (entries of :data:`bearinglab.inputs.INPUTS` and the
trend's own) and :func:`trend_from`, which builds the bearing from them and calls
:func:`~bearinglab.trend.analysis.trend_records` once; its errors name the input."""

from __future__ import annotations

from dataclasses import replace

from ..analyses.base import FILES, Analysis, plot_file
from ..errors import InputError
from ..inputs import (
    BEARING,
    INPUTS,
    Input,
    bearing_from,
    bearing_warnings,
    check,
    input_for,
    restate,
    speed_from,
)
from .alarm import FALSE_ALARM_PER_HOUR, MAX_WINDOW_RECORDS, PERSISTENCE
from .analysis import BASELINE, SETTLE

#: The trend's inputs besides the bearing, in the order the command line lists them.
TREND_INPUTS: dict[str, Input] = {
    "folder": INPUTS["folder"].with_(
        help="Folder of recordings: PRONOSTIA snapshots acc_NNNNN.csv as published, or records "
        "analyze reads (.npz, .csv, .wav, .mat) with an index.csv (file, time_s) or a time_s "
        "in their metadata.",
        sets=("path", "index.csv", "time_s", "time"),
    ),
    "channel": INPUTS["channel"].with_(
        kind="texts",
        help="Channel to trend (repeatable; PRONOSTIA: horizontal, vertical); default all. The "
        "diagnosis uses the first.",
        sets="channels",
    ),
    "sample_rate_hz": INPUTS["sample_rate_hz"].with_(
        help="Sample rate [Hz] where the files do not store it (PRONOSTIA: 25600)."
    ),
    "running_in_s": Input(
        "number",
        None,
        f"Running-in left out of the baseline: the records of the first seconds [s] "
        f"(default {SETTLE:g} s).",
        aliases=("settle_s",),
        sets="settle",
    ),
    "running_in_records": Input(
        "integer",
        None,
        "Running-in as a number of records instead.",
        aliases=("settle_records",),
        sets="settle_records",
    ),
    "baseline_s": Input(
        "number",
        None,
        f"Baseline after the running-in [s] (default {BASELINE:g} s); at least 30 records "
        "(extended when the records are sparse).",
    ),
    "baseline_records": Input("integer", None, "Baseline as a number of records instead (>= 10)."),
    "false_alarm_per_hour": Input(
        "number",
        FALSE_ALARM_PER_HOUR,
        "Rate of false alarms per hour of monitoring, all indicators and channels together: "
        "the limits are where healthy operation of the learning runs crosses them at this "
        "rate; the level per record is this times the records' spacing over 3600 s (at "
        "most 0.1).",
        low=0.0,
        low_open=True,
        what="a rate per hour",
    ),
    "persistence_s": Input(
        "number",
        None,
        f"Persistence window [s] (default {PERSISTENCE:g} s): each indicator's level is its "
        "median over the records of the last window (at least 3), so that a burst shorter "
        "than half of it raises no alarm.",
    ),
    "persistence_records": Input(
        "integer",
        None,
        f"Persistence window as a number of records instead (1 to {MAX_WINDOW_RECORDS}).",
    ),
    "max_frequency_hz": Input(
        "number",
        None,
        "Top of the indicators' band [Hz] (default a quarter of the sample rate: above it "
        "lie the anti-aliasing roll-off and the surface transients of a healthy bearing).",
        low=0.0,
        low_open=True,
        what="a frequency",
    ),
    "learn_from": Input(
        "path",
        None,
        "Runs to failure to learn the alarm's limits and the lives from: a folder with one "
        "sub-folder of recordings per run (each from new to failure), or a file written by "
        "LearnedRuns.write; default the six PRONOSTIA learning runs shipped with bearinglab.",
    ),
    "unit": Input(
        "text",
        None,
        "The channels' unit, g or m/s2: adds the r.m.s. velocity over 10-1000 Hz (PRONOSTIA: g).",
    ),
    "machine": Input(
        "text",
        None,
        "Machine group for the ISO 20816 zones: group1-rigid, group1-flexible, group2-rigid, "
        "group2-flexible (ISO 20816-3), class1..class4 (ISO 10816-1); needs unit.",
    ),
    "speed_rpm": INPUTS["speed_rpm"].with_(help="Shaft speed [rpm], for the diagnosis."),
    "jobs": INPUTS["jobs"].with_(sets="workers"),
    "scheduler": INPUTS["scheduler"].with_(
        help="A dask scheduler address (tcp://HOST:PORT), 'local' or 'serial', instead of `jobs`."
    ),
    **{name: INPUTS[name] for name in BEARING},
}
TREND_INPUTS["designation"] = TREND_INPUTS["designation"].with_(
    help="Bearing designation, or give the geometry: with `speed_rpm`, each fault family's "
    "significance by the diagnosis.",
    sets="bearing",
)

#: Inputs whose errors name the file or channel at fault: the error's value, not the one
#: given, is shown.
_AT_FAULT = ("folder", "channel", "learn_from")


def trend_from(values: dict, *, progress=None):
    """The TrendResult of a request (``values``: name -> value in its unit), on `jobs`
    processes or the dask `scheduler`; its warnings include the bearing's.
    ``progress(done, total)`` is called as records are read."""
    from .analysis import trend_records

    check(values, TREND_INPUTS)
    for seconds in ("running_in", "baseline", "persistence"):
        if values.get(f"{seconds}_s") is not None and values.get(f"{seconds}_records") is not None:
            raise InputError(
                f"{seconds}_records",
                values[f"{seconds}_records"],
                f"one of `{seconds}_s` and `{seconds}_records`",
            )
    bearing = decoded = None
    if any(values.get(name) is not None for name in BEARING):
        bearing, decoded = bearing_from(values)
    shaft_speed = None if values.get("speed_rpm") is None else speed_from(values)
    try:
        result = trend_records(
            values["folder"],
            channels=values.get("channel") or None,
            sample_rate=values.get("sample_rate_hz"),
            settle=SETTLE if values.get("running_in_s") is None else values["running_in_s"],
            settle_records=values.get("running_in_records"),
            baseline=BASELINE if values.get("baseline_s") is None else values["baseline_s"],
            baseline_records=values.get("baseline_records"),
            false_alarm_per_hour=values.get("false_alarm_per_hour", FALSE_ALARM_PER_HOUR),
            persistence=PERSISTENCE
            if values.get("persistence_s") is None
            else values["persistence_s"],
            persistence_records=values.get("persistence_records"),
            max_frequency=values.get("max_frequency_hz"),
            learn_from=values.get("learn_from"),
            unit=values.get("unit"),
            machine=values.get("machine"),
            bearing=bearing,
            shaft_speed=shaft_speed,
            jobs=values.get("jobs") or 1,
            scheduler=values.get("scheduler"),
            progress=progress,
        )
    except InputError as exc:
        name = input_for(exc.parameter, TREND_INPUTS)
        if name in _AT_FAULT:
            raise InputError(name, exc.value, exc.allowed, exc.hint) from None
        raise restate(exc, values, TREND_INPUTS) from None
    if bearing is None:
        return result
    return replace(result, warnings=(*result.warnings, *bearing_warnings(bearing, decoded)))


TREND = Analysis(
    "trend",
    "The trend of a machine over a series of recordings (trend_records).",
    TREND_INPUTS,
    run=trend_from,
    files={
        "html": FILES["html"].with_(
            help="Also write a page with the figure, the rule and the tests."
        ),
        **plot_file("the indicators over time, with the baseline, the limits and the alarm"),
    },
)
