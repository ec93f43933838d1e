"""Commands of the dynamics and diagnostics issue: simulate, analyze.

``simulate`` runs seed 003's rigid-ring model or seed 004's slip model
(:func:`bearinglab.dynamics.simulate`) and diagnoses the simulated acceleration;
``analyze`` diagnoses a recorded signal file. Both diagnose by envelope analysis
(:func:`bearinglab.diagnosis.analyze_signal`, after Randall & Antoni 2011).
"""

import math
from enum import Enum
from pathlib import Path
from typing import Annotated

import numpy as np
import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

from ..diagnosis import COUNT, HARMONICS, analyze_signal, peak_label
from ..dynamics import Defect, simulate
from ..errors import BearinglabError, InputError
from ..kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from ..operating import OperatingCondition
from ..signal import (
    SUFFIXES,
    amplitude_spectrum,
    find_peaks,
    match_peaks,
    read_signal,
    write_signal,
)
from ..signal.peaks import NAMES
from ._app import app, console
from ._forms import BallErrorOpt, FormErrors, Surface3dOpt, WavinessOpt
from ._inputs import (
    JsonOpt,
    OptionError,
    _geometry_line,
    _geometry_warnings,
    _print_warnings,
    check_loads,
    parse_spec,
    resolve_bearing,
    save_plot_figure,
    speed_rad_s,
    with_geometry,
)
from ._output import _emit_json, _save_plot, _table

DesignationArg = Annotated[str | None, typer.Argument(
    help="Bearing designation or catalogue name (e.g. ER-16K); optional with explicit "
         "geometry.", show_default=False)]
PlotOpt = Annotated[Path | None, typer.Option(
    "--plot", help="Also draw the envelope spectrum to this .png, .svg or .pdf file.",
    show_default=False)]
#: Channels whose plain spectrum ``simulate`` can read (both models have them).
SPECTRUM_CHANNELS = ("disp_y", "disp_x", "acc_y", "acc_x")
#: What a --defect specification may hold.
DEFECT_ALLOWED = ("LOCATION:KEY=VALUE,... with LOCATION outer, inner or ball and keys "
                  "width_mm (> 0, required), depth_mm (> 0), angle_deg (outer: position from "
                  "+x towards +y, 270 = bottom; inner: position at t = 0; ball: spin phase) "
                  "and ball (ball index, ball defects only), e.g. "
                  "outer:width_mm=1.2,depth_mm=0.25")
_DEFECT_KEYS = {"outer": {"width_mm": "positive", "depth_mm": "positive", "angle_deg": "number"},
                "inner": {"width_mm": "positive", "depth_mm": "positive", "angle_deg": "number"},
                "ball": {"width_mm": "positive", "depth_mm": "positive", "angle_deg": "number",
                         "ball": "index"}}


class Model(str, Enum):
    rigid = "rigid"
    slip = "slip"


# ------------------------------------------------------------------ parsing
def _bad_defect(text: str, hint: str) -> OptionError:
    return OptionError("--defect", text, DEFECT_ALLOWED, hint)


def parse_defect(text: str) -> Defect:
    """A :class:`~bearinglab.dynamics.Defect` (SI) from a --defect specification.

    ``outer:width_mm=1.2,depth_mm=0.25[,angle_deg=270]``, ``inner:...`` or
    ``ball:width_mm=1.2[,ball=0]``; widths and depths in mm, angles in degrees (for the
    outer race from +x towards +y, default 270 = the bottom of the load zone).

    >>> parse_defect("outer:width_mm=1.2,depth_mm=0.25").to_dict()["angle_deg"]
    -90.0
    """
    location, values = parse_spec(text, "--defect", DEFECT_ALLOWED, _DEFECT_KEYS,
                                  noun="defects", required=("width_mm",))
    kwargs = {"width": values["width_mm"] * 1e-3,
              "depth": values["depth_mm"] * 1e-3 if "depth_mm" in values else None}
    if "angle_deg" in values:  # into [-pi, pi): 270 deg is -90 deg, the bottom
        kwargs["angle"] = (math.radians(values["angle_deg"]) + math.pi) % (2 * math.pi) - math.pi
    if "ball" in values:
        kwargs["ball"] = values["ball"]
    return Defect(location, **kwargs)


