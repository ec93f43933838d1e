"""The ``report`` command: one self-contained HTML page about a bearing at an operating
point (:func:`bearinglab.report.build_report`)."""

import typer
from rich.console import Console
from rich.markup import escape

from ..report.request import REPORT
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, check_path, takes, writing
from ._output import _emit_json, progress_bar

app = command_app()


@app.command("report")
@takes(argument="designation", files=REPORT.files, **REPORT.command_options)
def report_command(values, json_output: JsonOpt = False, output=None):
    """Write an engineer's report of a bearing at an operating point to one self-contained
    HTML page: geometry and sources, load distribution, contact, stiffness, ring
    resonances, defect frequencies, simulated envelope spectrum, vibration bands, sound,
    friction and life. A section whose analysis fails shows its error in the page and is
    listed on stderr; the report is still written, and the exit code is 1."""
    check_path("output", output, (".html", ".htm"))
    with progress_bar("report", enabled=not json_output) as update:
        report = REPORT(
            values, progress=lambda title, done, total: update(done / total, f"report: {title}")
        )
    with writing("--output", output):
        report.write(output)
    failed = [{"section": s.key, "title": s.title, "error": s.error} for s in report.failed]
    warnings = list(report.warnings)
    err = Console(stderr=True)
    for f in failed:
        err.print(
            f"[yellow]warning:[/yellow] section {escape(f['title'])!s} failed: "
            f"{escape(f['error'])}",
            highlight=False,
            soft_wrap=True,
        )
    if json_output:
        _emit_json(
            {
                "designation": values["designation"],
                "output": str(output),
                "sections": [s.key for s in report.sections],
                "failed_sections": failed,
                "left_out_sections": {s.key: s.left_out for s in report.left_out},
                "warnings": warnings,
            }
        )
    else:
        ok = len(report.sections) - len(failed) - len(report.left_out)
        skipped = ", ".join(s.title.lower() for s in report.left_out)
        console.print(
            f"report written to [bold]{escape(str(output))}[/bold] ({ok} of "
            f"{len(report.sections)} sections"
            + (f"; not for this bearing: {escape(skipped)}" if skipped else "")
            + (f"; failed: {escape(', '.join(f['title'] for f in failed))})" if failed else ")")
        )
        _print_warnings(warnings)
    if failed:  # the page is written and lists them; the exit code says it is incomplete
        raise typer.Exit(code=1)
