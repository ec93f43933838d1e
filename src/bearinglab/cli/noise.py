"""The ``noise`` command (issue 5): sound pressure of a bearing with form errors, the lines
of its spectrum and the ISO 15242 vibration velocity bands.

Parses the options and calls :func:`bearinglab.noise.noise_analysis` (which the report
calls too), then prints its result: ``to_dict()`` for ``--json``, tables built from the
same data otherwise, ``plot()`` for ``--plot`` (docs/capabilities/noise.md, "The noise
command").
"""

import math
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import InputError
from ..noise.bearing import SAMPLE_RATE
from ..operating import OperatingCondition
from ..units import label, rpm_to_rad_s, unit_of
from ._app import command_app, console
from ._forms import (
    BallErrorOpt,
    FormErrors,
    SeedOpt,
    Surface3dOpt,
    WavinessOpt,
    form_errors_text,
)
from ._geometry import (
    _geometry_line,
    _geometry_warnings,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    MAX_LOAD_N,
    DesignationArg,
    JsonOpt,
    OptionError,
    ShaftSpeedOpt,
    _print_warnings,
    check_path,
    in_range,
    option_error,
    positive,
    save_plot_figure,
    speed_rad_s,
)
from ._output import _emit_json, _fmt, _table, peak_rows, progress_bar

app = command_app()

#: Most instants of the orbit (about 1.3 ms each).
MAX_POINTS = 200_000


class BandsFrom(str, Enum):
    auto = "auto"
    orbit = "orbit"
    rigid = "rigid"


@app.command("noise")
@with_geometry
def noise_command(
    designation: DesignationArg = None,
    speed_rpm: ShaftSpeedOpt = ...,
    radial_load_n: Annotated[
        float,
        typer.Option("--radial-load-n", help="Radial load F_r on the shaft, downwards [N] (> 0)."),
    ] = ...,
    waviness: WavinessOpt = None,
    ball_size_error_um: BallErrorOpt = None,
    surface3d: Surface3dOpt = None,
    seed: SeedOpt = None,
    distance_mm: Annotated[
        float | None,
        typer.Option(
            "--distance-mm",
            help="Distance of the field point from the bearing centre [mm] "
            "(default: 10 mm outside the outside diameter; seed 003's point A is 10 mm from "
            "the centre).",
        ),
    ] = None,
    angle_deg: Annotated[
        float,
        typer.Option(
            "--angle-deg",
            help="Direction of the field point in the radial plane, from +x "
            "towards +y [deg] (90 = straight up, against the load).",
        ),
    ] = 90.0,
    duration_s: Annotated[
        float | None,
        typer.Option(
            "--duration-s",
            help="Length of the orbit record [s] (default: one cage "
            "revolution, so each ball carries its size error round once).",
        ),
    ] = None,
    points: Annotated[
        int | None,
        typer.Option(
            "--points",
            help="Instants of the orbit (default: 8192 per second, at least "
            "256). More points resolve higher frequencies; the time-mean SPL hardly changes.",
        ),
    ] = None,
    bands_from: Annotated[
        BandsFrom,
        typer.Option(
            "--bands-from",
            help="Source of the ISO 15242 velocity bands (edges scaled with "
            "the speed from their 1800 rpm values): auto (the orbit if it is sampled above "
            "twice the top band edge for long enough, else the rigid dynamic model), orbit "
            "(a second, finer orbit if needed) or rigid.",
        ),
    ] = BandsFrom.auto,
    json_output: JsonOpt = False,
    plot: Annotated[
        Path | None,
        typer.Option(
            "--plot",
            help="Draw the pressure and SPL over time, the pressure spectrum and "
            "the directivity to this .png, .svg or .pdf file.",
        ),
    ] = None,
    *,
    geometry,
):
    """Noise of a running ball bearing with waviness, ball-size errors and random
    surfaces (seed 003 part 4, seed 002): SPL at a point, pressure spectrum lines, and the
    ISO 15242 vibration velocity bands."""
    from ..noise import FieldPoint, least_field_distance, noise_analysis
    from ..noise.model import outer_radius

    speed_rad_s(speed_rpm)
    in_range(
        "--radial-load-n",
        radial_load_n,
        0.0,
        MAX_LOAD_N,
        "a load",
        low_open=True,
        hint="the orbit needs a load",
    )
    positive("--distance-mm", distance_mm, "a distance > 0 mm")
    if not math.isfinite(angle_deg):
        raise OptionError("--angle-deg", angle_deg, "a finite angle [deg]")
    positive("--duration-s", duration_s, "a duration > 0 s")
    in_range("--points", points, 16, MAX_POINTS, "an integer")
    if seed is not None and seed < 0:
        raise OptionError("--seed", seed, "an integer >= 0")
    if duration_s is not None and points is None and duration_s * SAMPLE_RATE > MAX_POINTS:
        raise OptionError(
            "--duration-s",
            duration_s,
            f"at most {MAX_POINTS / SAMPLE_RATE:g} s with the default sampling (or give --points)",
        )
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
    forms = FormErrors(waviness, ball_size_error_um, surface3d)
    bearing, _ = resolve_bearing(designation, geometry)
    imperfections = forms.build(bearing, seed)
    condition = OperatingCondition(radial_load=radial_load_n, shaft_speed=rpm_to_rad_s(speed_rpm))
    angle = math.radians(angle_deg)
    point = None if distance_mm is None else FieldPoint(distance_mm * 1e-3, angle)
    with progress_bar("orbit and sound pressure", enabled=not json_output) as update:
        try:
            result = noise_analysis(
                bearing,
                condition,
                imperfections,
                point=point,
                angle=None if point is not None else angle,
                duration=duration_s,
                points=points,
                bands_from=bands_from.value,
                progress=lambda f, stage: update(f, stage),
            )
        except InputError as exc:
            if exc.parameter == "point":
                radius, how = outer_radius(bearing)
                raise OptionError(
                    "--distance-mm",
                    distance_mm,
                    f"a distance > {least_field_distance(bearing) * 1e3:.4g} mm (outside the "
                    "inner ring and the balls' path)",
                    f"the bearing's outside radius {how} is {radius * 1e3:.4g} mm",
                ) from None
            raise option_error(
                exc,
                {
                    "speed_rpm": speed_rpm,
                    "radial_load_n": radial_load_n,
                    "duration_s": duration_s,
                    "points": points,
                },
            ) from None
        if plot is not None:
            update(None, "plot (directivity)")
            save_plot_figure(result.plot()[0], plot)
    d = result.to_dict()
    out = {
        "designation": designation,
        "seed": 0 if seed is None else seed,
        **d,
        "warnings": _geometry_warnings(bearing) + d["warnings"],
    }
    if json_output:
        _emit_json(out)
        return
    _print(out, bearing, imperfections, result)


