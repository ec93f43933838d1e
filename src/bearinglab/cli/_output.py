"""Output helpers: JSON (tidied, finite), rich tables, numbered references, plots."""

import json
import math
import sys
from contextlib import contextmanager
from pathlib import Path

from rich import box
from rich.markup import escape
from rich.table import Table

from ..errors import BearinglabError
from ..geometry import References
from ._app import console
from ._inputs import save_plot_figure


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
        raise BearinglabError(
            f"the result {path.lstrip('.') or 'value'} = {value} is not "
            "finite for these inputs; check that they are in range"
        )
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(v, f"{path}.{k}")
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            _check_finite(v, f"{path}[{i}]")


def _emit_json(obj: dict) -> None:
    """Print ``obj`` as JSON; its warnings name the inputs as this command's flags."""
    from ._words import in_flags

    _check_finite(obj)
    if isinstance(obj.get("warnings"), list):
        obj = {
            **obj,
            "warnings": [in_flags(w) if isinstance(w, str) else w for w in obj["warnings"]],
        }
    sys.stdout.write(json.dumps(_tidy(obj), indent=2, allow_nan=False) + "\n")


def _plot_and_emit(out: dict, json_output: bool, result, plot: Path | None) -> bool:
    """Draw ``result`` to ``plot`` when one is given, then print ``out`` as JSON (True: the
    command is done) or check that it is finite for the tables (False)."""
    if plot is not None:
        save_plot_figure(result.plot()[0], plot)
    if json_output:
        _emit_json(out)
        return True
    _check_finite(out)
    return False


def _fmt(value, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if isinstance(value, float):
        return f"{value:.{digits}g}"
    return escape(str(value))


def _number(value) -> str:
    """A value for a table: 4 significant digits, no exponent from 1e-4 to 1e6; None (or
    a NaN, a table's "not computed") is "-", a string is shown as it is."""
    if value is None or (isinstance(value, float) and value != value):
        return "-"
    if isinstance(value, str):
        return value
    if 1e4 <= abs(value) < 1e6:
        return f"{value:.0f}"
    return f"{value:.4g}"


class _Table(Table):
    """A rich Table whose header words are kept whole (each column's ``min_width``) as
    long as the table then fits; where it would not, the minimum widths are dropped
    before drawing. Rich lays a table out without the minima and widens the columns
    back to them afterwards, so a narrow terminal cropped the last column instead of
    wrapping (``benchmark`` at 80 columns)."""

    def __rich_console__(self, console, options):
        # rich's own layout (a private method, pinned by tests/unit/test_cli.py's widths)
        widths = self._calculate_column_widths(console, options)
        if sum(widths) + self._extra_width > options.max_width:
            for column in self.columns:
                column.min_width = None
        yield from super().__rich_console__(console, options)


def _table(
    title: str, columns: list[str], rows: list[list], words: bool = False, whole: int | None = None
) -> Table:
    """A table of ``rows`` under ``columns``; ``words``: a table of words (left-aligned,
    no vertical rules), whose many columns then fit 80 terminal columns whole; column
    ``whole`` (an index) is never folded (file names: the other columns wrap first)."""
    light = (
        dict(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False, collapse_padding=True)
        if words
        else {}
    )
    table = _Table(
        title=title, title_justify="left", show_header=True, header_style="bold", **light
    )
    for i, col in enumerate(columns):
        # a header's words are never cut: its column is at least as wide as its longest word;
        # in a narrow terminal a long cell wraps onto more lines instead of losing its end
        table.add_column(
            escape(col),
            justify="right" if i and not words and col not in ("source", "meaning") else "left",
            min_width=max(
                max(map(len, col.split()), default=1),
                max((len(_fmt(r[i])) for r in rows), default=1) if i == whole else 1,
                max((len(w) for r in rows for w in _fmt(r[i]).split()), default=1) if words else 1,
            ),
            overflow="fold",
            no_wrap=i == whole,
        )
    for row in rows:
        table.add_row(*(_fmt(v) for v in row))
    return table


class _References(References):
    """Source references numbered once, printed under the table."""

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
        rows.append(
            [
                p["frequency_hz"],
                p["amplitude"],
                peak_label(p),
                None if deviation is None else 100.0 * deviation,
            ]
        )
    return rows


# ------------------------------------------------------------------ progress
@contextmanager
def progress_bar(description: str, *, enabled: bool = True, unit: str | None = None):
    """The progress bar of a long command, on stderr (drawn only on a terminal and when
    ``enabled``).

    With ``unit`` (``cases``, ``records``: what the engine counts) it yields the engine's
    ``progress(done, total)`` (:mod:`bearinglab.engine`), shows done/total, the time spent
    and the time left, stays on screen at the end, and prints the engine's notes (the
    dashboard of a long run) above itself. Without, it yields
    ``update(fraction=None, description=None)`` (either may be left out) and disappears at
    the end."""
    import logging

    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    err = Console(stderr=True)
    columns = (
        (MofNCompleteColumn(), TimeElapsedColumn(), TextColumn("left"), TimeRemainingColumn())
        if unit
        else (TextColumn("{task.percentage:>3.0f}%"), TimeElapsedColumn())
    )
    with Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        *columns,
        console=err,
        transient=unit is None,
        disable=not enabled or not err.is_terminal,
    ) as bar:
        task = bar.add_task(description, total=None if unit else 1.0)
        if unit is None:

            def update(fraction: float | None = None, description: str | None = None) -> None:
                bar.update(task, completed=fraction, description=description)

            yield update
            return

        def progress(done: int, total: int) -> None:
            bar.update(task, completed=done, total=total)

        class Notes(logging.Handler):
            def emit(self, record: logging.LogRecord) -> None:
                err.print(escape(record.getMessage()))

        if not enabled:  # --json: only the JSON is printed
            yield progress
            return
        engine = logging.getLogger("bearinglab.engine")
        saved = engine.level, engine.propagate
        notes = Notes(logging.INFO)
        engine.addHandler(notes)
        engine.setLevel(logging.INFO)
        engine.propagate = False
        try:
            yield progress
        finally:
            engine.removeHandler(notes)
            engine.setLevel(saved[0])
            engine.propagate = saved[1]


