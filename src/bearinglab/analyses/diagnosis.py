"""The diagnosis of a recorded vibration signal (``analyze``): the request's inputs and
:func:`diagnose`, which reads them and calls :func:`bearinglab.diagnosis.analyze_file`
once; its errors name the input at fault (docs/capabilities/diagnosis.md)."""

from __future__ import annotations

import math
from dataclasses import replace

from ..errors import InputError
from ..inputs import BEARING, INPUTS, Input, bearing_from, bearing_warnings, input_for
from .base import FILES, Analysis, plot_file

#: The diagnosis' inputs besides the bearing.
DIAGNOSIS_INPUTS: dict[str, Input] = {
    "signal_file": INPUTS["signal_file"].with_(sets=("path", "signal_or_array")),
    "channel": INPUTS["channel"],
    "record": Input(
        "text",
        None,
        "CWRU record of a .mat file holding several (e.g. X099); default the one named like "
        "the file.",
    ),
    "sample_rate_hz": INPUTS["sample_rate_hz"].with_(
        help="Sample rate [Hz], when the file does not say (CWRU .mat: 12000 or 48000) or to "
        "override it."
    ),
    "speed_rpm": INPUTS["speed_rpm"].with_(
        kind="text",
        help="Shaft speed [rpm], or auto (the speed the signal shows); default the speed the "
        "file records.",
    ),
    "speed_range_rpm": Input(
        "text",
        None,
        "LO,HI [rpm]: where `speed_rpm` auto searches (default +-5 % of the recorded speed).",
    ),
    "method": Input(
        "texts",
        None,
        "raw, cpw, drs-sk or all (repeatable or comma-separated): Smith & Randall's Methods "
        "1-3; ies: the improved envelope spectrum (spectral coherence), optional; default cpw "
        "(raw and cpw for bearinglab simulations).",
        sets="methods",
    ),
    "band_hz": Input(
        "text",
        None,
        "Demodulation band: none (each method's own: whole band, or the kurtogram's for "
        "drs-sk), auto (the kurtogram's for every method) or LO,HI [Hz].",
    ),
    "tolerance": Input(
        "texts",
        None,
        "Family tolerance FAMILY=FRACTION or FAMILY=BELOW,ABOVE (families outer, inner, ball, "
        "cage; defaults 0.02, 0.02, 0.07/0.02, 0.02); repeatable.",
        sets="tolerances",
    ),
    "false_alarm": Input(
        "number",
        0.01,
        "Largest probability of calling a fault on a record without one.",
    ),
    "supply_hz": Input(
        "number",
        None,
        "Electrical supply frequency [Hz]: its harmonics are not bearing lines.",
        low=0.0,
        low_open=True,
        what="a frequency",
        sets="supply_frequency",
    ),
    "mesh_hz": Input(
        "number",
        None,
        "Gear-mesh frequency [Hz]: its harmonics are not bearing lines.",
        low=0.0,
        low_open=True,
        what="a frequency",
        sets="mesh_frequency",
    ),
    "radial_load_n": INPUTS["radial_load_n"].with_(
        default=None,
        help="Radial load on the bearing [N], for the width of a race defect found (what "
        "the ball bridges at the edges); default 0.032 x its dynamic rating C, the interval "
        "then spanning 0.01-0.1 C.",
        low_open=True,
    ),
}
#: The inputs of ``analyze``: the record's, then the bearing's.
ANALYZE_INPUTS = {
    **DIAGNOSIS_INPUTS,
    **{name: INPUTS[name] for name in BEARING},
    "designation": INPUTS["designation"].with_(
        help="Bearing designation or catalogue name (e.g. ER-16K, 6205); optional with "
        "explicit geometry."
    ),
}


def _low_high(name: str, text: str, allowed: str) -> tuple[float, float]:
    """An input LO,HI with 0 < LO < HI."""
    try:
        low, high = (float(v) for v in text.split(","))
    except ValueError:
        raise InputError(name, text, allowed) from None
    if not (math.isfinite(high) and 0 < low < high):
        raise InputError(name, text, allowed)
    return low, high


def parse_band(text: str | None):
    """band_hz: none (each method's own band), auto (the fast kurtogram's for every
    method) or LO,HI [Hz]."""
    if text is None or text.strip().lower() in ("none", "method"):
        return None
    if text.strip().lower() == "auto":
        return "auto"
    return _low_high(
        "band_hz", text, "none (each method's own band), auto or LO,HI in Hz with 0 < LO < HI"
    )


def parse_speed(text):
    """speed_rpm: a number [rpm] -> rad/s, or "auto"."""
    if text is None:
        return None
    if str(text).strip().lower() == "auto":
        return "auto"
    try:
        value = float(text)
    except ValueError:
        raise InputError("speed_rpm", text, "a speed in rpm or auto") from None
    INPUTS["speed_rpm"].check("speed_rpm", value)
    if value <= 0:
        raise InputError("speed_rpm", value, "a speed > 0 rpm or auto")
    return value * math.pi / 30


def parse_range(text: str | None):
    """speed_range_rpm LO,HI -> (lo, hi) [rad/s]."""
    if text is None:
        return None
    low, high = _low_high("speed_range_rpm", text, "LO,HI in rpm with 0 < LO < HI")
    return low * math.pi / 30, high * math.pi / 30


