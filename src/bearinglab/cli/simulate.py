"""The ``simulate`` command: seed 003's rigid-ring model or seed 004's slip model
(:func:`bearinglab.dynamics.simulate`), the envelope diagnosis of the simulated acceleration
(:func:`bearinglab.diagnosis.analyze_signal`) and the lines of its plain spectrum."""

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..diagnosis import analyze_signal
from ..dynamics import SlipParameters, simulate
from ..errors import BearinglabError, InputError
from ..kinematics import defect_frequencies
from ..operating import OperatingCondition
from ..plausibility import LOCATION_FAMILY, operating_warnings, sampling_warnings
from ..signal import SUFFIXES, write_signal
from ..signal.lines import spectrum_lines
from ._app import command_app, console
from ._forms import (
    BallErrorOpt,
    FormErrors,
    Surface3dOpt,
    WavinessOpt,
    bad_defect,
    defect_reason,
    defect_text,
    form_errors_text,
    parse_defect,
)
from ._inputs import (
    DesignationArg,
    JsonOpt,
    OptionError,
    _geometry_line,
    _geometry_warnings,
    _print_warnings,
    check_loads,
    check_path,
    option_error,
    positive,
    resolve_bearing,
    save_plot_figure,
    speed_rad_s,
    with_geometry,
)
from ._output import (
    _emit_json,
    _table,
    peak_rows,
    peaks_json,
    print_diagnosis,
    progress_bar,
    simulation_stage,
)

app = command_app()
#: Channels whose plain spectrum ``simulate`` can read (both models have them).
SPECTRUM_CHANNELS = ("disp_y", "disp_x", "acc_y", "acc_x")


class Model(str, Enum):
    rigid = "rigid"
    slip = "slip"


