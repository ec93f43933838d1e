"""The HTML page of a report: sections, tables, embedded figures and the page template.

Everything the page needs is inside it: the style sheet is inline, figures are PNG images
embedded as base64 ``data:`` URLs, links only point inside the page (``#section``). No
scripts, fonts or images are loaded from anywhere else, so the file can be mailed,
archived and opened offline.
"""

from __future__ import annotations

import base64
import html
import io
import math
from dataclasses import dataclass, field
from pathlib import Path

from ..files import write_text_atomically

#: Resolution of the embedded figures [dots per inch]; a 11 in wide figure is 1100 px.
FIGURE_DPI = 100


def esc(value) -> str:
    """HTML-escaped text of ``value`` [-]."""
    return html.escape(str(value), quote=True)


def prose(text) -> str:
    """HTML of a library text: escaped, the inputs it names in backquotes as the command
    line's options (``code``), other backquoted words as code.

    >>> prose("use `system` gost, or `bearinglab noise`")
    'use <code>--system</code> gost, or <code>bearinglab noise</code>'
    """
    parts = str(text).split("`")
    if len(parts) % 2 == 0:  # an unpaired backquote: not markup
        return esc(text)
    out = []
    for i, part in enumerate(parts):
        if i % 2 == 0:
            out.append(esc(part))
        else:
            shown = "--" + part.replace("_", "-") if part.isidentifier() else part
            out.append(f"<code>{esc(shown)}</code>")
    return "".join(out)


def fmt(value, digits: int = 4) -> str:
    """A table cell: floats to ``digits`` significant figures, None or NaN as a dash [-].

    >>> fmt(1234.5678), fmt(None), fmt(0.000123456), fmt(True), fmt(819876.5)
    ('1235', '&ndash;', '0.0001235', 'yes', '819,900')
    """
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "&ndash;"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return esc(number(value, digits))
    return esc(value)