def _positive(flag: str, value, allowed: str, zero: bool = False):
    if value is not None and not (math.isfinite(value) and (value >= 0 if zero else value > 0)):
        raise OptionError(flag, value, allowed)
    return value


def _check_path(flag: str, path: Path | None, suffixes: tuple[str, ...]) -> None:
    """Refuse an output path with an unknown suffix or in a missing directory, before
    any simulating."""
    if path is None:
        return
    if path.suffix.lower() not in suffixes:
        raise OptionError(flag, str(path), f"a file name ending in {', '.join(suffixes)}")
    if not path.parent.is_dir():
        raise OptionError(flag, str(path), "a path in an existing directory")


# ------------------------------------------------------------------ output
def _peak_rows(diag) -> list[list]:
    return _peak_rows_of(diag.peaks)


def _peak_rows_of(peaks) -> list[list]:
    rows = []
    for p in peaks:
        deviation = p.get("deviation")
        rows.append([p["frequency_hz"], p["amplitude"], peak_label(p),
                     None if deviation is None else 100.0 * deviation])
    return rows


def _print_diagnosis(diag, title: str) -> None:
    """The kinematic frequencies, the envelope lines and the verdict, as tables."""
    kin = diag.frequencies
    console.print(_table(f"Kinematic frequencies at {kin.shaft_hz * 60:g} rpm",
                         ["frequency", "Hz", "order", "meaning"],
                         [["shaft", kin.shaft_hz, 1.0, LONG_NAMES["shaft"]]]
                         + [[n.upper() if n != "ball_defect" else "BALL DEFECT", kin.hz(n),
                             kin.orders[n], LONG_NAMES[n]] for n in FREQUENCY_NAMES]))
    band = ("none (no band-pass)" if diag.band is None
            else f"{diag.band[0]:.6g} - {diag.band[1]:.6g} Hz")
    console.print(_table(f"{title}: envelope lines (band {band}, resolution "
                         f"{diag.resolution:.3g} Hz)",
                         ["Hz", "amplitude", "matched", "deviation %"], _peak_rows(diag)))
    fault = diag.likely_fault or "none found"
    console.print(f"likely fault: [bold]{escape(fault)}[/bold]")
    console.print(f"[dim]{escape(diag.reason)}[/dim]")
    if diag.ball_defect_frequency_hz is not None:
        console.print(f"ball defect line measured at {diag.ball_defect_frequency_hz:.5g} Hz "
                      f"(kinematic {kin.hz('ball_defect'):.5g} Hz)")


def _peaks_json(diag) -> list[dict]:
    return peaks_json(diag.peaks)


def peaks_json(peaks) -> list[dict]:
    """Labelled lines (:func:`bearinglab.signal.match_peaks`) in the JSON form of
    ``peaks``: frequency_hz, amplitude, matched, harmonic, deviation and sideband keys."""
    keys = ("frequency_hz", "amplitude", "matched", "harmonic", "deviation", "sideband_of",
            "sideband_harmonic", "sideband_order", "modulation")
    return [{k: p[k] for k in keys if k in p} for p in peaks]


def spectrum_lines(x, sample_rate: float, kin, max_frequency: float, *,
                   count: int = COUNT, harmonics: int = HARMONICS, prominence: float = 4.0,
                   slip_tolerance: float = 0.08):
    """The plain (Hann, whole-record) amplitude spectrum of ``x`` and its largest lines up
    to ``max_frequency`` matched to the shaft and defect frequencies of ``kin`` as in the
    envelope analysis (:func:`bearinglab.signal.find_peaks`, :func:`match_peaks` with a
    window of at least one bin). Returns (Spectrum, labelled lines)."""
    spec = amplitude_spectrum(x, sample_rate)
    lines = find_peaks(spec, count=count, max_frequency=max_frequency, prominence=prominence)
    matched = match_peaks(lines, {name: kin.hz(name) for name in NAMES}, harmonics=harmonics,
                          slip_tolerance=slip_tolerance, resolution=spec.resolution)
    return spec, matched


