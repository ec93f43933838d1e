"""The ``trend`` command: the trend of a machine over a folder of recordings, with a
baseline, an alarm at a stated false-alarm probability, the diagnosis at and after it
and the ISO 20816 severity (:func:`bearinglab.trend.trend_records`;
docs/capabilities/trend.md)."""

from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError
from ..trend.alarm import FALSE_ALARM, PERSISTENCE
from ..trend.analysis import BASELINE, SETTLE
from ._app import command_app, console
from ._geometry import _geometry_warnings, resolve_bearing, with_geometry
from ._inputs import (
    JsonOpt,
    OptionError,
    SchedulerOpt,
    _print_warnings,
    plot_option,
    save_plot_figure,
    speed_rad_s,
    typed,
)
from ._output import _emit_json, _table, escape, progress_bar
from ._preflight import output_file
from ._preflight import scheduler as preflight_scheduler

app = command_app()
PlotOpt = plot_option("the indicators over time, with the baseline, the limits and the alarm")
#: InputError parameter of the library -> the option (or argument) to blame.
FLAGS = {
    "folder": "FOLDER",
    "path": "FOLDER",
    "index.csv": "FOLDER",
    "time_s": "FOLDER",
    "time": "FOLDER",
    "channels": "--channel",
    "sample_rate": "--sample-rate-hz",
    "sample_rate_hz": "--sample-rate-hz",
    "settle": "--settle-s",
    "settle_records": "--settle-records",
    "baseline": "--baseline-s",
    "baseline_records": "--baseline-records",
    "false_alarm": "--false-alarm",
    "persistence": "--persistence-s",
    "persistence_records": "--persistence-records",
    "unit": "--unit",
    "machine": "--machine",
    "shaft_speed": "--speed-rpm",
    "bearing": "--designation",
    "jobs": "--jobs",
    "workers": "--jobs",
    "scheduler": "--scheduler",
}