def number(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures, thousands separated up to 1e7, in
    scientific notation beyond that or below 1e-4 [-].

    >>> number(13490.2), number(3.69e7), number(-0.5), number(2.0)
    ('13,490', '3.690e+07', '-0.5', '2')
    """
    if not math.isfinite(value):
        return str(value)
    size = abs(value)
    if value != 0 and (size >= 1e7 or size < 1e-4):
        return f"{value:.{digits - 1}e}"
    if size >= 1e4:
        return f"{round(value, digits - 1 - math.floor(math.log10(size))):,.0f}"
    return f"{value:.{digits}g}"


def table(
    columns: list[str],
    rows: list[list],
    caption: str | None = None,
    numeric: tuple[int, ...] | None = None,
    css: str = "",
) -> str:
    """An HTML table; ``numeric`` columns are right-aligned (default: all but the first).

    Cells that are already HTML are passed as :class:`Raw`.
    """
    numeric = tuple(range(1, len(columns))) if numeric is None else numeric
    head = "".join(
        f'<th class="{"num" if i in numeric else ""}">{esc(c)}</th>' for i, c in enumerate(columns)
    )
    body = []
    for row in rows:
        cells = "".join(
            f'<td class="{"num" if i in numeric else ""}">'
            f"{v.text if isinstance(v, Raw) else fmt(v)}</td>"
            for i, v in enumerate(row)
        )
        body.append(f"<tr>{cells}</tr>")
    cap = f"<caption>{esc(caption)}</caption>" if caption else ""
    return (
        f'<div class="table-wrap"><table class="{css}">{cap}<thead><tr>{head}</tr></thead>'
        f"<tbody>{''.join(body)}</tbody></table></div>"
    )


@dataclass(frozen=True)
class Raw:
    """A table cell or paragraph that is already HTML."""

    text: str


def paragraph(text: str, css: str = "") -> str:
    """A paragraph of a library text (:func:`prose`)."""
    return f'<p class="{css}">{prose(text)}</p>'


def notes(items: list[str], title: str = "Notes") -> str:
    """A titled list of plain-text notes (assumptions, warnings); empty when no items."""
    if not items:
        return ""
    lis = "".join(f"<li>{prose(t)}</li>" for t in items)
    return f'<div class="notes"><h4>{esc(title)}</h4><ul>{lis}</ul></div>'


def figure(fig, caption: str, width_percent: int = 100) -> str:
    """Embed a matplotlib figure as a base64 PNG (the figure is closed) [-]."""
    from ..plotting import _pyplot

    buffer = io.BytesIO()
    try:
        fig.savefig(buffer, format="png", dpi=FIGURE_DPI, bbox_inches="tight")
    finally:
        _pyplot().close(fig)
    data = base64.b64encode(buffer.getvalue()).decode("ascii")
    return (
        f'<figure style="max-width:{width_percent}%"><img src="data:image/png;base64,{data}" '
        f'alt="{esc(caption)}"><figcaption>{esc(caption)}</figcaption></figure>'
    )


def key_figures(items: list[tuple[str, str]]) -> str:
    """A grid of (label, value) cards for the summary."""
    cards = "".join(
        f'<div class="card"><div class="label">{esc(k)}</div>'
        f'<div class="value">{esc(v)}</div></div>'
        for k, v in items
    )
    return f'<div class="cards">{cards}</div>'


@dataclass
class Section:
    """One section of a report: ``body`` HTML, ``error`` when its analysis failed, or
    ``left_out``: why it does not apply to this bearing; ``highlights`` are (label, value)
    pairs for the summary at the top."""

    key: str
    title: str
    body: str = ""
    error: str | None = None
    highlights: list[tuple[str, str]] = field(default_factory=list)
    left_out: str | None = None

    @property
    def failed(self) -> bool:
        return self.error is not None

    def to_html(self) -> str:
        badge = '<span class="badge fail">failed</span>' if self.failed else ""
        content = (
            f'<div class="error"><strong>This analysis failed</strong> (the rest of the '
            f"report is unaffected):<pre>{prose(self.error)}</pre></div>"
            if self.failed
            else f'<p class="small">Not computed: {esc(self.left_out)}.</p>'
            if self.left_out
            else self.body
        )
        return (
            f'<section id="{esc(self.key)}"><h2>{esc(self.title)} {badge}</h2>'
            f'{content}<p class="top"><a href="#top">back to top</a></p></section>'
        )


@dataclass
class Report:
    """A built report: ``title``, ``subtitle`` lines, ``sections`` and page metadata."""

    title: str
    subtitle: list[str]
    sections: list[Section]
    generated: str = ""
    version: str = ""
    intro: str = ""
    warnings: tuple = ()

    @property
    def failed(self) -> list[Section]:
        """The sections whose analysis failed."""
        return [s for s in self.sections if s.failed]

    @property
    def left_out(self) -> list[Section]:
        """The sections that do not apply to the bearing."""
        return [s for s in self.sections if s.left_out]

    def to_html(self) -> str:
        """The self-contained page."""
        badge = ' <span class="badge fail">failed</span>'
        items = "".join(
            f'<li><a href="#{esc(s.key)}">{esc(s.title)}</a>{badge if s.failed else ""}</li>'
            for s in self.sections
        )
        toc = f'<nav class="toc"><h2>Contents</h2><ol>{items}</ol></nav>'
        highlights = [h for s in self.sections for h in s.highlights]
        summary = (
            f'<section id="summary"><h2>At a glance</h2>{key_figures(highlights)}'
            f"{self.intro}</section>"
            if highlights or self.intro
            else ""
        )
        failed = self.failed
        status = (
            f'<p class="status fail">{len(failed)} of {len(self.sections)} analyses '
            f"failed: {esc(', '.join(s.title for s in failed))}</p>"
            if failed
            else ""
        )
        status += "".join(f'<p class="status warn">{prose(w)}</p>' for w in self.warnings)
        return PAGE.format(
            title=esc(self.title),
            heading=esc(self.title),
            subtitle="".join(f"<p>{esc(line)}</p>" for line in self.subtitle),
            meta=esc(f"generated {self.generated} by bearinglab {self.version}".strip()),
            status=status,
            toc=toc,
            summary=summary,
            sections="".join(s.to_html() for s in self.sections),
            style=STYLE,
        )

    def write(self, path: str | Path) -> Path:
        """Write the page to ``path`` atomically (UTF-8).

        Parameters
        ----------
        path : str or Path
            The HTML file to write; its directory must exist.

        Returns
        -------
        Path
            The file written.
        """
        text = self.to_html()
        return write_text_atomically(path, text)


def page(title: str, subtitle: list[str], body: str, meta: str = "") -> str:
    """A self-contained page with the report's style around ``body`` (used by
    ``bearinglab validate --html``)."""
    return PAGE.format(
        title=esc(title),
        heading=esc(title),
        subtitle="".join(f"<p>{esc(line)}</p>" for line in subtitle),
        meta=esc(meta),
        status="",
        toc="",
        summary="",
        sections=body,
        style=STYLE,
    )


STYLE = """
:root { --ink: #1d2733; --muted: #5b6875; --line: #d9dee4; --accent: #1f5f99;
        --band: #f4f6f8; --bad: #a3262a; --good: #21743b; --warn: #8a5a00; }
* { box-sizing: border-box; }
body { margin: 0; font: 15px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans",
       sans-serif; color: var(--ink); background: #fff; }
header { background: linear-gradient(120deg, #123a5e, #1f5f99); color: #fff;
         padding: 28px 40px 22px; }
header h1 { margin: 0 0 6px; font-size: 28px; font-weight: 650; letter-spacing: .2px; }
header p { margin: 2px 0; opacity: .92; }
header .meta { font-size: 12.5px; opacity: .75; margin-top: 10px; }
main { max-width: 1180px; margin: 0 auto; padding: 10px 40px 60px; }
nav.toc { background: var(--band); border: 1px solid var(--line); border-radius: 8px;
          padding: 10px 22px 12px; margin: 22px 0 8px; }
nav.toc h2 { font-size: 16px; margin: 4px 0 6px; border: 0; padding: 0; }
nav.toc ol { columns: 2; column-gap: 40px; margin: 0; padding-left: 22px; }
nav.toc li { margin: 2px 0; break-inside: avoid; }
a { color: var(--accent); text-decoration: none; }
a:hover { text-decoration: underline; }
section { margin-top: 30px; }
h2 { font-size: 21px; border-bottom: 2px solid var(--accent); padding-bottom: 4px;
     margin: 0 0 12px; }
h3 { font-size: 16px; margin: 18px 0 6px; color: var(--accent); }
h4 { margin: 0 0 4px; font-size: 13.5px; }
.table-wrap { overflow-x: auto; margin: 8px 0 14px; }
table { border-collapse: collapse; font-size: 13.5px; min-width: 40%; }
caption { text-align: left; font-weight: 600; padding: 4px 0; color: var(--muted); }
th, td { border-bottom: 1px solid var(--line); padding: 4px 12px; vertical-align: top; }
th { background: var(--band); text-align: left; font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tbody tr:nth-child(even) td { background: #fafbfc; }
td.src { color: var(--muted); font-size: 12.5px; max-width: 520px; }
figure { margin: 12px 0 18px; }
figure img { display: block; width: 100%; height: auto; border: 1px solid var(--line);
             border-radius: 6px; background: #fff; }
figcaption { font-size: 12.5px; color: var(--muted); margin-top: 4px; }
.cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(200px, 1fr));
         gap: 10px; margin: 6px 0 10px; }
.card { border: 1px solid var(--line); border-left: 4px solid var(--accent);
        border-radius: 6px; padding: 8px 12px; background: #fff; }
.card .label { font-size: 12px; color: var(--muted); }
.card .value { font-size: 18px; font-weight: 600; }
.notes { background: #fbf8ef; border: 1px solid #eadfbd; border-radius: 6px;
         padding: 8px 14px; margin: 8px 0 14px; font-size: 13.5px; }
.notes ul { margin: 2px 0; padding-left: 20px; }
.error { background: #fcefef; border: 1px solid #e3b4b4; border-radius: 6px;
         padding: 10px 14px; color: var(--bad); }
.error pre { white-space: pre-wrap; margin: 6px 0 0; color: var(--ink); }
.badge { font-size: 11px; font-weight: 600; padding: 1px 7px; border-radius: 9px;
         vertical-align: middle; }
.badge.fail, .verdict.fail { background: #f6d5d5; color: var(--bad); }
.verdict { font-weight: 600; padding: 1px 7px; border-radius: 9px; white-space: nowrap; }
.verdict.pass { background: #d9efdf; color: var(--good); }
.verdict.known { background: #f7ebcf; color: var(--warn); }
.status.fail { color: var(--bad); font-weight: 600; }
.status.warn { color: var(--warn); }
p.small, .small { font-size: 12.5px; color: var(--muted); }
p.top { text-align: right; font-size: 12px; margin: 4px 0 0; }
.two { display: grid; grid-template-columns: 1fr 1fr; gap: 22px; align-items: start; }
@media (max-width: 900px) { .two { grid-template-columns: 1fr; } nav.toc ol { columns: 1; } }
@media print { header { background: #123a5e; } a { color: inherit; } }
"""

PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
<style>{style}</style>
</head>
<body>
<header id="top"><h1>{heading}</h1>{subtitle}<p class="meta">{meta}</p></header>
<main>
{status}
{toc}
{summary}
{sections}
</main>
</body>
</html>
"""
