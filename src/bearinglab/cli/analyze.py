"""The ``analyze`` command: diagnose a recorded vibration signal
(:func:`bearinglab.diagnosis.analyze_file`: the significance of each fault family's
harmonic series above the noise floor of the squared envelope spectrum, by Smith &
Randall's methods; docs/capabilities/diagnosis.md)."""

import math
from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError
from ._app import command_app
from ._geometry import (
    _geometry_warnings,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    JsonOpt,
    OptionError,
    _print_warnings,
    check_path,
    number_list,
    plot_option,
    positive,
    save_plot_figure,
    speed_rad_s,
)
from ._output import _emit_json, print_verdict

app = command_app()
PlotOpt = plot_option("the squared envelope spectrum")
#: InputError parameter of the library -> the option (or argument) to blame.
FLAGS = {
    "path": "SIGNAL_FILE",
    "sample_rate": "--sample-rate-hz",
    "sample_rate_hz": "--sample-rate-hz",
    "channel": "--channel",
    "record": "--record",
    "shaft_speed": "--speed-rpm",
    "speed_range": "--speed-range-rpm",
    "methods": "--method",
    "band": "--band-hz",
    "false_alarm": "--false-alarm",
    "signal_or_array": "SIGNAL_FILE",
    "tolerances": "--tolerance",
    "supply_frequency": "--supply-hz",
    "mesh_frequency": "--mesh-hz",
}


def _low_high(flag: str, text: str, allowed: str) -> tuple[float, float]:
    """An option LO,HI with 0 < LO < HI."""
    low, high = number_list(flag, text, allowed, counts=(2,))
    if not low < high:
        raise OptionError(flag, text, allowed)
    return low, high


def parse_band(text: str | None):
    """--band-hz: none (each method's own band), auto (the fast kurtogram's for every
    method) or LO,HI [Hz]."""
    if text is None or text.strip().lower() in ("none", "method"):
        return None
    if text.strip().lower() == "auto":
        return "auto"
    return _low_high(
        "--band-hz", text, "none (each method's own band), auto or LO,HI in Hz with 0 < LO < HI"
    )


def parse_speed(text: str | None):
    """--speed-rpm: a number [rpm] -> rad/s, or "auto"."""
    if text is None:
        return None
    if text.strip().lower() == "auto":
        return "auto"
    try:
        value = float(text)
    except ValueError:
        raise OptionError("--speed-rpm", text, "a speed in rpm or auto") from None
    return speed_rad_s(value)


def parse_range(text: str | None):
    """--speed-range-rpm LO,HI -> (lo, hi) [rad/s]."""
    if text is None:
        return None
    low, high = _low_high("--speed-range-rpm", text, "LO,HI in rpm with 0 < LO < HI")
    return low * math.pi / 30, high * math.pi / 30


def parse_tolerances(items: list[str] | None) -> dict | None:
    """--tolerance FAMILY=FRACTION or FAMILY=BELOW,ABOVE (repeatable)."""
    if not items:
        return None
    out = {}
    for item in items:
        family, sep, value = item.partition("=")
        try:
            parts = tuple(float(v) for v in value.split(","))
        except ValueError:
            parts = ()
        if not sep or len(parts) not in (1, 2):
            raise OptionError(
                "--tolerance",
                item,
                "FAMILY=FRACTION or FAMILY=BELOW,ABOVE, e.g. ball=0.05 or outer=0.01,0.02",
            )
        out[family.strip()] = parts[0] if len(parts) == 1 else parts
    return out