def draw_spectrum(ax, spec, lines, kin, max_frequency: float, *, title: str, ylabel: str,
                  names=("shaft", "ftf", "bpfo", "bpfi", "ball_defect"),
                  harmonics: int = HARMONICS) -> None:
    """A plain spectrum up to ``max_frequency`` with the kinematic lines and their
    harmonics marked and the labelled peaks annotated."""
    f, a = spec.frequency, spec.amplitude
    shown = f <= max_frequency
    ax.plot(f[shown], a[shown], color="0.3", lw=0.8, label="spectrum")
    top = float(np.max(a[shown])) if np.any(shown) else 1.0
    for i, name in enumerate(names):
        base = kin.hz(name)
        marks = np.arange(1, harmonics + 1) * base
        marks = marks[marks <= max_frequency]
        if marks.size:
            ax.vlines(marks, 0, 1.05 * top, colors=f"C{i}", linestyles="--", lw=0.8, alpha=0.7,
                      label=f"{name.upper()} {base:.2f} Hz and harmonics")
    for p in lines:
        label = peak_label(p)
        ax.plot(p["frequency_hz"], p["amplitude"], "o", ms=4, color="k" if label == "-" else "C3")
        ax.annotate(label, (p["frequency_hz"], p["amplitude"]), textcoords="offset points",
                    xytext=(2, 4), fontsize=7, rotation=60)
    ax.set_title(title)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel(ylabel)
    ax.set_xlim(0, max_frequency)
    ax.set_ylim(0, 1.25 * top)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))


# ------------------------------------------------------------------ simulate
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
            "rigid, two cage revolutions slip).", show_default=False)] = None,
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
    _positive("--duration-s", duration_s, "a duration > 0 s")
    _positive("--sample-rate-hz", sample_rate_hz, "a sample rate > 0 Hz")
    _positive("--settle-s", settle_s, "a time >= 0 s", zero=True)
    _positive("--noise-ms2", noise_ms2, "an RMS >= 0 m/s^2", zero=True)
    if seed is not None and seed < 0:
        raise OptionError("--seed", seed, "an integer >= 0")
    _check_path("--output", output, SUFFIXES)
    _check_path("--plot", plot, (".png", ".svg", ".pdf"))
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
            raise _bad_defect(text, f"for {bearing.name or 'this bearing'}: "
                              f"{_defect_reason(exc)}") from None
    condition = OperatingCondition(radial_load=radial_load_n, axial_load=axial_load_n,
                                   shaft_speed=shaft_speed)
    err = Console(stderr=True)
    with Progress(TextColumn(f"simulating ({model.value} model)"), BarColumn(),
                  TextColumn("{task.percentage:>3.0f}%"), TimeElapsedColumn(), console=err,
                  transient=True, disable=json_output or not err.is_terminal) as progress:
        task = progress.add_task("simulate", total=1.0)
        try:
            sim = simulate(bearing, condition, defects, model=model.value, duration=duration_s,
                           sample_rate=sample_rate_hz, settle=settle_s, noise=noise_ms2,
                           seed=seed, imperfections=imperfections,
                           progress=lambda f: progress.update(task, completed=f))
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
    warnings = _geometry_warnings(bearing)
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
           "channel": diag.channel, "peaks": _peaks_json(diag),
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
           "warnings": warnings}
    if json_output:
        _emit_json(out)
        return
    rows = [["model", model.value], ["duration", f"{sim.signal.duration:g} s"],
            ["sample rate", f"{sim.signal.sample_rate:g} Hz"],
            ["speed, radial load", f"{speed_rpm:g} rpm, {radial_load_n:g} N"],
            ["defects", "; ".join(_defect_text(d) for d in defects) or "none (healthy)"],
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
    _print_diagnosis(diag, "acc_y")
    console.print(_table(f"{spectrum_channel}: plain spectrum lines (resolution "
                         f"{spec.resolution:.3g} Hz)", ["Hz", "amplitude", "matched",
                                                        "deviation %"],
                         _peak_rows_of(spectrum_peaks)))
    _print_warnings(warnings)


def form_errors_text(imperfections) -> str:
    """One line describing the form errors (or "none")."""
    if imperfections is None or imperfections.is_empty:
        return "none"
    parts = []
    for w in imperfections.waviness:
        where = w.race + (f" {w.ball}" if w.ball is not None else "")
        parts.append(f"{where} waviness q = {w.order}, {w.amplitude * 1e6:g} um")
    if imperfections.ball_size_errors is not None:
        parts.append(f"ball sizes within {imperfections.ball_size_errors.band * 1e6:.3g} um")
    for srf in imperfections.surfaces:
        parts.append(f"{srf.race} 3-D surface {srf.amplitude * 1e6:g} um RMS")
    return "; ".join(parts)


def _plot_spectra(diag, spec, lines, channel: str, path: Path) -> None:
    """Envelope spectrum (top) and plain spectrum (bottom) in one figure."""
    from ..plotting import _pyplot

    plt = _pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(11, 8))
    diag.plot(ax=axes[0])
    draw_spectrum(axes[1], spec, lines, diag.frequencies, diag.max_frequency,
                  title=f"plain spectrum of {channel} (resolution {spec.resolution:.3g} Hz)",
                  ylabel=f"amplitude [{'m' if channel.startswith('disp') else 'm/s^2'}]")
    fig.tight_layout()
    save_plot_figure(fig, path)