@app.command("simulate")
@with_geometry
def simulate_command(
        designation: DesignationArg = None,
        speed_rpm: Annotated[float, typer.Option("--speed-rpm",
                                                 help="Shaft (inner-ring) speed [rpm].")] = ...,
        radial_load_n: Annotated[float, typer.Option(
            "--radial-load-n", help="Radial load F_r on the shaft, downwards [N].")] = ...,
        axial_load_n: Annotated[float, typer.Option(
            "--axial-load-n", help="Axial load [N] (the models are planar: not used).")] = 0.0,
        defect: Annotated[list[str] | None, typer.Option(
            "--defect", help="A defect, repeatable: outer:width_mm=1.2,depth_mm=0.25"
            "[,angle_deg=270] (angle from +x towards +y, 270 = bottom, the default), "
            "inner:width_mm=...,depth_mm=...[,angle_deg=...], ball:width_mm=1.2[,ball=0].",
            show_default=False)] = None,
        model: Annotated[Model, typer.Option(
            "--model", help="rigid: seed 003's 4-DOF rigid-ring model (no slip); slip: seed "
            "004's model with ball slip and a cage.")] = Model.rigid,
        duration_s: Annotated[float, typer.Option(
            "--duration-s", help="Length of the recorded signal [s].")] = 1.0,
        sample_rate_hz: Annotated[float, typer.Option(
            "--sample-rate-hz", help="Sample rate of the signal [Hz].")] = 50000.0,
        settle_s: Annotated[float | None, typer.Option(
            "--settle-s", help="Time simulated and discarded first [s] (default: 0.05 s "
            "rigid; slip: detected, whole cage revolutions, at least 4, until the cage and "
            "spin ratios change by less than 1e-3).", show_default=False)] = None,
        cage_friction: Annotated[float | None, typer.Option(
            "--cage-friction", help="Slip model: ball-cage pocket friction coefficient mu_c "
            "[-], 0-0.3 (lubricated pockets 0.05-0.2; default 0.1 = seed 004 eq. 11 at pure "
            "sliding).", show_default=False)] = None,
        spin_drag: Annotated[bool, typer.Option(
            "--spin-drag/--no-spin-drag", help="Slip model: add the drag moment of each ball "
            "spinning in the oil-air mixture (Dennis, Singh & Ingham 1980; not in seed "
            "004).")] = False,
        oil_fraction: Annotated[float | None, typer.Option(
            "--oil-fraction", help="Slip model: volume fraction of oil in the oil-air mixture "
            "that drags balls and cage [-], 0-1 (default 0.03; Harris & Kotzalas give "
            "0.01-0.05).", show_default=False)] = None,
        noise_ms2: Annotated[float, typer.Option(
            "--noise-ms2", help="RMS white noise added to the accelerations [m/s^2].")] = 0.0,
        waviness: WavinessOpt = None, ball_size_error_um: BallErrorOpt = None,
        surface3d: Surface3dOpt = None,
        seed: Annotated[int | None, typer.Option(
            "--seed", help="Seed of the noise (default: fresh noise) and of the random "
            "form errors (--ball-size-error-um, --surface3d; default 0 for those).",
            show_default=False)] = None,
        spectrum_channel: Annotated[str, typer.Option(
            "--spectrum-channel", help="Channel of the plain spectrum (spectrum_peaks): "
            "disp_y, disp_x (inner ring relative to the outer: the form-error lines stand "
            "out), acc_y or acc_x (the resonances dominate).")] = "disp_y",
        output: Annotated[Path | None, typer.Option(
            "-o", "--output", help="Write the signal to this .npz, .csv, .wav or .mat file.",
            show_default=False)] = None,
        json_output: JsonOpt = False,
        plot: Annotated[Path | None, typer.Option(
            "--plot", help="Also draw the envelope spectrum (acc_y) and the plain spectrum "
            "(--spectrum-channel) to this .png, .svg or .pdf file.",
            show_default=False)] = None, *, geometry):
    """Simulate the vibration of a bearing with defects and form errors (seed 003 rigid
    model or seed 004 slip model), diagnose it by envelope analysis and list the lines of
    its plain spectrum."""
    shaft_speed = speed_rad_s(speed_rpm)
    check_loads(radial_load_n, axial_load_n)
    positive("--duration-s", duration_s, "a duration > 0 s")
    positive("--sample-rate-hz", sample_rate_hz, "a sample rate > 0 Hz")
    positive("--settle-s", settle_s, "a time >= 0 s", zero=True)
    positive("--noise-ms2", noise_ms2, "an RMS >= 0 m/s^2", zero=True)
    if seed is not None and seed < 0:
        raise OptionError("--seed", seed, "an integer >= 0")
    check_path("--output", output, SUFFIXES)
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
    if output is not None and output.suffix.lower() == ".wav" and \
            sample_rate_hz != round(sample_rate_hz):
        raise OptionError("--sample-rate-hz", sample_rate_hz, "a whole number of Hz for .wav")
    if spectrum_channel not in SPECTRUM_CHANNELS:
        raise OptionError("--spectrum-channel", spectrum_channel,
                          f"one of {', '.join(SPECTRUM_CHANNELS)}")
    specs = list(defect or [])
    defects = [parse_defect(text) for text in specs]
    forms = FormErrors(waviness, ball_size_error_um, surface3d)
    bearing, _ = resolve_bearing(designation, geometry)
    imperfections = forms.build(bearing, seed)
    for text, d in zip(specs, defects, strict=True):
        try:
            d.check(bearing)
        except InputError as exc:
            raise bad_defect(text, f"for {bearing.name or 'this bearing'}: "
                              f"{defect_reason(exc)}") from None
    condition = OperatingCondition(radial_load=radial_load_n, axial_load=axial_load_n,
                                   shaft_speed=shaft_speed)
    # a record that cannot show the simulated defects (or, healthy, even BPFO) is refused
    families = [LOCATION_FAMILY[d.location] for d in defects] or ["outer_race"]
    try:
        plausible = (operating_warnings(bearing, condition)
                     + sampling_warnings(defect_frequencies(bearing, shaft_speed),
                                         sample_rate_hz, duration_s, families))
    except InputError as exc:
        raise option_error(exc, {"radial_load_n": radial_load_n, "speed_rpm": speed_rpm,
                                 "sample_rate_hz": sample_rate_hz}) from None
    slip_given = {"cage_friction": cage_friction, "oil_fraction": oil_fraction,
                  "spin_drag": spin_drag or None}
    parameters = None
    if model is Model.slip:
        parameters = SlipParameters(**{k: v for k, v in slip_given.items() if v is not None})
    elif any(v is not None for v in slip_given.values()):
        name = next(k for k, v in slip_given.items() if v is not None).replace("_", "-")
        raise OptionError(f"--{name}", slip_given[name.replace("-", "_")],
                          "no value with --model rigid (a slip-model parameter)")
    running = f"simulating ({model.value} model)"
    with progress_bar(simulation_stage(model.value), enabled=not json_output) as update:
        try:
            sim = simulate(bearing, condition, defects, model=model.value, duration=duration_s,
                           sample_rate=sample_rate_hz, settle=settle_s, noise=noise_ms2,
                           seed=seed, imperfections=imperfections, parameters=parameters,
                           progress=lambda f: update(f, running))
        except InputError as exc:
            raise _simulate_error(exc, bearing) from None
    diag = analyze_signal(sim.signal, None, sim.kinematic, channel="acc_y")
    spec, spectrum_peaks = spectrum_lines(sim.signal.channel(spectrum_channel),
                                          sim.signal.sample_rate, sim.kinematic,
                                          diag.max_frequency)
    if output is not None:
        _write(output, sim.signal)
    if plot is not None:
        _plot_spectra(diag, spec, spectrum_peaks, spectrum_channel, plot)
    has_ball = any(d.location == "ball" for d in defects)
    warnings = _geometry_warnings(bearing) + plausible + list(sim.warnings)
    if axial_load_n:
        warnings.append(f"--axial-load-n {axial_load_n:g} N does not enter the {model.value} "
                        "model (it is planar: radial load only)")
    if imperfections is not None and not defects:
        warnings.append("no defects were simulated: the lines at the defect frequencies come "
                        "from the form errors (e.g. outer-race waviness of order kZ +- 1 "
                        "gives k x BPFO), so the 'likely fault' is not a defect")
    out = {"designation": designation, "model": model.value,
           "sample_rate_hz": sim.signal.sample_rate, "duration_s": sim.signal.duration,
           "speed_rpm": speed_rpm, "radial_load_n": radial_load_n,
           "axial_load_n": axial_load_n, "kinematic": sim.kinematic.to_dict(),
           "channel": diag.channel, "peaks": peaks_json(diag.peaks),
           "likely_fault": diag.likely_fault, "faults": diag.faults, "scores": diag.scores,
           "reason": diag.reason,
           "band_hz": None if diag.band is None else list(diag.band),
           "cage_speed_ratio": sim.cage_speed_ratio, "spin_speed_ratio": sim.spin_speed_ratio,
           "ball_defect_frequency_hz": diag.ball_defect_frequency_hz if has_ball else None,
           "spectrum_channel": spectrum_channel, "spectrum_resolution_hz": spec.resolution,
           "spectrum_peaks": peaks_json(spectrum_peaks),
           "defects": [d.to_dict() for d in defects],
           "imperfections": None if imperfections is None else imperfections.to_dict(),
           "seed": seed,
           "output": None if output is None else str(output), "stats": dict(sim.stats),
           "halves": sim.halves,
           "slip_parameters": None if parameters is None else parameters.to_dict(),
           "warnings": warnings}
    if json_output:
        _emit_json(out)
        return
    rows = [["model", model.value], ["duration", f"{sim.signal.duration:g} s"],
            ["sample rate", f"{sim.signal.sample_rate:g} Hz"],
            ["speed, radial load", f"{speed_rpm:g} rpm, {radial_load_n:g} N"],
            ["defects", "; ".join(defect_text(d) for d in defects) or "none (healthy)"],
            ["form errors", form_errors_text(imperfections)],
            ["integration", (f"{sim.stats.get('steps')} steps, "
                             f"{sim.stats.get('rejected_steps')} rejected, settle "
                             f"{sim.stats.get('settle_s', 0):g} s")]]
    if sim.cage_speed_ratio is not None:
        rows.append(["cage speed / pure rolling", f"{sim.cage_speed_ratio:.4f}"])
    if sim.spin_speed_ratio is not None:
        rows.append(["ball spin / pure rolling", f"{sim.spin_speed_ratio:.4f}"])
    if output is not None:
        rows.append(["signal written to", str(output)])
    console.print(_table(f"{bearing.name or 'bearing'}: simulation", ["", "value"], rows))
    console.print(escape(_geometry_line(bearing)))
    print_diagnosis(diag, "acc_y")
    console.print(_table(f"{spectrum_channel}: plain spectrum lines (resolution "
                         f"{spec.resolution:.3g} Hz)", ["Hz", "amplitude", "matched",
                                                        "deviation %"],
                         peak_rows(spectrum_peaks)))
    _print_warnings(warnings)


