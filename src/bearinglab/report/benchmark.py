"""The HTML page of ``bearinglab benchmark --html``: the summary, the per-record table and,
per record, its envelope spectrum with the lines matched (the report's style,
self-contained). The page takes the :class:`bearinglab.diagnosis.BenchmarkResult` as data;
the diagnosis does not render pages.
"""

from __future__ import annotations

from pathlib import Path

from ..files import write_text_atomically
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
        _sizing_table(result),
    ]
    for r in result.records:
        diag = result.diagnoses.get(r["file"])
        body.append(f"<h3>{r['file']}: {r['verdict']} (label {r['fault']})</h3>")
        body.append(paragraph(r.get("reason") or r.get("error") or ""))
        if diag is not None:
            for size in diag.defect_sizes:
                body.append(paragraph(f"Defect width ({size.status}): {size.reason}"))
            caption = f"{r['file']}: squared envelope spectrum" + (
                "; below, the passages of the race defect averaged, aligned on the exit"
                if any(size.lag.size for size in diag.defect_sizes)
                else ""
            )
            body.append(figure(diag.plot()[0], caption))
    return page("bearinglab benchmark", [f"{result.folder}"], "".join(body))


def _sizing_table(result) -> str:
    """The width read from each record with a race fault or a labelled width (empty when
    there is none)."""
    rows = []
    for r in result.records:
        size = r.get("defect_size") or {}
        if not size and r.get("defect_width_mm") is None:
            continue
        sized = size.get("width_mm") is not None
        rows.append(
            [
                r["file"],
                r.get("defect_width_mm"),
                size.get("status", "-"),
                size.get("width_mm") if sized else None,
                f"{size['low_mm']:.3g}-{size['high_mm']:.3g}" if sized else "",
                r.get("sizing_error_percent"),
            ]
        )
    if not rows:
        return ""
    s = result.sizing()
    caption = f"Defect width: {s['sized']} of {s['labelled']} labelled widths sized" + (
        f", error median {s['median_abs_error_percent']:.3g} %, largest "
        f"{s['max_abs_error_percent']:.3g} %"
        if s["sized"]
        else ""
    )
    return table(
        ["file", "label [mm]", "status", "width [mm]", "interval [mm]", "error [%]"],
        rows,
        caption,
        numeric=(1, 3, 5),
    )


def write_benchmark_page(result, path) -> Path:
    """Write :func:`benchmark_page` of ``result`` atomically to ``path`` (UTF-8).

    Parameters
    ----------
    result : BenchmarkResult
        What :func:`bearinglab.diagnosis.run_benchmark` returned.
    path : str or Path
        The HTML file to write; its directory must exist.

    Returns
    -------
    Path
        The file written.
    """
    text = benchmark_page(result)
    return write_text_atomically(path, text)
