"""The ``simulate`` command: seed 003's rigid-ring model or seed 004's slip model
(:func:`bearinglab.dynamics.simulate`), the envelope diagnosis of the simulated acceleration
(:func:`bearinglab.diagnosis.analyze_signal`) and the lines of its plain spectrum."""

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from ..dynamics import SlipParameters
from ..dynamics.record import SPECTRUM_CHANNELS, simulate_record
from ..errors import BearinglabError, InputError
from ..operating import OperatingCondition
from ..signal import SUFFIXES, write_signal
from ._app import command_app, console
from ._forms import (
    BallErrorOpt,
    FormErrors,
    Surface3dOpt,
    WavinessOpt,
    check_defects,
    defect_text,
    form_errors_text,
    parse_defect,
)
from ._geometry import (
    _geometry_warnings,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    DesignationArg,
    JsonOpt,
    OptionError,
    RadialLoadOpt,
    ShaftSpeedOpt,
    _print_warnings,
    check_loads,
    check_path,
    in_range,
    option_error,
    plot_option,
    save_plot_figure,
    speed_rad_s,
    writing,
)
from ._output import (
    _emit_json,
    _table,
    peak_rows,
    print_verdict,
    progress_bar,
    simulation_stage,
)

app = command_app()
PlotOpt = plot_option("the envelope spectrum (acc_y) and the plain spectrum (--spectrum-channel)")


class Model(str, Enum):
    rigid = "rigid"
    slip = "slip"


