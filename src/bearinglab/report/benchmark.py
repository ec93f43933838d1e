"""The HTML page of ``bearinglab benchmark --html``: the summary, the per-record table and,
per record, its envelope spectrum with the lines matched (the report's style,
self-contained). The page takes the :class:`bearinglab.diagnosis.BenchmarkResult` as data;
the diagnosis does not render pages.
"""

from __future__ import annotations

from pathlib import Path

from ..files import write_atomically
from .document import figure, page, paragraph, table


def benchmark_page(result) -> str:
    """The page of a benchmark run.

    Parameters
    ----------
    result : bearinglab.diagnosis.BenchmarkResult
        What :func:`bearinglab.diagnosis.run_benchmark` returned (with its diagnoses
        kept, ``keep_spectra=True``, for the spectra).
    """
    d = result.to_dict()
    cols = result.columns
    summary = table(
        ["", *cols],
        [
            [kind, *[f"{d[key][c]} / {d['total']}" for c in cols]]
            for kind, key in (
                ("right", "right"),
                ("wrong fault", "wrong"),
                ("missed", "missed"),
            )
        ]
        + [[f"recall {k}", *[d["recall"][c].get(k) for c in cols]] for k in d["recall"][cols[-1]]],
        "Summary",
    )
    rows = [
        [
            r["file"],
            r["fault"],
            r["smith_randall_2015"] or "",
            *[r.get(c) or r.get("error") for c in cols],
            "yes" if r["right"] else "no",
        ]
        for r in result.records
    ]
    body = [
        paragraph(f"Folder {result.folder}; methods {', '.join(result.methods)}."),
        summary,
        figure(result.plot()[0], "Confusion matrix (methods together)", 60),
        table(["file", "label", "Smith & Randall", *cols, "right"], rows, "Records", numeric=()),
    ]
    for r in result.records:
        diag = result.diagnoses.get(r["file"])
        body.append(f"<h3>{r['file']}: {r['verdict']} (label {r['fault']})</h3>")
        body.append(paragraph(r.get("reason") or r.get("error") or ""))
        if diag is not None:
            body.append(figure(diag.plot()[0], f"{r['file']}: squared envelope spectrum"))
    return page("bearinglab benchmark", [f"{result.folder}"], "".join(body))


def write_benchmark_page(result, path) -> Path:
    """Write :func:`benchmark_page` of ``result`` atomically to ``path`` (UTF-8)."""
    text = benchmark_page(result)
    return write_atomically(path, lambda tmp: Path(tmp).write_text(text, encoding="utf-8"))