def _defect_text(d: Defect) -> str:
    x = d.to_dict()
    text = f"{d.location}: width {x['width_mm']:g} mm"
    if x["depth_mm"] is not None:
        text += f", depth {x['depth_mm']:g} mm"
    text += f", angle {x['angle_deg'] % 360:g} deg"
    return text + (f", ball {d.ball}" if d.location == "ball" else "")


def _defect_reason(exc: InputError) -> str:
    """Defect.check's error in the --defect spec's units."""
    if exc.parameter == "width":
        return f"width_mm = {exc.value * 1e3:g} must be {exc.allowed}"
    return f"{exc.parameter} = {exc.value!r} must be {exc.allowed}"


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


# ------------------------------------------------------------------ analyze
def _band(text: str):
    """--band-hz: "auto", "none" or "LO,HI" [Hz]."""
    word = text.strip().lower()
    if word == "auto":
        return "auto"
    if word == "none":
        return None
    try:
        low, high = (float(v) for v in text.split(","))
    except ValueError:
        low = high = math.nan
    if not (math.isfinite(low) and math.isfinite(high) and 0 < low < high):
        raise OptionError("--band-hz", text, "auto, none (no band-pass) or LO,HI in Hz with "
                          "0 < LO < HI")
    return low, high


_READ_FLAGS = {"path": "SIGNAL_FILE", "sample_rate": "--sample-rate-hz",
               "sample_rate_hz": "--sample-rate-hz", "channel": "--channel"}