@app.command("trend")
@with_geometry
def trend_command(
    ctx: typer.Context,
    folder: Annotated[
        Path,
        typer.Argument(
            help="Folder of recordings: PRONOSTIA snapshots acc_NNNNN.csv as published, or "
            "records analyze reads (.npz, .csv, .wav, .mat) with an index.csv (file, time_s) "
            "or a time_s in their metadata.",
        ),
    ],
    channel: Annotated[
        list[str] | None,
        typer.Option(
            "--channel",
            help="Channel to trend (repeatable; PRONOSTIA: horizontal, vertical); default all. "
            "The diagnosis uses the first.",
        ),
    ] = None,
    sample_rate_hz: Annotated[
        float | None,
        typer.Option(
            "--sample-rate-hz",
            help="Sample rate [Hz] where the files do not store it (PRONOSTIA: 25600).",
        ),
    ] = None,
    settle_s: Annotated[
        float,
        typer.Option(
            "--settle-s",
            help="Running-in left out of the baseline: the records of the first SETTLE "
            "seconds [s].",
        ),
    ] = SETTLE,
    settle_records: Annotated[
        int | None,
        typer.Option("--settle-records", help="Running-in as a number of records instead."),
    ] = None,
    baseline_s: Annotated[
        float,
        typer.Option(
            "--baseline-s",
            help="Baseline after the running-in [s]; at least 30 records (extended when the "
            "records are sparse).",
        ),
    ] = BASELINE,
    baseline_records: Annotated[
        int | None,
        typer.Option("--baseline-records", help="Baseline as a number of records instead (>= 10)."),
    ] = None,
    false_alarm: Annotated[
        float,
        typer.Option(
            "--false-alarm",
            help="Probability of a false alarm at a given record, all indicators and channels "
            "together (the rule's tail model).",
        ),
    ] = FALSE_ALARM,
    persistence_s: Annotated[
        float,
        typer.Option(
            "--persistence-s",
            help="How long records above a limit must last to raise the alarm [s]: the records "
            "spanning it at the series' cadence, at least 2.",
        ),
    ] = PERSISTENCE,
    persistence_records: Annotated[
        int | None,
        typer.Option(
            "--persistence-records", help="Persistence as a number of consecutive records instead."
        ),
    ] = None,
    unit: Annotated[
        str | None,
        typer.Option(
            "--unit",
            help="The channels' unit, g or m/s2: adds the r.m.s. velocity over 10-1000 Hz "
            "(PRONOSTIA: g).",
        ),
    ] = None,
    machine: Annotated[
        str | None,
        typer.Option(
            "--machine",
            help="Machine group for the ISO 20816 zones: group1-rigid, group1-flexible, "
            "group2-rigid, group2-flexible (ISO 20816-3), class1..class4 (ISO 10816-1); "
            "needs --unit.",
        ),
    ] = None,
    designation: Annotated[
        str | None,
        typer.Option(
            "--designation",
            help="Bearing designation, or give the geometry: with --speed-rpm, each fault "
            "family's significance by the diagnosis.",
        ),
    ] = None,
    speed_rpm: Annotated[
        float | None, typer.Option("--speed-rpm", help="Shaft speed [rpm], for the diagnosis.")
    ] = None,
    jobs: Annotated[
        int,
        typer.Option("--jobs", help="Worker processes (a dask LocalCluster); 1: this process."),
    ] = 1,
    scheduler: SchedulerOpt = None,
    html: Annotated[
        Path | None,
        typer.Option("--html", help="Also write a page with the figure, the rule and the tests."),
    ] = None,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Trend health indicators over a series of recordings and raise an alarm."""
    output_file("--plot", plot, (".png", ".svg", ".pdf"), figure=True)
    output_file("--html", html, (".html", ".htm"))
    given = typed(ctx)
    for seconds, records in (
        ("settle_s", "settle_records"),
        ("baseline_s", "baseline_records"),
        ("persistence_s", "persistence_records"),
    ):
        if seconds in given and records in given:
            flag = "--" + records.replace("_", "-")
            raise OptionError(
                flag, ctx.params[records], f"one of --{seconds.replace('_', '-')} and {flag}"
            )
    bearing = None
    if designation is not None or any(v is not None for v in geometry.values()):
        bearing, _ = resolve_bearing(designation, geometry)
    shaft_speed = None if speed_rpm is None else speed_rad_s(speed_rpm)
    preflight_scheduler(scheduler, environment=False)
    from ..trend.analysis import trend_records

    with progress_bar("reading records", enabled=not json_output) as update:
        try:
            result = trend_records(
                folder,
                channels=channel or None,
                sample_rate=sample_rate_hz,
                settle=settle_s,
                settle_records=settle_records,
                baseline=baseline_s,
                baseline_records=baseline_records,
                false_alarm=false_alarm,
                persistence=persistence_s,
                persistence_records=persistence_records,
                unit=unit,
                machine=machine,
                bearing=bearing,
                shaft_speed=shaft_speed,
                jobs=jobs,
                scheduler=scheduler,
                progress=lambda done, total: update(done / total),
            )
        except InputError as exc:
            typed_values = {
                "--channel": channel,
                "--sample-rate-hz": sample_rate_hz,
                "--settle-s": settle_s,
                "--settle-records": settle_records,
                "--baseline-s": baseline_s,
                "--baseline-records": baseline_records,
                "--false-alarm": false_alarm,
                "--persistence-s": persistence_s,
                "--persistence-records": persistence_records,
                "--unit": unit,
                "--machine": machine,
                "--speed-rpm": speed_rpm,
                "--designation": designation,
                "--jobs": jobs,
                "--scheduler": scheduler,
            }
            raise _option_error(exc, typed_values) from None
    if plot is not None:
        save_plot_figure(result.plot()[0], plot)
    if html is not None:
        from ..report.trend import write_trend_page

        write_trend_page(result, html)
    out = result.to_dict()
    if bearing is not None:
        out["warnings"] += _geometry_warnings(bearing)
    if json_output:
        _emit_json(out)
        return
    _print(out)
    _print_warnings(out["warnings"])
    for flag, path in (("plot", plot), ("page", html)):
        if path is not None:
            console.print(f"{flag} written to {escape(str(path))}")


def _option_error(exc: InputError, typed_values: dict) -> InputError:
    """The library's error in the command line's terms: the flag, the value typed (the
    library's value for FOLDER and --channel: the file or the channel at fault)."""
    flag = FLAGS.get(exc.parameter)
    if flag is None:
        return exc
    value = exc.value if flag in ("FOLDER", "--channel") else typed_values.get(flag, exc.value)
    return OptionError(flag, value, exc.allowed, exc.hint)


def _seconds(value: float | None) -> str:
    if value is None:
        return "-"
    return f"{value:.6g} s" + (f" ({value / 3600:.3g} h)" if value >= 3600 else "")


def _print(out: dict) -> None:
    """The summary and the tests as tables (the same data as ``--json``)."""
    rule = out["rule"]
    base = out["baseline"]
    rows = [
        ["folder", f"{out['folder']} ({out['layout']})"],
        ["records", f"{len(out['records'])} over {_seconds(out['duration_s'])}"],
        ["channels", ", ".join(out["channels"])],
        [
            "baseline",
            f"{out['baseline_records']} records, {_seconds(base['start_s'])} to "
            f"{_seconds(base['end_s'])} (after {base['settle_records']} running-in records)",
        ],
        [
            "rule",
            f"{rule['tests']} tests, {rule['persistence']} records in a row above a limit; "
            f"false alarm <= {rule['false_alarm_per_record']:.3g} per record, <= "
            f"{rule['false_alarm_per_run']:.3g} over the {rule['monitored_records']} records "
            "monitored",
        ],
    ]
    alarm = out["alarm"]
    if alarm is None:
        rows.append(["alarm", "none"])
    else:
        rows += [
            [
                "alarm",
                f"{_seconds(alarm['time_s'])}, record {alarm['record']} ({alarm['file']}): "
                f"{alarm['indicator']} of {alarm['channel']} {alarm['value']:.4g} > limit "
                f"{alarm['limit']:.4g}",
            ],
            ["before the last record", _seconds(alarm["time_to_last_record_s"])],
        ]
    diag = out["diagnosis"]
    if diag is not None and alarm is not None:
        after = diag["after_alarm"] or {}
        rows.append(["diagnosis at the alarm", alarm["verdict"] or "not computed"])
        rows.append(
            [
                "diagnosis after it",
                ", ".join(f"{k} in {v} blocks" for k, v in after.items()) or "-",
            ]
        )
    severity = out["severity"]
    if severity is not None:
        first = severity["first_zone_s"]
        rows.append(
            [
                f"ISO zones ({severity['machine']})",
                "; ".join(f"zone {z} from {_seconds(t)}" for z, t in first.items() if t is not None)
                or "zone A throughout",
            ]
        )
    console.print(_table("Trend", ["", "value"], rows, words=True))
    console.print(
        _table(
            "Tests (limits in the indicator's unit)",
            ["indicator", "channel", "baseline median", "limit", "first alarm [s]"],
            [
                [
                    t["indicator"],
                    t["channel"],
                    t["baseline_median"],
                    t["limit"],
                    "-" if t["first_alarm_s"] is None else f"{t['first_alarm_s']:.6g}",
                ]
                for t in out["tests"]
            ],
        )
    )
