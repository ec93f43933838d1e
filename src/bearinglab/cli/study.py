"""The ``study`` command: one analysis over a grid of inputs or a table of cases, on dask
(the registry's ``study``: bearinglab.study.request)."""

from rich.markup import escape

from ..study.request import STUDY
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, given, save_plot_figure, takes
from ._output import _emit_json, _table, progress_bar
from ._preflight import output_file
from ._preflight import scheduler as preflight_scheduler

app = command_app()

#: Rows shown in the table printed after a run.
PREVIEW_ROWS = 10
PREVIEW_OUTPUTS = 4


def _label(name: str) -> str:
    from ..study.plots import _label as label

    return label(name)


@app.command("study")
@takes(argument="analysis", files=STUDY.files, **STUDY.command_options)
def study(values, json_output: JsonOpt = False, plot=None):
    """Run one analysis over a grid of inputs or a table of cases, on dask.

    Example: bearinglab study stiffness --set designation=6205 --set radial_load_n=0:2000:21
    --set speed_rpm=0,6000 -o stiffness-6205
    """
    # the whole request is checked before any case runs: the figure's file and columns,
    # the output folder (run_study), the scheduler
    output_file("--plot", plot, (".png", ".svg", ".pdf"), figure=True)
    preflight_scheduler(values["scheduler"])
    typed_ = given()
    with progress_bar(values["analysis"], enabled=not json_output, unit="cases") as progress:
        r = STUDY(values, progress=progress, given=typed_, plot=plot)
    if plot is not None:
        save_plot_figure(r.plot()[0], plot)
    if json_output:
        _emit_json(r.to_dict())
        return
    _print(r.result, r.table)
    _print_warnings(list(r.warnings))


def _natural_width(table) -> int:
    """The width ``table`` takes when nothing is wrapped or cut [characters]."""
    from rich.console import Console

    return Console(width=10_000).measure(table).maximum


def run_rows(d: dict, unit: str) -> list[list]:
    """The summary rows of a run on dask (a study's or a data set's ``to_dict()``), its
    rate in ``unit`` (cases, records) per second."""
    rate = d[f"{unit}_per_s"]
    return [
        [
            "partitions computed / reused",
            f"{d['partitions_computed']} / {d['partitions_reused']}",
            "",
        ],
        ["wall time", d["wall_time_s"], "s"],
        [f"{unit} per second", "-" if rate is None else rate, "1/s"],
        ["workers", d["workers"], ""],
        ["scheduler", d["scheduler"], ""],
        ["output", d["output"], ""],
    ]


def _print(result, table) -> None:
    d = result.to_dict()
    rows = [
        ["analysis", d["analysis"], ""],
        ["cases", d["cases"], ""],
        ["failed cases", d["failed_cases"], ""],
        *run_rows(d, "cases"),
    ]
    console.print(_table("study", ["", "value", "unit"], rows))
    ok = table[table["error"].isna()]
    shown = ok.head(PREVIEW_ROWS)
    # as many output columns as fit the terminal: numbers are never cut (the whole table is
    # in the Parquet files)
    outputs = [c for c in result.outputs if table[c].notna().any()][:PREVIEW_OUTPUTS]
    while True:
        columns = ["case", *result.inputs, *outputs]
        preview = _table(
            f"first {len(shown)} of {len(ok)} cases that ran",
            [_label(c).replace(" [", "\n[") for c in columns],
            [[row[c] for c in columns] for _, row in shown.iterrows()],
        )
        if not outputs or _natural_width(preview) <= console.width:
            break
        outputs.pop()
    console.print(preview)
    failed = table[table["error"].notna()]
    for _, row in failed.head(PREVIEW_ROWS).iterrows():
        console.print(f"[yellow]case {row['case']} failed:[/yellow] {escape(row['error'])}")
    if len(failed) > PREVIEW_ROWS:
        console.print(
            f"[yellow]... and {len(failed) - PREVIEW_ROWS} more failed cases "
            "(column 'error')[/yellow]"
        )
    more = len(result.outputs) - len(outputs)
    console.print(
        f"[dim]{f'{more} more output columns; ' if more else ''}the whole table: "
        f"pandas.read_parquet({escape(repr(str(result.path)))})[/dim]"
    )
