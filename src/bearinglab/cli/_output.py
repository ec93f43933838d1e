"""Output helpers: JSON (tidied, finite), rich tables, numbered references, plots."""

import json
import math
import sys
from contextlib import contextmanager
from pathlib import Path

from rich.markup import escape
from rich.table import Table

from ..errors import BearinglabError
from ..geometry import BallBearing
from ..plotting import save_figure
from ._app import console
from ._inputs import (
    OptionError,
)


# ------------------------------------------------------------------ output helpers
def _tidy(value):
    """Round floats to 12 significant digits (52.00000000000001 -> 52.0) for JSON."""
    if isinstance(value, float):
        return float(f"{value:.12g}")
    if isinstance(value, dict):
        return {k: _tidy(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_tidy(v) for v in value]
    return value


def _check_finite(value, path: str = "") -> None:
    """Refuse to print a result that is not finite (inf or NaN) with a one-line error."""
    if isinstance(value, float) and not math.isfinite(value):
        raise BearinglabError(f"the result {path.lstrip('.') or 'value'} = {value} is not "
                              "finite for these inputs; check that they are in range")
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(v, f"{path}.{k}")
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            _check_finite(v, f"{path}[{i}]")


def _emit_json(obj: dict) -> None:
    _check_finite(obj)
    sys.stdout.write(json.dumps(_tidy(obj), indent=2, allow_nan=False) + "\n")


def _save_plot(result, plot: Path) -> None:
    try:
        save_figure(result.plot()[0], plot)
    except OSError as exc:
        raise OptionError("--plot", str(plot), "a writable file",
                          exc.strerror or type(exc).__name__) from None


def _fmt(value, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if isinstance(value, float):
        return f"{value:.{digits}g}"
    return escape(str(value))


def _table(title: str, columns: list[str], rows: list[list]) -> Table:
    table = Table(title=title, title_justify="left", show_header=True, header_style="bold")
    for i, col in enumerate(columns):
        # a header's words are never cut: its column is at least as wide as its longest word
        table.add_column(escape(col), justify="right" if i and col not in ("source", "meaning")
                         else "left", min_width=max(map(len, col.split()), default=1))
    for row in rows:
        table.add_row(*(_fmt(v) for v in row))
    return table


class _References:
    """Numbers each distinct reference once, so tables show "catalog [1]" and the full
    references are printed once underneath."""

    def __init__(self) -> None:
        self.refs: list[str] = []

    def cell(self, bearing: BallBearing, field: str) -> str:
        src = bearing.sources.get(field)
        if src is None:
            return "default"
        if not src.reference:
            return src.kind
        if src.reference not in self.refs:
            self.refs.append(src.reference)
        return f"{src.kind} [{self.refs.index(src.reference) + 1}]"

    def print(self) -> None:
        for i, ref in enumerate(self.refs, start=1):
            console.print(f"[dim]\\[{i}] {escape(ref)}[/dim]")


# ------------------------------------------------------------------ diagnosis
def peak_rows(peaks) -> list[list]:
    """Table rows (Hz, amplitude, label, deviation %) of labelled lines."""
    from ..diagnosis import peak_label

    rows = []
    for p in peaks:
        deviation = p.get("deviation")
        rows.append([p["frequency_hz"], p["amplitude"], peak_label(p),
                     None if deviation is None else 100.0 * deviation])
    return rows


def print_diagnosis(diag, title: str) -> None:
    """The kinematic frequencies, the envelope lines and the verdict, as tables."""
    from ..kinematics import FREQUENCY_NAMES, LONG_NAMES

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
                         ["Hz", "amplitude", "matched", "deviation %"], peak_rows(diag.peaks)))
    fault = (diag.likely_fault or "no fault detected").replace("_", " ")
    console.print(f"likely fault: [bold]{escape(fault)}[/bold]")
    console.print(f"[dim]{escape(diag.reason)}[/dim]")
    if diag.ball_defect_frequency_hz is not None:
        console.print(f"ball defect line measured at {diag.ball_defect_frequency_hz:.5g} Hz "
                      f"(kinematic {kin.hz('ball_defect'):.5g} Hz)")


def peaks_json(peaks) -> list[dict]:
    """Labelled lines (:func:`bearinglab.signal.match_peaks`) in the JSON form of
    ``peaks``: frequency_hz, amplitude, matched, harmonic, deviation and sideband keys."""
    keys = ("frequency_hz", "amplitude", "matched", "harmonic", "deviation", "sideband_of",
            "sideband_harmonic", "sideband_order", "modulation")
    return [{k: p[k] for k in keys if k in p} for p in peaks]


# ------------------------------------------------------------------ progress
@contextmanager
def progress_bar(description: str, *, enabled: bool = True):
    """A transient progress bar on stderr (shown only on a terminal and when ``enabled``).

    Yields ``update(fraction=None, description=None)``; either may be left out."""
    from rich.console import Console
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    err = Console(stderr=True)
    with Progress(TextColumn("{task.description}"), BarColumn(),
                  TextColumn("{task.percentage:>3.0f}%"), TimeElapsedColumn(), console=err,
                  transient=True, disable=not enabled or not err.is_terminal) as progress:
        task = progress.add_task(description, total=1.0)

        def update(fraction: float | None = None, description: str | None = None) -> None:
            progress.update(task, completed=fraction, description=description)

        yield update


def simulation_stage(model: str) -> str:
    """What a progress bar says before a simulation starts: that the first run in this
    install compiles the model (numba), when it will."""
    from ..dynamics import needs_compiling

    if needs_compiling(model):
        return f"compiling the {model} model (first run only; later runs load it)"
    return f"simulating ({model} model)"
