"""The ``noise`` command (issue 5): sound pressure of a bearing with form errors, the lines
of its spectrum and the ISO 15242 vibration velocity bands.

Parses the options and calls :func:`bearinglab.noise.noise_analysis` (which the report
calls too), then prints its result: ``to_dict()`` for ``--json``, tables built from the
same data otherwise, ``plot()`` for ``--plot`` (docs/capabilities/noise.md, "The noise
command").
"""

from rich.markup import escape

from ..analyses.vibration import NOISE
from ..inputs import geometry_line
from ..inputs.specs import form_errors_text
from ..units import label, unit_of
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, check_path, save_plot_figure, takes
from ._output import _emit_json, _fmt, _table, peak_rows, progress_bar

app = command_app()


@app.command("noise")
@takes(argument="designation", files=NOISE.files, **NOISE.command_options)
def noise_command(values, json_output: JsonOpt = False, plot=None):
    """Noise of a running ball bearing with waviness, ball-size errors and random
    surfaces (seed 003 part 4, seed 002): SPL at a point, pressure spectrum lines, and the
    ISO 15242 vibration velocity bands."""
    check_path("plot", plot, (".png", ".svg", ".pdf"))
    with progress_bar("orbit and sound pressure", enabled=not json_output) as update:
        r = NOISE(values, progress=lambda f, stage: update(f, stage))
        if plot is not None:
            update(None, "plot (directivity)")
            save_plot_figure(r.plot()[0], plot)
    out = r.to_dict()
    if json_output:
        _emit_json(out)
        return
    _print(out, r.bearing, r.imperfections, r.result)


def _print(out: dict, bearing, imperfections, result) -> None:
    from ..noise import LEVEL_ROWS

    name = bearing.name or "bearing"
    console.print(
        f"[bold]{escape(name)}: noise at {out['speed_rpm']:g} rpm, "
        f"F_r = {out['radial_load_n']:g} N[/bold]"
    )
    console.print(escape(geometry_line(bearing)))
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