@app.command("simulate")
@with_geometry
def simulate_command(
    designation: DesignationArg = None,
    speed_rpm: ShaftSpeedOpt = ...,
    radial_load_n: RadialLoadOpt = ...,
    axial_load_n: Annotated[
        float,
        typer.Option("--axial-load-n", help="Axial load [N] (the models are planar: not used)."),
    ] = 0.0,
    defect: Annotated[
        list[str] | None,
        typer.Option(
            "--defect",
            help="A defect, repeatable: outer:width_mm=1.2,depth_mm=0.25"
            "[,angle_deg=270] (angle from +x towards +y, 270 = bottom, the default), "
            "inner:width_mm=...,depth_mm=...[,angle_deg=...], ball:width_mm=1.2[,ball=0].",
        ),
    ] = None,
    model: Annotated[
        Model,
        typer.Option(
            "--model",
            help="rigid: seed 003's 4-DOF rigid-ring model (no slip); slip: seed "
            "004's model with ball slip and a cage.",
        ),
    ] = Model.rigid,
    duration_s: Annotated[
        float, typer.Option("--duration-s", help="Length of the recorded signal [s].")
    ] = 1.0,
    sample_rate_hz: Annotated[
        float, typer.Option("--sample-rate-hz", help="Sample rate of the signal [Hz].")
    ] = 50000.0,
    settle_s: Annotated[
        float | None,
        typer.Option(
            "--settle-s",
            help="Time simulated and discarded first [s] (default: 0.05 s "
            "rigid; slip: detected, whole cage revolutions, at least 4, until the cage and "
            "spin ratios change by less than 1e-3).",
        ),
    ] = None,
    cage_friction: Annotated[
        float | None,
        typer.Option(
            "--cage-friction",
            help="Slip model: ball-cage pocket friction coefficient mu_c "
            "[-], 0-0.3 (lubricated pockets 0.05-0.2; default 0.1 = seed 004 eq. 11 at pure "
            "sliding).",
        ),
    ] = None,
    spin_drag: Annotated[
        bool,
        typer.Option(
            "--spin-drag/--no-spin-drag",
            help="Slip model: add the drag moment of each ball "
            "spinning in the oil-air mixture (Dennis, Singh & Ingham 1980; not in seed "
            "004).",
        ),
    ] = False,
    oil_fraction: Annotated[
        float | None,
        typer.Option(
            "--oil-fraction",
            help="Slip model: volume fraction of oil in the oil-air mixture "
            "that drags balls and cage [-], 0-1 (default 0.03; Harris & Kotzalas give "
            "0.01-0.05).",
        ),
    ] = None,
    noise_ms2: Annotated[
        float,
        typer.Option("--noise-ms2", help="RMS white noise added to the accelerations [m/s^2]."),
    ] = 0.0,
    waviness: WavinessOpt = None,
    ball_size_error_um: BallErrorOpt = None,
    surface3d: Surface3dOpt = None,
    seed: Annotated[
        int | None,
        typer.Option(
            "--seed",
            help="Seed of the noise (default: fresh noise) and of the random "
            "form errors (--ball-size-error-um, --surface3d; default 0 for those).",
        ),
    ] = None,
    spectrum_channel: Annotated[
        str,
        typer.Option(
            "--spectrum-channel",
            help="Channel of the plain spectrum (spectrum_peaks): "
            "disp_y, disp_x (inner ring relative to the outer: the form-error lines stand "
            "out), acc_y or acc_x (the resonances dominate).",
        ),
    ] = "disp_y",
    output: Annotated[
        Path | None,
        typer.Option(
            "-o",
            "--output",
            help="Write the signal to this .npz, .csv, .wav or .mat file.",
        ),
    ] = None,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Simulate the vibration of a bearing with defects and form errors (seed 003 rigid
    model or seed 004 slip model), diagnose it by envelope analysis and list the lines of
    its plain spectrum."""
    shaft_speed = speed_rad_s(speed_rpm)
    check_loads(radial_load_n, axial_load_n)
    # upper bounds far beyond any measurement, so that a slip of the keyboard (1e9 Hz,
    # 1e300 m/s^2) is named here rather than overflowing or stalling the integrator
    in_range("--duration-s", duration_s, 0.0, 3600.0, "a duration", low_open=True)
    in_range("--sample-rate-hz", sample_rate_hz, 0.0, 1e6, "a sample rate", low_open=True)
    in_range("--settle-s", settle_s, 0.0, 60.0, "a settling time")
    in_range("--noise-ms2", noise_ms2, 0.0, 1e6, "an RMS acceleration (m/s²)")
    if seed is not None and seed < 0:
        raise OptionError("--seed", seed, "an integer >= 0")
    check_path("--output", output, SUFFIXES)
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
    if (
        output is not None
        and output.suffix.lower() == ".wav"
        and sample_rate_hz != round(sample_rate_hz)
    ):
        raise OptionError("--sample-rate-hz", sample_rate_hz, "a whole number of Hz for .wav")
    if spectrum_channel not in SPECTRUM_CHANNELS:
        raise OptionError(
            "--spectrum-channel", spectrum_channel, f"one of {', '.join(SPECTRUM_CHANNELS)}"
        )
    specs = list(defect or [])
    defects = [parse_defect(text) for text in specs]
    forms = FormErrors(waviness, ball_size_error_um, surface3d)
    bearing, _ = resolve_bearing(designation, geometry)
    imperfections = forms.build(bearing, seed)
    check_defects(specs, defects, bearing)
    condition = OperatingCondition(
        radial_load=radial_load_n, axial_load=axial_load_n, shaft_speed=shaft_speed
    )
    slip_given = {
        "cage_friction": cage_friction,
        "oil_fraction": oil_fraction,
        "spin_drag": spin_drag or None,
    }
    parameters = None
    if model is Model.slip:
        try:
            parameters = SlipParameters(**{k: v for k, v in slip_given.items() if v is not None})
        except InputError as exc:
            raise option_error(exc, slip_given) from None
    elif any(v is not None for v in slip_given.values()):
        name = next(k for k, v in slip_given.items() if v is not None)
        raise OptionError(
            "--" + name.replace("_", "-"),
            slip_given[name],
            "no value with --model rigid (a slip-model parameter)",
        )
    running = f"simulating ({model.value} model)"
    with progress_bar(simulation_stage(model.value), enabled=not json_output) as update:
        try:
            record = simulate_record(
                bearing,
                condition,
                defects,
                model=model.value,
                duration=duration_s,
                sample_rate=sample_rate_hz,
                settle=settle_s,
                noise=noise_ms2,
                seed=seed,
                imperfections=imperfections,
                parameters=parameters,
                spectrum_channel=spectrum_channel,
                progress=lambda f: update(f, running),
            )
        except InputError as exc:
            raise _simulate_error(
                exc,
                bearing,
                {
                    "radial_load_n": radial_load_n,
                    "speed_rpm": speed_rpm,
                    "sample_rate_hz": sample_rate_hz,
                    "duration_s": duration_s,
                    "settle_s": settle_s,
                    "noise_ms2": noise_ms2,
                    "cage_friction": cage_friction,
                    "oil_fraction": oil_fraction,
                    "spectrum_channel": spectrum_channel,
                },
            ) from None
    if output is not None:
        with writing("--output", output):
            write_signal(output, record.simulation.signal)
    if plot is not None:
        save_plot_figure(record.plot()[0], plot)
    warnings = _geometry_warnings(bearing) + list(record.warnings)
    out = {
        "designation": designation,
        **record.to_dict(),
        "seed": seed,
        "output": None if output is None else str(output),
        "warnings": warnings,
    }
    if json_output:
        _emit_json(out)
        return
    sim = record.simulation
    rows = [
        ["model", model.value],
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


def _simulate_error(exc: InputError, bearing, options: dict) -> BearinglabError:
    """An error of the simulation in the options' terms, where one option is to blame."""
    name = bearing.name or "the bearing"
    if exc.parameter in ("inner_mass", "outer_mass") and exc.value is None:
        return BearinglabError(
            f"--model slip needs the ring masses, which follow from the "
            f"boundary dimensions {name} lacks: give --bore-mm, "
            "--outside-diameter-mm and --width-mm"
        )
    if exc.parameter == "contact_angle":
        return OptionError(
            "--model",
            "slip",
            "rigid for this bearing (the slip model is "
            f"planar: contact angle 0; {name} has {exc.value:g} deg)",
        )
    if exc.parameter == "noise":  # --noise-ms2: the one option without a unit-table suffix
        return OptionError("--noise-ms2", options.get("noise_ms2"), exc.allowed, exc.hint)
    return option_error(exc, options)