def _plot_spectra(diag, spec, lines, channel: str, path: Path) -> None:
    """Envelope spectrum (top) and plain spectrum (bottom) in one figure."""
    from ..plotting import _pyplot, draw_spectrum

    plt = _pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(11, 8))
    diag.plot(ax=axes[0])
    draw_spectrum(axes[1], spec, lines, diag.frequencies, diag.max_frequency,
                  title=f"plain spectrum of {channel} (resolution {spec.resolution:.3g} Hz)",
                  ylabel=f"amplitude [{'m' if channel.startswith('disp') else 'm/s^2'}]")
    fig.tight_layout()
    save_plot_figure(fig, path)


_SIMULATE_FLAGS = {"duration": "--duration-s", "sample_rate": "--sample-rate-hz",
                   "settle": "--settle-s", "noise": "--noise-ms2", "shaft_speed": "--speed-rpm",
                   "radial_load": "--radial-load-n", "axial_load": "--axial-load-n"}


def _simulate_error(exc: InputError, bearing) -> BearinglabError:
    """An error of simulate() in the options' terms, where one option is to blame."""
    name = bearing.name or "the bearing"
    if exc.parameter in ("inner_mass", "outer_mass") and exc.value is None:
        return BearinglabError(f"--model slip needs the ring masses, which follow from the "
                               f"boundary dimensions {name} lacks: give --bore-mm, "
                               "--outside-diameter-mm and --width-mm")
    if exc.parameter == "contact_angle":
        return OptionError("--model", "slip", "rigid for this bearing (the slip model is "
                           f"planar: contact angle 0; {name} has {exc.value:g} deg)")
    if exc.parameter in ("cage_friction", "oil_fraction"):
        return OptionError("--" + exc.parameter.replace("_", "-"), exc.value, exc.allowed)
    flag = _SIMULATE_FLAGS.get(exc.parameter)
    if flag is None or flag == "--speed-rpm":
        return exc
    return OptionError(flag, exc.value, exc.allowed)


def _write(path: Path, signal) -> None:
    try:
        write_signal(path, signal)
    except InputError as exc:
        raise OptionError("--output", str(path), exc.allowed) from None
    except OSError as exc:
        raise OptionError("--output", str(path), "a writable file",
                          exc.strerror or type(exc).__name__) from None