@app.command("analyze")
@with_geometry
def analyze_command(
    signal_file: Annotated[
        Path,
        typer.Argument(
            help="Vibration record: .npz, .csv (with a time column), .wav or .mat (CWRU "
            "variables, MATLAB structs such as MFPT's bearing.gs, v7.3).",
        ),
    ],
    channel: Annotated[
        str | None,
        typer.Option(
            "--channel",
            help="Channel or struct field path (e.g. DE, acc_y, bearing.gs or "
            "gs); default acc_y, DE or gs if present, else the first.",
        ),
    ] = None,
    record: Annotated[
        str | None,
        typer.Option(
            "--record",
            help="CWRU record of a .mat file holding several (e.g. X099); default the "
            "one named like the file.",
        ),
    ] = None,
    sample_rate_hz: Annotated[
        float | None,
        typer.Option(
            "--sample-rate-hz",
            help="Sample rate [Hz], when the file does not say (CWRU "
            ".mat: 12000 or 48000) or to override it.",
        ),
    ] = None,
    designation: Annotated[
        str | None,
        typer.Option(
            "--designation",
            help="Bearing designation or catalogue name (e.g. ER-16K, "
            "6205); optional with explicit geometry.",
        ),
    ] = None,
    speed_rpm: Annotated[
        str | None,
        typer.Option(
            "--speed-rpm",
            help="Shaft speed [rpm], or auto (the speed the signal shows); "
            "default the speed the file records.",
        ),
    ] = None,
    speed_range_rpm: Annotated[
        str | None,
        typer.Option(
            "--speed-range-rpm",
            help="LO,HI [rpm]: where --speed-rpm auto searches (default "
            "+-5 % of the recorded speed).",
        ),
    ] = None,
    method: Annotated[
        list[str] | None,
        typer.Option(
            "--method",
            help="raw, cpw, drs-sk or all (repeatable or comma-separated): "
            "Smith & Randall's Methods 1-3; ies: the improved envelope spectrum "
            "(spectral coherence), optional; default cpw (raw for bearinglab "
            "simulations).",
        ),
    ] = None,
    band_hz: Annotated[
        str | None,
        typer.Option(
            "--band-hz",
            help="Demodulation band: none (each method's own: whole band, or "
            "the kurtogram's for drs-sk), auto (the kurtogram's for every method) or LO,HI "
            "[Hz].",
        ),
    ] = None,
    tolerance: Annotated[
        list[str] | None,
        typer.Option(
            "--tolerance",
            help="Family tolerance FAMILY=FRACTION or FAMILY=BELOW,ABOVE "
            "(families outer, inner, ball, cage; defaults 0.02, 0.02, 0.07/0.02, 0.02); "
            "repeatable.",
        ),
    ] = None,
    false_alarm: Annotated[
        float,
        typer.Option(
            "--false-alarm", help="Largest probability of calling a fault on a record without one."
        ),
    ] = 0.01,
    supply_hz: Annotated[
        float | None,
        typer.Option(
            "--supply-hz",
            help="Electrical supply frequency [Hz]: its harmonics are not bearing lines.",
        ),
    ] = None,
    mesh_hz: Annotated[
        float | None,
        typer.Option(
            "--mesh-hz",
            help="Gear-mesh frequency [Hz]: its harmonics are not bearing lines.",
        ),
    ] = None,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Diagnose a vibration record by envelope analysis."""
    positive("--sample-rate-hz", sample_rate_hz, "a sample rate > 0 Hz")
    positive("--supply-hz", supply_hz, "a frequency > 0 Hz")
    positive("--mesh-hz", mesh_hz, "a frequency > 0 Hz")
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
    options = {
        "shaft_speed": parse_speed(speed_rpm),
        "speed_range": parse_range(speed_range_rpm),
        "channel": channel,
        "record": record,
        "sample_rate": sample_rate_hz,
        "band": parse_band(band_hz),
        "methods": method or None,
        "tolerances": parse_tolerances(tolerance),
        "false_alarm": false_alarm,
        "supply_frequency": supply_hz,
        "mesh_frequency": mesh_hz,
    }
    bearing, _ = resolve_bearing(designation, geometry)
    from ..diagnosis import analyze_file

    try:
        diag = analyze_file(signal_file, bearing, **options)
    except InputError as exc:
        flag = FLAGS.get(exc.parameter.split("[")[0])
        if flag is None:
            raise
        given = {
            "SIGNAL_FILE": str(signal_file),
            "--speed-rpm": speed_rpm,
            "--method": method,
            "--band-hz": band_hz,
            "--channel": channel,
            "--record": record,
            "--sample-rate-hz": sample_rate_hz,
            "--tolerance": tolerance,
            "--speed-range-rpm": speed_range_rpm,
            "--false-alarm": false_alarm,
        }
        value = given.get(flag, exc.value)
        if flag == "--speed-rpm" and speed_rpm is None:
            raise OptionError(
                flag, None, "a speed in rpm or auto (the file does not record the shaft speed)"
            ) from None
        if flag == "--sample-rate-hz" and sample_rate_hz is None and exc.value is None:
            raise OptionError(
                flag,
                None,
                "the sample rate in Hz (the file does not store it; "
                "CWRU records are 12000 or 48000 Hz)",
            ) from None
        hint = exc.hint or (
            f"it holds {exc.value}"
            if flag == "SIGNAL_FILE" and exc.parameter == "signal_or_array"
            else ""
        )
        if flag == "--sample-rate-hz" and sample_rate_hz is None:
            value = exc.value  # the file's own rate
        raise OptionError(flag, value, exc.allowed, hint) from None
    if plot is not None:
        save_plot_figure(diag.plot()[0], plot)
    out = {"file": str(signal_file), "designation": designation, **diag.to_dict()}
    out["warnings"] = list(out["warnings"]) + _geometry_warnings(bearing)
    if json_output:
        _emit_json(out)
        return
    print_verdict(diag, signal_file.name, bearing)
    _print_warnings(out["warnings"])