def simulation_stage(model: str) -> str:
    """What a progress bar says before a simulation starts: that the first run in this
    install compiles the model (numba), when it will."""
    from ..dynamics import needs_compiling

    if needs_compiling(model):
        return f"compiling the {model} model (first run only; later runs load it)"
    return f"simulating ({model} model)"


def print_verdict(diag, name: str, bearing) -> None:
    """The record, the family tests, the lines and the verdict as tables (the same data as
    ``to_dict``: a roller bearing's rolling-element family named "roller")."""
    d = diag.to_dict()
    speed = diag.speed
    measured = speed.get("measured_rpm")
    console.print(
        _table(
            f"{escape(name)}: channel {diag.channel}",
            ["", "value"],
            [
                ["sample rate", f"{diag.sample_rate:g} Hz"],
                ["bearing", bearing.name or "bearing"],
                ["speed used", f"{speed['used_rpm']:.6g} rpm ({speed['source']})"],
                [
                    "speed the signal shows",
                    "no shaft line found" if measured is None else f"{measured:.6g} rpm",
                ],
                ["methods", ", ".join(diag.methods)],
                [
                    "band",
                    "; ".join(
                        f"{m}: "
                        + (
                            "whole band"
                            if s.band is None
                            else f"{s.band[0]:.6g} - {s.band[1]:.6g} Hz"
                        )
                        for m, s in diag.spectra.items()
                    ),
                ],
                ["resolution", f"{diag.resolution:.3g} Hz"],
            ],
        )
    )
    from ..inputs import geometry_line

    console.print(escape(geometry_line(bearing)))
    rows = [
        [
            name,
            t["method"],
            t["kinematic_hz"],
            t["fundamental_hz"],
            100 * t["slip"],
            round(t["significance"], 2),
            "yes" if t["passed"] else "no",
        ]
        for name, t in d["families"].items()
    ]
    console.print(
        _table(
            f"Fault families: significance -log10 p, threshold "
            f"{diag.threshold:.3g} (false-alarm probability {diag.false_alarm:g})",
            ["family", "method", "f kin [Hz]", "f fit [Hz]", "slip [%]", "signif.", "found"],
            rows,
        )
    )
    from ..diagnosis import peak_label

    lines = [
        [
            p["frequency_hz"],
            p["z"],
            peak_label(p),
            None if p.get("deviation") is None else 100 * p["deviation"],
        ]
        for p in d["peaks"]
    ]
    console.print(
        _table(
            "Envelope lines", ["f [Hz]", "level over floor [-]", "matched", "deviation [%]"], lines
        )
    )
    console.print(f"verdict: [bold]{escape(d['verdict'].replace('_', ' '))}[/bold]")
    console.print(f"[dim]{escape(diag.reason)}[/dim]")
