"""Output helpers: JSON (tidied, finite), rich tables, numbered references, plots."""

import json
import math
import sys
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
        table.add_column(col, justify="right" if i and col not in ("source", "meaning") else "left")
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