def parse_tolerances(items) -> dict | None:
    """tolerance FAMILY=FRACTION or FAMILY=BELOW,ABOVE (repeatable)."""
    if not items:
        return None
    out = {}
    for item in [items] if isinstance(items, str) else items:
        family, sep, value = item.partition("=")
        try:
            parts = tuple(float(v) for v in value.split(","))
        except ValueError:
            parts = ()
        if not sep or len(parts) not in (1, 2):
            raise InputError(
                "tolerance",
                item,
                "FAMILY=FRACTION or FAMILY=BELOW,ABOVE, e.g. ball=0.05 or outer=0.01,0.02",
            )
        out[family.strip()] = parts[0] if len(parts) == 1 else parts
    return out


def diagnose(values: dict):
    """The ``analyze`` request: the diagnosis of the record ``signal_file`` with the
    bearing of the request (:func:`bearinglab.diagnosis.analyze_file`); its warnings
    include the bearing's."""
    from ..diagnosis import analyze_file

    options = {
        "shaft_speed": parse_speed(values.get("speed_rpm")),
        "speed_range": parse_range(values.get("speed_range_rpm")),
        "channel": values.get("channel"),
        "record": values.get("record"),
        "sample_rate": values.get("sample_rate_hz"),
        "band": parse_band(values.get("band_hz")),
        "methods": values.get("method") or None,
        "tolerances": parse_tolerances(values.get("tolerance")),
        "false_alarm": values.get("false_alarm", 0.01),
        "supply_frequency": values.get("supply_hz"),
        "mesh_frequency": values.get("mesh_hz"),
        "radial_load": values.get("radial_load_n"),
    }
    bearing, decoded = bearing_from(values)
    try:
        diag = analyze_file(values["signal_file"], bearing, **options)
    except InputError as exc:
        name = input_for(exc.parameter.split("[")[0], DIAGNOSIS_INPUTS)
        if name is None:
            raise
        given = values.get(name)
        if name == "speed_rpm" and given is None:
            raise InputError(
                name, None, "a speed in rpm or auto (the file does not record the shaft speed)"
            ) from None
        if name == "sample_rate_hz" and given is None:
            if exc.value is None:
                raise InputError(
                    name,
                    None,
                    "the sample rate in Hz (the file does not store it; CWRU records are "
                    "12000 or 48000 Hz)",
                ) from None
            given = exc.value  # the file's own rate
        hint = exc.hint or (
            f"it holds {exc.value}"
            if name == "signal_file" and exc.parameter == "signal_or_array"
            else ""
        )
        value = str(given) if name == "signal_file" else given
        raise InputError(
            name, value if value is not None else exc.value, exc.allowed, hint
        ) from None
    return replace(diag, warnings=(*diag.warnings, *bearing_warnings(bearing, decoded)))


ANALYZE = Analysis(
    "analyze",
    "The diagnosis of a recorded vibration signal (analyze_file).",
    ANALYZE_INPUTS,
    run=diagnose,
    files=plot_file(
        "the squared envelope spectrum (and a race defect's passages averaged, entry and exit "
        "marked)"
    ),
)


def check_labelled_files(folder) -> None:
    """Every recording labels.csv names must be there, before any record is diagnosed: a
    benchmark that silently scores fewer records than its labels list misleads. The error
    names labels.csv, its line and the missing file."""
    from pathlib import Path

    from ..diagnosis.benchmark import read_labels

    folder = Path(folder)
    for line, row in enumerate(read_labels(folder), start=2):
        path = folder / row["file"]
        if not path.is_file():
            raise InputError(
                f"{folder / 'labels.csv'} line {line}: file",
                row["file"],
                "a recording in the folder",
                f"there is no {path}",
            )


def benchmark(values: dict, progress=None, keep_spectra: bool = True):
    """The ``benchmark`` request: the diagnosis over the labelled recordings of `folder`
    (:func:`bearinglab.diagnosis.run_benchmark`), every file the labels name checked first;
    a benchmark none of whose records could be diagnosed is an error with the first
    record's reason, not a table of errors."""
    from ..diagnosis import run_benchmark
    from ..errors import BearinglabError

    check_labelled_files(values["folder"])
    result = run_benchmark(
        values["folder"],
        methods=values.get("method") or None,
        jobs=values.get("jobs") or 1,
        progress=progress,
        keep_spectra=keep_spectra,
    )
    records = result.to_dict()["records"]
    errors = [r for r in records if r["error"]]
    if errors and len(errors) == len(records):
        first, n, where = errors[0], len(errors), values["folder"]
        raise BearinglabError(
            (
                f"none of the {n} records of {where} could be diagnosed; the first, "
                if n > 1
                else f"the one record of {where} could not be diagnosed: "
            )
            + f"{first['file']}: {' '.join(str(first['error']).split())}"
        )
    return result


BENCHMARK = Analysis(
    "benchmark",
    "The diagnosis over a folder of labelled recordings (run_benchmark).",
    {
        "folder": INPUTS["folder"].with_(
            help="Folder with a labels.csv (file, channel, sample_rate_hz, speed_rpm, the "
            "bearing, fault) and the recordings it names.",
        ),
        "method": DIAGNOSIS_INPUTS["method"].with_(
            help="raw, cpw, drs-sk, all (the three) or ies (repeatable or comma-separated); "
            "each is also run on its own; default cpw."
        ),
        "jobs": INPUTS["jobs"].with_(help="Records diagnosed at once (processes)."),
    },
    run=benchmark,
    files={
        "html": FILES["html"].with_(
            help="Also write a page with each record's envelope spectrum and the lines it matched."
        )
    },
)

__all__ = ["ANALYZE", "ANALYZE_INPUTS", "BENCHMARK", "DIAGNOSIS_INPUTS", "benchmark", "diagnose"]
