"""The ``validate`` command: run every published case bearinglab reproduces
(:func:`bearinglab.validation.all_cases`, the same list tests/literature runs) and show
source, published and computed value, error and verdict."""

import datetime
from pathlib import Path

import typer
from rich.markup import escape
from rich.table import Table

from ..analyses.base import HTML_FILE
from ._app import command_app, console
from ._inputs import JsonOpt, check_path, takes, writing
from ._output import _emit_json, progress_bar

app = command_app()


#: Terminal width below which the table is three columns [characters].
NARROW = 120


def _cell(value, digits: int = 5) -> str:
    return "-" if value is None else f"{value:.{digits}g}"


def _print(results: list[dict], summary: dict) -> None:
    """One table per source, numbered reasons of the known failures and errors below."""
    styles = {
        "pass": "green",
        "known failure": "yellow",
        "fail": "bold red",
        "unexpected pass": "bold red",
        "error": "bold red",
    }
    reasons: list[str] = []
    sources: dict[str, list[dict]] = {}
    for r in results:
        sources.setdefault(r["source"], []).append(r)
    # a narrow terminal gets three columns, so the quantity keeps most of the width
    narrow = console.width < NARROW
    columns = (
        (
            ("verdict", "left"),
            ("error / tol. %", "right"),
            ("quantity: published -> computed", "left"),
        )
        if narrow
        else (
            ("quantity", "left"),
            ("published", "right"),
            ("computed", "right"),
            ("unit", "left"),
            ("error %", "right"),
            ("tol. %", "right"),
            ("verdict", "left"),
        )
    )
    for source, group in sources.items():
        table = Table(
            title=escape(source), title_justify="left", title_style="bold", header_style="bold"
        )
        for name, justify in columns:
            table.add_column(
                name,
                justify=justify,
                overflow="fold",
                no_wrap=name in ("verdict", "published", "computed", "error / tol. %"),
            )
        for r in group:
            note = r["known_failure"] if r["verdict"] == "known failure" else r["error"]
            text = r["verdict"]
            if note:
                if note not in reasons:
                    reasons.append(note)
                text += f" [{reasons.index(note) + 1}]"
            verdict = f"[{styles[r['verdict']]}]{escape(text)}[/]"
            error, tolerance = _cell(r["error_percent"], 3), _cell(r["tolerance_percent"], 3)
            if narrow:
                values = f"{_cell(r['published'])} -> {_cell(r['computed'])} {r['unit']}"
                table.add_row(
                    verdict, f"{error} / {tolerance}", escape(f"{r['quantity']}: {values}")
                )
            else:
                table.add_row(
                    escape(r["quantity"]),
                    _cell(r["published"]),
                    _cell(r["computed"]),
                    escape(r["unit"]),
                    error,
                    tolerance,
                    verdict,
                )
        console.print(table)
    for i, text in enumerate(reasons, start=1):
        console.print(f"[dim]\\[{i}] {escape(text)}[/dim]")
    s = summary
    line = (
        f"{s['total']} cases: {s['passed']} pass, {s['known_failures']} known failures "
        f"(documented), {s['failed']} fail, {s['unexpected_passes']} unexpected passes, "
        f"{s['errors']} errors ({s['duration_s']:.1f} s)"
    )
    console.print(f"[{'green' if s['ok'] else 'bold red'}]{escape(line)}[/]")


@app.command("validate")
@takes(files=HTML_FILE)
def validate_command(values, json_output: JsonOpt = False, html=None):
    """Run every published case bearinglab reproduces (seed papers, data-set frequency
    factors, textbook examples, catalogue ratings) and show published and computed
    values, error and verdict: pass, fail, or known failure (a documented
    non-reproduction, with its reason). Exit code 0 when every case passes or fails as
    documented; 1 when a case that should pass fails (or raises), or a known failure
    unexpectedly passes. Some cases run simulations: expect a minute or two."""
    from ..registry import entry

    check_path("--html", html, (".html", ".htm"))
    with progress_bar("validate", enabled=not json_output) as update:
        result = entry("validate")(
            {},
            progress=lambda done, total, label: update(
                done / total, escape(f"validate {done + 1}/{total}: {label}"[:70])
            ),
        )
    results, summary = list(result.results), result.summary
    if html is not None:
        _write_html(html, results, summary)
    if json_output:
        _emit_json(result.to_dict())
    else:
        _print(results, summary)
        if html is not None:
            console.print(f"HTML written to {escape(str(html))}")
    if not result.ok:
        raise typer.Exit(code=1)


def _write_html(path: Path, results: list[dict], summary: dict) -> None:
    from .. import __version__
    from ..files import write_text_atomically
    from ..report import validation_page

    now = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    text = validation_page(
        results,
        summary,
        f"generated {now} by bearinglab {__version__} in {summary['duration_s']:.1f} s",
    )
    with writing("--html", path):
        write_text_atomically(path, text)
