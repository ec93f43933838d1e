"""The ``report`` command: one self-contained HTML page about a bearing at an operating
point (:func:`bearinglab.report.build_report`)."""

import math
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.markup import escape

from ..errors import InputError
from ..operating import OperatingCondition
from ..units import rpm_to_rad_s
from ._app import command_app, console
from ._forms import check_defects, parse_defect
from ._geometry import (
    _geometry_warnings,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    AxialLoadOpt,
    JsonOpt,
    OptionError,
    RadialLoadOpt,
    ShaftSpeedOpt,
    _print_warnings,
    check_loads,
    in_range,
    option_error,
    speed_rad_s,
    writing,
)
from ._output import _emit_json, progress_bar

app = command_app()

DesignationArg = Annotated[
    str | None,
    typer.Argument(
        help="Bearing designation or catalogue name (e.g. 6205, 180205, ER-16K); optional with "
        "explicit geometry.",
    ),
]


def _check(speed_rpm, radial, axial, duration, slip_duration, sample_rate, viscosity, output):
    speed_rad_s(speed_rpm)
    check_loads(radial, axial, unloaded="an unloaded bearing has no load distribution or life")
    in_range("--duration-s", duration, 0.0, 60.0, "a duration", low_open=True)
    in_range("--slip-duration-s", slip_duration, 0.0, 10.0, "a duration")
    if sample_rate is not None and not (math.isfinite(sample_rate) and 0 < sample_rate <= 1e7):
        raise OptionError("--sample-rate-hz", sample_rate, "a rate in (0, 1e7] Hz")
    if viscosity is not None and not (math.isfinite(viscosity) and 0 < viscosity <= 1e6):
        raise OptionError("--viscosity-mm2-s", viscosity, "a viscosity in (0, 1e6] mm^2/s")
    if output.suffix.lower() not in (".html", ".htm"):
        raise OptionError("--output", str(output), "a file name ending in .html or .htm")
    if not output.parent.is_dir():
        raise OptionError("--output", str(output), "a path in an existing directory")


@app.command("report")
@with_geometry
def report_command(
    designation: DesignationArg = None,
    speed_rpm: ShaftSpeedOpt = ...,
    radial_load_n: RadialLoadOpt = ...,
    axial_load_n: AxialLoadOpt = 0.0,
    lubricant: Annotated[
        str,
        typer.Option(
            "--lubricant",
            help="Built-in lubricant for the viscosity (friction, a_ISO), at "
            "its reference temperature: iso-vg68 or seed004-grease.",
        ),
    ] = "iso-vg68",
    viscosity_mm2_s: Annotated[
        float | None,
        typer.Option(
            "--viscosity-mm2-s",
            help="Operating kinematic viscosity [mm^2/s] instead of --lubricant.",
        ),
    ] = None,
    defect: Annotated[
        list[str] | None,
        typer.Option(
            "--defect",
            help="A defect to simulate, repeatable, as for 'simulate': "
            "outer:width_mm=1.2,depth_mm=0.25[,angle_deg=270], inner:..., "
            "ball:width_mm=1.2[,ball=0]. Default: an example outer-race defect (said so in "
            "the report).",
        ),
    ] = None,
    duration_s: Annotated[
        float,
        typer.Option(
            "--duration-s", help="Length of the simulated vibration record (rigid model) [s]."
        ),
    ] = 1.0,
    slip_duration_s: Annotated[
        float,
        typer.Option(
            "--slip-duration-s",
            help="Length of the slip-model run for the defect "
            "frequencies with slip [s] (about 5 s of computing per simulated second); 0 "
            "skips it.",
        ),
    ] = 0.1,
    sample_rate_hz: Annotated[
        float | None,
        typer.Option(
            "--sample-rate-hz",
            help="Sample rate of the simulated record [Hz] (default: "
            "25.6 kHz, more at high speed so the ISO 15242 bands are resolved).",
        ),
    ] = None,
    output: Annotated[Path, typer.Option("-o", "--output", help="The HTML file to write.")] = ...,
    json_output: JsonOpt = False,
    *,
    geometry,
):
    """Write an engineer's report of a bearing at an operating point to one self-contained
    HTML page: geometry and sources, load distribution, contact, stiffness, ring
    resonances, defect frequencies, simulated envelope spectrum, vibration bands, sound,
    friction and life. A section whose analysis fails shows its error in the page and is
    listed on stderr; the report is still written, and the exit code is 1."""
    from ..report import build_report

    _check(
        speed_rpm,
        radial_load_n,
        axial_load_n,
        duration_s,
        slip_duration_s,
        sample_rate_hz,
        viscosity_mm2_s,
        output,
    )
    specs = list(defect or [])
    defects = [parse_defect(text) for text in specs]
    bearing, decoded = resolve_bearing(designation, geometry)
    check_defects(specs, defects, bearing)
    from ..lubrication import LUBRICANTS

    # checked even when --viscosity-mm2-s replaces it (a typo is never silently passed)
    if lubricant not in LUBRICANTS:
        raise OptionError("--lubricant", lubricant, f"one of {', '.join(LUBRICANTS)}")
    condition = OperatingCondition(
        radial_load=radial_load_n, axial_load=axial_load_n, shaft_speed=rpm_to_rad_s(speed_rpm)
    )
    with progress_bar("report", enabled=not json_output) as update:
        try:
            report = build_report(
                bearing,
                condition,
                designation=decoded,
                defects=defects,
                lubricant=None if viscosity_mm2_s is not None else lubricant,
                viscosity=None if viscosity_mm2_s is None else viscosity_mm2_s * 1e-6,
                duration=duration_s,
                sample_rate=sample_rate_hz,
                slip_duration=slip_duration_s,
                progress=lambda title, done, total: update(done / total, f"report: {title}"),
            )
        except InputError as exc:
            raise option_error(
                exc,
                {
                    "radial_load_n": radial_load_n,
                    "axial_load_n": axial_load_n,
                    "speed_rpm": speed_rpm,
                    "sample_rate_hz": sample_rate_hz,
                    "duration_s": duration_s,
                },
            ) from None
    with writing("--output", output):
        report.write(output)
    failed = [{"section": s.key, "title": s.title, "error": s.error} for s in report.failed]
    warnings = _geometry_warnings(bearing) + list(report.warnings)
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
                "designation": designation,
                "output": str(output),
                "sections": [s.key for s in report.sections],
                "failed_sections": failed,
                "warnings": warnings,
            }
        )
    else:
        ok = len(report.sections) - len(failed)
        console.print(
            f"report written to [bold]{escape(str(output))}[/bold] ({ok} of "
            f"{len(report.sections)} sections"
            + (f"; failed: {escape(', '.join(f['title'] for f in failed))})" if failed else ")")
        )
        _print_warnings(warnings)
    if failed:  # the page is written and lists them; the exit code says it is incomplete
        raise typer.Exit(code=1)
