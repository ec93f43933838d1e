"""The HTML page of ``bearinglab validate --html``: every published case with its verdict,
grouped by source, in the report's style (self-contained)."""

from __future__ import annotations

from .document import Raw, esc, key_figures, page, table

#: verdict -> CSS class of its badge.
_BADGES = {
    "pass": "pass",
    "known failure": "known",
    "fail": "fail",
    "unexpected pass": "fail",
    "error": "fail",
}


def _verdict(case: dict) -> Raw:
    verdict = case["verdict"]
    badge = f'<span class="verdict {_BADGES.get(verdict, "fail")}">{esc(verdict)}</span>'
    why = case.get("known_failure") if verdict == "known failure" else case.get("error")
    return Raw(badge + (f'<div class="small">{esc(why)}</div>' if why else ""))


def validation_page(cases: list[dict], summary: dict, meta: str = "") -> str:
    """The page: summary cards, then one table per source (published, computed, unit,
    error, tolerance with its reason, verdict).

    Parameters
    ----------
    cases : list of dict
        As in ``bearinglab validate --json`` (``source``, ``quantity``, ``published``,
        ``computed``, ``unit``, ``error_percent``, ``tolerance_percent``,
        ``tolerance_reason``, ``verdict``, ``known_failure``, ``error``).
    summary : dict
        ``total``, ``passed``, ``known_failures``, ``failed``, ``unexpected_passes``,
        ``errors``, ``ok``.
    meta : str
        A line under the title (date, version).
    """
    ok = summary["ok"]
    cards = key_figures(
        [
            ("cases", str(summary["total"])),
            ("pass", str(summary["passed"])),
            ("known failures (documented)", str(summary["known_failures"])),
            ("fail", str(summary["failed"] + summary["errors"])),
            ("unexpected passes", str(summary["unexpected_passes"])),
        ]
    )
    verdict = (
        "Every case passes or fails as documented."
        if ok
        else "Some cases do not behave as documented: see the red verdicts."
    )
    parts = [
        (
            f'<section id="summary"><h2>Summary</h2>{cards}'
            f'<p class="{"" if ok else "status fail"}">{esc(verdict)} A <em>known failure</em> '
            "is a published number bearinglab does not reproduce, with the reason; it is "
            "expected to fail, and passing would be a change to look at.</p></section>"
        )
    ]
    sources: dict[str, list[dict]] = {}
    for case in cases:
        sources.setdefault(case["source"], []).append(case)
    for i, (source, group) in enumerate(sources.items()):
        rows = [
            [
                c["quantity"],
                c["published"],
                c["computed"],
                c["unit"],
                c["error_percent"],
                c["tolerance_percent"],
                Raw(f'<span class="small">{esc(c.get("tolerance_reason") or "")}</span>'),
                _verdict(c),
            ]
            for c in group
        ]
        parts.append(
            f'<section id="source-{i + 1}"><h3>{esc(source)}</h3>'
            + table(
                [
                    "quantity",
                    "published",
                    "computed",
                    "unit",
                    "error [%]",
                    "tolerance [%]",
                    "why that tolerance",
                    "verdict",
                ],
                rows,
                numeric=(1, 2, 4, 5),
            )
            + "</section>"
        )
    line = (
        f"{summary['total']} published numbers from the seed papers, data sets, textbooks "
        "and catalogues, recomputed with bearinglab"
    )
    return page("bearinglab validate: published cases", [line], "".join(parts), meta)
