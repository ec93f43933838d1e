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

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

from ..diagnosis import analyze_signal, peak_label
from ..dynamics import Defect, simulate
from ..errors import BearinglabError, InputError
from ..kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from ..operating import OperatingCondition
from ..signal import SUFFIXES, read_signal, write_signal
from ._app import app, console
from ._inputs import (
    MAX_LOAD_N,
    MAX_SPEED_RPM,
    JsonOpt,
    OptionError,
    _geometry_line,
    _geometry_warnings,
    _print_warnings,
    resolve_bearing,
    with_geometry,
)
from ._output import _emit_json, _save_plot, _table

DesignationArg = Annotated[str | None, typer.Argument(
    help="Bearing designation or catalogue name (e.g. ER-16K); optional with explicit "
         "geometry.", show_default=False)]
PlotOpt = Annotated[Path | None, typer.Option(
    "--plot", help="Also draw the envelope spectrum to this .png, .svg or .pdf file.",
    show_default=False)]
#: What a --defect specification may hold.
DEFECT_ALLOWED = ("LOCATION:KEY=VALUE,... with LOCATION outer, inner or ball and keys "
                  "width_mm (> 0, required), depth_mm (> 0), angle_deg (outer: position from "
                  "+x towards +y, 270 = bottom; inner: position at t = 0; ball: spin phase) "
                  "and ball (ball index, ball defects only), e.g. "
                  "outer:width_mm=1.2,depth_mm=0.25")
_DEFECT_KEYS = {"outer": ("width_mm", "depth_mm", "angle_deg"),
                "inner": ("width_mm", "depth_mm", "angle_deg"),
                "ball": ("width_mm", "depth_mm", "angle_deg", "ball")}


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
    location, sep, rest = text.strip().partition(":")
    location = location.strip().lower()
    if location not in _DEFECT_KEYS:
        raise _bad_defect(text, f"unknown location {location!r}")
    if not sep or not rest.strip():
        raise _bad_defect(text, "no KEY=VALUE given; width_mm is required")
    values: dict = {}
    for item in rest.split(","):
        key, eq, value = (s.strip() for s in item.partition("="))
        if key not in _DEFECT_KEYS[location]:
            raise _bad_defect(text, f"unknown key {key!r} for {location} defects (keys: "
                              f"{', '.join(_DEFECT_KEYS[location])})")
        if not eq or not value:
            raise _bad_defect(text, f"{key} has no value")
        if key in values:
            raise _bad_defect(text, f"{key} given twice")
        if key == "ball":
            try:
                number = int(value)
            except ValueError:
                raise _bad_defect(text, f"ball = {value!r} is not a whole number") from None
            if number < 0:
                raise _bad_defect(text, "ball must be >= 0")
        else:
            try:
                number = float(value)
            except ValueError:
                raise _bad_defect(text, f"{key} = {value!r} is not a number") from None
            if not math.isfinite(number):
                raise _bad_defect(text, f"{key} must be finite")
            if key in ("width_mm", "depth_mm") and number <= 0:
                raise _bad_defect(text, f"{key} must be > 0")
        values[key] = number
    if "width_mm" not in values:
        raise _bad_defect(text, "width_mm is required")
    kwargs = {"width": values["width_mm"] * 1e-3,
              "depth": values["depth_mm"] * 1e-3 if "depth_mm" in values else None}
    if "angle_deg" in values:  # into [-pi, pi): 270 deg is -90 deg, the bottom
        kwargs["angle"] = (math.radians(values["angle_deg"]) + math.pi) % (2 * math.pi) - math.pi
    if "ball" in values:
        kwargs["ball"] = values["ball"]
    return Defect(location, **kwargs)


def _speed(value: float) -> float:
    """Shaft speed [rad/s] from --speed-rpm (> 0)."""
    if not (math.isfinite(value) and 0 < value <= MAX_SPEED_RPM):
        raise OptionError("--speed-rpm", value, f"a speed in (0, {MAX_SPEED_RPM:g}] rpm")
    return value * math.pi / 30


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
    rows = []
    for p in diag.peaks:
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
    keys = ("frequency_hz", "amplitude", "matched", "harmonic", "deviation", "sideband_of",
            "sideband_harmonic", "sideband_order", "modulation")
    return [{k: p[k] for k in keys if k in p} for p in diag.peaks]


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
        seed: Annotated[int | None, typer.Option(
            "--seed", help="Seed of the noise.", show_default=False)] = None,
        output: Annotated[Path | None, typer.Option(
            "-o", "--output", help="Write the signal to this .npz, .csv, .wav or .mat file.",
            show_default=False)] = None,
        json_output: JsonOpt = False, plot: PlotOpt = None, *, geometry):
    """Simulate the vibration of a bearing with defects (seed 003 rigid model or seed 004
    slip model) and diagnose it by envelope analysis."""
    shaft_speed = _speed(speed_rpm)
    for flag, value, signed in (("--radial-load-n", radial_load_n, False),
                                ("--axial-load-n", axial_load_n, True)):
        low = -MAX_LOAD_N if signed else 0.0
        if not (math.isfinite(value) and low <= value <= MAX_LOAD_N):
            raise OptionError(flag, value, f"a load in [{low:g}, {MAX_LOAD_N:g}] N")
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
    specs = list(defect or [])
    defects = [parse_defect(text) for text in specs]
    bearing, _ = resolve_bearing(designation, geometry)
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
                           seed=seed,
                           progress=lambda f: progress.update(task, completed=f))
        except InputError as exc:
            raise _simulate_error(exc, bearing) from None
    diag = analyze_signal(sim.signal, None, sim.kinematic, channel="acc_y")
    if output is not None:
        _write(output, sim.signal)
    if plot is not None:
        _save_plot(diag, plot)
    has_ball = any(d.location == "ball" for d in defects)
    warnings = _geometry_warnings(bearing)
    if axial_load_n:
        warnings.append(f"--axial-load-n {axial_load_n:g} N does not enter the {model.value} "
                        "model (it is planar: radial load only)")
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
           "defects": [d.to_dict() for d in defects],
           "output": None if output is None else str(output), "stats": dict(sim.stats),
           "warnings": warnings}
    if json_output:
        _emit_json(out)
        return
    rows = [["model", model.value], ["duration", f"{sim.signal.duration:g} s"],
            ["sample rate", f"{sim.signal.sample_rate:g} Hz"],
            ["speed, radial load", f"{speed_rpm:g} rpm, {radial_load_n:g} N"],
            ["defects", "; ".join(_defect_text(d) for d in defects) or "none (healthy)"],
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
    _print_warnings(warnings)


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
        _speed(speed_rpm)
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
    shaft_speed = _speed(speed_rpm)
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

