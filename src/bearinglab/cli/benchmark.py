"""The ``benchmark`` command: the diagnosis over a folder of labelled recordings
(the registry's ``benchmark``: bearinglab.analyses.diagnosis; docs/capabilities/diagnosis.md)."""

from ..analyses.diagnosis import BENCHMARK
from ._app import command_app, console
from ._inputs import JsonOpt, takes
from ._output import _emit_json, _table, escape, progress_bar
from ._preflight import output_file

app = command_app()


@app.command("benchmark")
@takes(argument="folder", files=BENCHMARK.files, **BENCHMARK.command_options)
def benchmark_command(values, json_output: JsonOpt = False, html=None):
    """Run the diagnosis over a folder of labelled recordings."""
    folder = values["folder"]
    output_file("--html", html, (".html", ".htm"))
    with progress_bar("records", enabled=not json_output, unit="records") as progress:
        result = BENCHMARK(values, progress=progress, keep_spectra=html is not None)
    out = result.to_dict()
    if html is not None:
        from ..report.benchmark import write_benchmark_page

        write_benchmark_page(result, html)
    if json_output:
        _emit_json(out)
        return
    cols = out["columns"]
    # headers and cells that wrap well in 80 columns: the methods together are "combined",
    # verdicts in the labels' words - "outer", "inner", "no fault", "compound: outer + ball"
    # (the JSON keeps the full names)
    heads = [("combined" if "+" in c else c) for c in cols]
    rows = [
        [
            r["file"],
            r["fault"],
            r["smith_randall_2015"] or "-",
            *[(r.get(c) or "error").replace(" detected", "").replace("_race", "") for c in cols],
            r["outcome"],
            "-" if r.get("measured_rpm") is None else f"{r['measured_rpm']:.1f}",
        ]
        for r in out["records"]
    ]
    title = f"{folder}: verdicts" + (f" (combined: {cols[-1]})" if len(cols) > 1 else "")
    console.print(
        _table(
            title,
            ["file", "label", "S&R 2015", *heads, "outcome", "shaft [rpm]"],
            rows,
            words=True,
            whole=0,
        )
    )
    together = cols[-1]
    matrix = out["confusion"][together]
    verdicts = [c for c in next(iter(matrix.values())) if any(m[c] for m in matrix.values())]
    console.print(
        _table(
            f"confusion ({together}): label / verdict",
            ["label", *verdicts],
            [[k, *[v[c] for c in verdicts]] for k, v in matrix.items()],
        )
    )
    console.print(
        _table(
            "right, wrong faults, missed, and recall per class",
            ["", *heads],
            [
                [kind, *[f"{out[key][c]} / {out['total']}" for c in cols]]
                for kind, key in (
                    ("right", "right"),
                    ("wrong fault", "wrong"),
                    ("missed", "missed"),
                )
            ]
            + [
                [f"recall {k}", *[out["recall"][c].get(k) for c in cols]]
                for k in out["recall"][together]
            ],
        )
    )
    sized = [r for r in out["records"] if r["defect_size"] or r["defect_width_mm"] is not None]
    if sized:
        summary = out["sizing"]
        console.print(
            _table(
                f"defect width: {summary['sized']} of {summary['labelled']} labelled widths "
                "sized"
                + (
                    f", error median {summary['median_abs_error_percent']:.3g} %, largest "
                    f"{summary['max_abs_error_percent']:.3g} %"
                    if summary["sized"]
                    else ""
                ),
                ["file", "label [mm]", "status", "width [mm]", "interval [mm]", "error [%]"],
                [
                    [
                        r["file"],
                        "-" if r["defect_width_mm"] is None else f"{r['defect_width_mm']:.3g}",
                        (r["defect_size"] or {}).get("status", "-"),
                        "-"
                        if not (r["defect_size"] or {}).get("width_mm")
                        else f"{r['defect_size']['width_mm']:.3g}",
                        "-"
                        if not (r["defect_size"] or {}).get("width_mm")
                        else f"{r['defect_size']['low_mm']:.3g}-{r['defect_size']['high_mm']:.3g}",
                        "-"
                        if r["sizing_error_percent"] is None
                        else f"{r['sizing_error_percent']:+.0f}",
                    ]
                    for r in sized
                ],
                words=True,
                whole=0,
            )
        )
    said: dict[str, list[str]] = {}  # a warning said of many records is printed once
    for r in out["records"]:
        for warning in r.get("warnings") or []:
            said.setdefault(warning, []).append(r["file"])
    for warning, files in said.items():
        where = files[0] if len(files) == 1 else f"{len(files)} records"
        console.print(f"[yellow]{escape(where)}: {escape(warning)}[/yellow]")
    errors = [r for r in out["records"] if r["error"]]
    for r in errors:
        console.print(f"[red]{escape(r['file'])}: {escape(r['error'])}[/red]")
    if html is not None:
        console.print(f"page written to {html}")