def _print(out: dict, bearing, imperfections, result) -> None:
    from ..noise import LEVEL_ROWS

    name = bearing.name or "bearing"
    console.print(
        f"[bold]{escape(name)}: noise at {out['speed_rpm']:g} rpm, "
        f"F_r = {out['radial_load_n']:g} N[/bold]"
    )
    console.print(escape(_geometry_line(bearing)))
    console.print(f"form errors: {escape(form_errors_text(imperfections))}")
    console.print(
        f"field point: {out['distance_mm']:.4g} mm from the centre, "
        f"{out['angle_deg']:g} deg from +x ({escape(out['field_point_source'])})"
    )
    console.print(
        f"record: {out['points']} instants over {out['duration_s']:.4g} s "
        f"({out['sample_rate_hz']:.5g} Hz); orbit peak to peak "
        f"{out['orbit_peak_to_peak_um']:.4g} µm"
    )
    rows = [
        [label(what, unit_of(key).suffix), _fmt(out.get(key), 3 if key.endswith("_db") else 4)]
        for what, key in LEVEL_ROWS
    ]
    console.print(_table("Sound at the field point", ["level", "value"], rows))
    vb, hz = out["velocity_bands_um_s"], out["velocity_bands_hz"]
    console.print(
        _table(
            f"ISO 15242 velocity bands at {out['speed_rpm']:g} rpm, from the "
            f"{out['velocity_bands_source']}",
            ["band", label("from", "hz"), label("to", "hz"), label("RMS velocity", "um_s")],
            [[k, hz[k][0], hz[k][1], vb[k]] for k in vb],
        )
    )
    console.print(f"[dim]{escape(out['velocity_bands_note'])}[/dim]")
    console.print(
        _table(
            f"Sound-pressure spectrum lines (resolution {out['peaks_resolution_hz']:.3g} Hz)",
            [
                label("frequency", "hz"),
                label("amplitude", "pa"),
                "matched",
                label("deviation", "pct"),
            ],
            peak_rows(result.peaks),
        )
    )
    kin = out["kinematic"]
    console.print(
        f"BPFO {kin['bpfo_hz']:.4g} Hz, BPFI {kin['bpfi_hz']:.4g} Hz, FTF "
        f"{kin['ftf_hz']:.4g} Hz, shaft {kin['shaft_hz']:.4g} Hz"
    )
    _print_warnings(out["warnings"])