@app.command("analyze")
@with_geometry
def analyze_command(
        signal_file: Annotated[Path, typer.Argument(
            help="Vibration record: .npz, .csv (time_s first column), .wav or .mat "
                 "(CWRU layout).", show_default=False)],
        channel: Annotated[str | None, typer.Option(
            "--channel", help="Channel to analyse (default: acc_y or DE if present, else "
            "the first).", show_default=False)] = None,
        sample_rate_hz: Annotated[float | None, typer.Option(
            "--sample-rate-hz", help="Sample rate [Hz], when the file does not say (CWRU "
            ".mat: 12000 or 48000) or to override it.", show_default=False)] = None,
        designation: Annotated[str | None, typer.Option(
            "--designation", help="Bearing designation or catalogue name (e.g. ER-16K, "
            "6205); optional with explicit geometry.", show_default=False)] = None,
        speed_rpm: Annotated[float | None, typer.Option(
            "--speed-rpm", help="Shaft speed [rpm] (default: the speed the file records).",
            show_default=False)] = None,
        band_hz: Annotated[str, typer.Option(
            "--band-hz", help="Demodulation band: auto (spectral kurtosis), none, or LO,HI "
            "[Hz].")] = "auto",
        json_output: JsonOpt = False, plot: PlotOpt = None, *, geometry):
    """Diagnose a vibration record by envelope analysis: the envelope lines matched to the
    bearing's defect frequencies and the likely fault."""
    band = _band(band_hz)
    _positive("--sample-rate-hz", sample_rate_hz, "a sample rate > 0 Hz")
    if speed_rpm is not None:
        speed_rad_s(speed_rpm)
    _check_path("--plot", plot, (".png", ".svg", ".pdf"))
    try:
        signal = read_signal(signal_file, sample_rate=sample_rate_hz)
        if channel is not None:
            signal.channel(channel)
    except InputError as exc:
        if exc.parameter == "sample_rate_hz" and sample_rate_hz is None:
            raise BearinglabError("--sample-rate-hz is required: the file does not store its "
                                  "sample rate (CWRU records are 12000 or 48000 Hz)") from None
        flag = _READ_FLAGS.get(exc.parameter)
        if flag is None:
            raise
        value = str(signal_file) if flag == "SIGNAL_FILE" else (
            channel if flag == "--channel" else sample_rate_hz)
        raise OptionError(flag, value, exc.allowed, _hint(exc)) from None
    if speed_rpm is None:
        recorded = signal.metadata.get("speed_rpm")
        if not isinstance(recorded, (int, float)) or isinstance(recorded, bool):
            raise BearinglabError("--speed-rpm is required: the file does not record the "
                                  "shaft speed")
        speed_rpm = float(recorded)
    shaft_speed = speed_rad_s(speed_rpm)
    bearing, _ = resolve_bearing(designation, geometry)
    kin = defect_frequencies(bearing, shaft_speed)
    try:
        diag = analyze_signal(signal, None, kin, channel=channel, band=band)
    except InputError as exc:
        if exc.parameter == "band":
            raise OptionError("--band-hz", band_hz, exc.allowed) from None
        raise
    if plot is not None:
        _save_plot(diag, plot)
    out = {"file": str(signal_file), "designation": designation, "channel": diag.channel,
           "sample_rate_hz": diag.sample_rate, "duration_s": signal.duration,
           "speed_rpm": speed_rpm, "kinematic": kin.to_dict(), "peaks": _peaks_json(diag),
           "likely_fault": diag.likely_fault, "faults": diag.faults, "scores": diag.scores,
           "reason": diag.reason,
           "band_hz": None if diag.band is None else list(diag.band),
           "resolution_hz": diag.resolution,
           "ball_defect_frequency_hz": diag.ball_defect_frequency_hz,
           "warnings": _geometry_warnings(bearing)}
    if json_output:
        _emit_json(out)
        return
    console.print(_table(f"{escape(signal_file.name)}: channel {diag.channel}", ["", "value"], [
        ["channels", ", ".join(signal.names)],
        ["samples", (f"{signal.n_samples} at {signal.sample_rate:g} Hz "
                     f"({signal.duration:g} s)")],
        ["bearing, speed", f"{bearing.name or 'bearing'}, {speed_rpm:g} rpm"]]))
    console.print(escape(_geometry_line(bearing)))
    _print_diagnosis(diag, diag.channel or "signal")
    _print_warnings(out["warnings"])


def _hint(exc: InputError) -> str:
    text = str(exc)
    head = f"expected {exc.allowed}"
    rest = text[text.find(head) + len(head):] if head in text else ""
    return rest[2:-1] if rest.startswith(" (") and rest.endswith(")") else ""

