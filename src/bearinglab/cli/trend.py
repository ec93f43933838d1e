"""The ``trend`` command: the trend of a machine over a folder of recordings, with a
baseline, an alarm at a stated false-alarm probability, the diagnosis at and after it
and the ISO 20816 severity (:func:`bearinglab.trend.trend_records`;
docs/capabilities/trend.md)."""

from ..trend.request import TREND
from ..trend.result import duration_text, life_text, measured_text
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, plot_option, save_plot_figure, takes
from ._output import _emit_json, _table, escape, progress_bar
from ._preflight import output_file
from ._preflight import scheduler as preflight_scheduler

app = command_app()
PlotOpt = plot_option("the indicators over time, with the baseline, the limits and the alarm")


@app.command("trend")
@takes(argument="folder", files=TREND.files, **TREND.command_options)
def trend_command(values, json_output: JsonOpt = False, html=None, plot=None):
    """Trend health indicators over a series of recordings and raise an alarm."""
    output_file("--plot", plot, (".png", ".svg", ".pdf"), figure=True)
    output_file("--html", html, (".html", ".htm"))
    preflight_scheduler(values["scheduler"], environment=False)
    with progress_bar("records", enabled=not json_output, unit="records") as progress:
        result = TREND(values, progress=progress)
    if plot is not None:
        save_plot_figure(result.plot()[0], plot)
    if html is not None:
        from ..report.trend import write_trend_page

        write_trend_page(result, html)
    out = result.to_dict()
    if json_output:
        _emit_json(out)
        return
    _print(out)
    _print_warnings(out["warnings"])
    for what, path in (("plot", plot), ("page", html)):
        if path is not None:
            console.print(f"{what} written to {escape(str(path))}")


def _print(out: dict) -> None:
    """The summary and the tests as tables (the same data as ``--json``)."""
    rule = out["rule"]
    base = out["baseline"]
    rows = [
        ["folder", f"{out['folder']} ({out['layout']})"],
        ["records", f"{len(out['records'])} over {duration_text(out['duration_s'])}"],
        ["channels", ", ".join(out["channels"])],
        [
            "baseline",
            f"{out['baseline_records']} records, {duration_text(base['start_s'])} to "
            f"{duration_text(base['end_s'])} "
            f"(after {base['running_in_records']} running-in records)",
        ],
        [
            "rule",
            f"{rule['tests']} tests over 0-{rule['band_hz'][1]:.6g} Hz, each level the median "
            f"of {rule['persistence']} records ({duration_text(rule['persistence_s'])}), limit "
            f"{rule['limit_excess']:.3g} robust scales above the baseline; false alarms "
            f"stated {rule['false_alarm_per_hour']:.3g} per hour of monitoring "
            f"({rule['false_alarm_per_record']:.3g} per record)",
        ],
        ["false alarms measured", measured_text(rule["measured_false_alarm"])],
    ]
    alarm = out["alarm"]
    if alarm is None:
        rows.append(["alarm", "none"])
    else:
        rows += [
            [
                "alarm",
                f"{duration_text(alarm['time_s'])}, record {alarm['record']} ({alarm['file']}): "
                f"{alarm['indicator']} of {alarm['channel']} {alarm['value']:.4g} > limit "
                f"{alarm['limit']:.4g}",
            ],
            ["before the last record", duration_text(alarm["time_to_last_record_s"])],
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
    if out["short_crossings"]:
        first = out["short_crossings"][0]
        rows.append(
            [
                "short crossings",
                f"{len(out['short_crossings'])} run(s) of records above a limit that did not "
                f"persist, the first at {duration_text(first['time_s'])} ({first['indicator']}, "
                f"{first['channel']})",
            ]
        )
    life = out.get("remaining_life")
    if life is not None:
        rows.append(["remaining life", life_text(life)])
    severity = out["severity"]
    if severity is not None:
        first = severity["first_zone_s"]
        rows.append(
            [
                f"ISO zones ({severity['machine']})",
                "; ".join(
                    f"zone {z} from {duration_text(t)}" for z, t in first.items() if t is not None
                )
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
