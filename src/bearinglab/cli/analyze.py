"""The ``analyze`` command: diagnose a recorded vibration signal by envelope analysis
(:func:`bearinglab.diagnosis.analyze_signal`, after Randall & Antoni 2011)."""

import math
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..diagnosis import analyze_signal
from ..errors import BearinglabError, InputError
from ..kinematics import defect_frequencies
from ..signal import read_signal
from ._app import command_app, console
from ._inputs import (
    JsonOpt,
    OptionError,
    _geometry_line,
    _geometry_warnings,
    _print_warnings,
    check_path,
    positive,
    resolve_bearing,
    speed_rad_s,
    with_geometry,
)
from ._output import _emit_json, _save_plot, _table, peaks_json, print_diagnosis

app = command_app()
PlotOpt = Annotated[Path | None, typer.Option(
    "--plot", help="Also draw the envelope spectrum to this .png, .svg or .pdf file.",
    show_default=False)]


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
    positive("--sample-rate-hz", sample_rate_hz, "a sample rate > 0 Hz")
    if speed_rpm is not None:
        speed_rad_s(speed_rpm)
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
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
        raise OptionError(flag, value, exc.allowed, exc.hint) from None
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
           "speed_rpm": speed_rpm, "kinematic": kin.to_dict(), "peaks": peaks_json(diag.peaks),
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
    print_diagnosis(diag, diag.channel or "signal")
    _print_warnings(out["warnings"])

