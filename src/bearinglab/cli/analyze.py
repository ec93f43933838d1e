"""The ``analyze`` command: diagnose a recorded vibration signal
(:func:`bearinglab.diagnosis.analyze_file`: the significance of each fault family's
harmonic series above the noise floor of the squared envelope spectrum, by Smith &
Randall's methods; docs/capabilities/diagnosis.md)."""

from ..analyses.diagnosis import ANALYZE
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, check_path, save_plot_figure, takes
from ._output import _emit_json, escape, print_verdict

app = command_app()


@app.command("analyze")
@takes(argument="signal_file", files=ANALYZE.files, **ANALYZE.command_options)
def analyze_command(values, json_output: JsonOpt = False, plot=None):
    """Diagnose a vibration record by envelope analysis."""
    check_path("plot", plot, (".png", ".svg", ".pdf"))
    diag = ANALYZE(values)
    if plot is not None:
        save_plot_figure(diag.plot()[0], plot)
    out = {"file": str(values["signal_file"]), "designation": values["designation"]}
    out.update(diag.to_dict())
    if json_output:
        _emit_json(out)
        return
    print_verdict(diag, values["signal_file"].name, diag.frequencies.bearing)
    for size in out["defect_sizes"]:
        width = (
            f": {size['width_mm']:.3g} mm ({size['low_mm']:.3g}-{size['high_mm']:.3g}), "
            f"{size['extent_deg']:.3g} deg"
            if size["status"] == "sized"
            else ""
        )
        race = size["race"].replace("_", " ")
        console.print(f"defect width, {race}: [bold]{size['status']}{width}[/bold]")
        console.print(f"[dim]{escape(size['reason'])}[/dim]")
    _print_warnings(out["warnings"])
