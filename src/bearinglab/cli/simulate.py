"""The ``simulate`` command: seed 003's rigid-ring model or seed 004's slip model
(:func:`bearinglab.dynamics.simulate`), the envelope diagnosis of the simulated acceleration
(:func:`bearinglab.diagnosis.analyze_signal`) and the lines of its plain spectrum."""

from ..analyses.vibration import SIMULATE
from ..inputs.specs import defect_text, form_errors_text
from ..signal import SUFFIXES, write_signal
from ._app import command_app, console
from ._inputs import (
    JsonOpt,
    OptionError,
    _print_warnings,
    check_path,
    plot_option,
    save_plot_figure,
    takes,
    writing,
)
from ._output import _emit_json, _table, peak_rows, print_verdict, progress_bar, simulation_stage

app = command_app()
PlotOpt = plot_option("the envelope spectrum (acc_y) and the plain spectrum (--spectrum-channel)")


@app.command("simulate")
@takes(argument="designation", files=SIMULATE.files, **SIMULATE.command_options)
def simulate_command(values, json_output: JsonOpt = False, output=None, plot=None):
    """Simulate the vibration of a bearing with defects and form errors (seed 003 rigid
    model or seed 004 slip model), diagnose it by envelope analysis and list the lines of
    its plain spectrum."""
    check_path("output", output, SUFFIXES)
    check_path("plot", plot, (".png", ".svg", ".pdf"))
    rate = values["sample_rate_hz"]
    if output is not None and output.suffix.lower() == ".wav" and rate != round(rate):
        raise OptionError("--sample-rate-hz", rate, "a whole number of Hz for .wav")
    model = values["dynamic_model"]
    running = f"simulating ({model} model)"
    with progress_bar(simulation_stage(model), enabled=not json_output) as update:
        r = SIMULATE(values, progress=lambda f: update(f, running))
    record = r.record
    if output is not None:
        with writing("--output", output):
            write_signal(output, record.simulation.signal)
    if plot is not None:
        save_plot_figure(r.plot()[0], plot)
    out = {**r.to_dict(), "output": None if output is None else str(output)}
    if json_output:
        _emit_json(out)
        return
    bearing, defects, imperfections = r.bearing, r.defects, r.imperfections
    speed_rpm, radial_load_n, spectrum_channel = (
        values[k] for k in ("speed_rpm", "radial_load_n", "spectrum_channel")
    )
    warnings = out["warnings"]
    sim = record.simulation
    rows = [
        ["model", model],
        ["duration", f"{sim.signal.duration:g} s"],
        ["sample rate", f"{sim.signal.sample_rate:g} Hz"],
        ["speed, radial load", f"{speed_rpm:g} rpm, {radial_load_n:g} N"],
        ["defects", "; ".join(defect_text(d) for d in defects) or "none (healthy)"],
        ["form errors", form_errors_text(imperfections)],
        [
            "integration",
            (
                f"{sim.stats.get('steps')} steps, "
                f"{sim.stats.get('rejected_steps')} rejected, settle "
                f"{sim.stats.get('settle_s', 0):g} s"
            ),
        ],
    ]
    if sim.cage_speed_ratio is not None:
        rows.append(["cage speed / pure rolling", f"{sim.cage_speed_ratio:.4f}"])
    if sim.spin_speed_ratio is not None:
        rows.append(["ball spin / pure rolling", f"{sim.spin_speed_ratio:.4f}"])
    if output is not None:
        rows.append(["signal written to", str(output)])
    console.print(_table(f"{bearing.name or 'bearing'}: simulation", ["", "value"], rows))
    print_verdict(record.diagnosis, "simulated acc_y", bearing)
    console.print(
        _table(
            f"{spectrum_channel}: plain spectrum lines (resolution "
            f"{record.spectrum.resolution:.3g} Hz)",
            ["f [Hz]", "amplitude", "matched", "deviation [%]"],
            peak_rows(record.spectrum_lines),
        )
    )
    _print_warnings(warnings)
