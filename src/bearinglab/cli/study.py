"""The ``study`` command: one analysis over a grid of inputs or a table of cases, on dask
(bearinglab.study.run_study)."""

from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import BearinglabError, InputError
from ..inputs import no_effect
from ._app import command_app, console
from ._inputs import (
    JsonOpt,
    OptionError,
    SchedulerOpt,
    WorkersOpt,
    _print_warnings,
    save_plot_figure,
    typed,
)
from ._output import _emit_json, _table, progress_bar
from ._preflight import output_file
from ._preflight import scheduler as preflight_scheduler

app = command_app()

#: More cases than this need --yes.
CONFIRM_CASES = 100_000
#: Rows shown in the table printed after a run.
PREVIEW_ROWS = 10
PREVIEW_OUTPUTS = 4
#: Library parameter -> the option the user typed.
_FLAGS = {
    "output": "--output",
    "scheduler": "--scheduler",
    "workers": "--workers",
    "seed": "--seed",
    "repeats": "--repeats",
    "partition_size": "--partition-size",
    "cases": "--cases",
    "grid": "--set",
    "option": "--set",
    "analysis": "ANALYSIS",
}


def _grid(items: list[str]) -> dict:
    grid = {}
    for item in items:
        name, eq, values = item.partition("=")
        name = name.strip()
        if not eq or not name:
            raise OptionError(
                "--set",
                item,
                "NAME=VALUES, e.g. radial_load_n=100:2000:20 or designation=6205,6206",
            )
        if name in grid:
            raise OptionError("--set", item, f"each option once ({name} is given twice)")
        grid[name] = values
    return grid


def _remap(exc: InputError) -> InputError:
    """The library's error in the command line's terms (the flag the user typed)."""
    if exc.parameter == "cases" and "confirmation" in exc.allowed:
        return OptionError(
            "cases",
            exc.value,
            f"at most {CONFIRM_CASES} cases without --yes",
            "add --yes to run them all",
        )
    flag = _FLAGS.get(exc.parameter, f"--set {exc.parameter}")
    return OptionError(flag, exc.value, exc.allowed, exc.hint)


def _label(name: str) -> str:
    from ..study.plots import _label as label

    return label(name)


def resume_line(exc, unit: str, output: Path, verb: str) -> str | None:
    """What an interrupted study or data set kept and how to finish it (None when the
    run had not begun)."""
    if exc.total is None:
        return None
    left = exc.total - exc.done
    return (
        f"{exc.done} of {exc.total} {unit} are kept in {output}; run the same command "
        f"again to {verb} the other {left}"
    )


def runner_warnings(scheduler: str | None, workers: int | None) -> list[str]:
    """--workers sizes a LocalCluster: without effect on any other scheduler."""
    from ..engine import scheduler_of

    where = scheduler_of(scheduler)
    return no_effect(
        [("--workers", workers is not None and where != "local")],
        f"with the scheduler {where!r} (it sizes a LocalCluster only)",
    )


def _warnings(result, given: set, analysis: str, cases, repeats: int) -> list[str]:
    """The options the run made moot: --seed and --repeats without random inputs,
    --repeats with --cases."""
    from ..study.analyses import analysis as get_analysis

    seeded = [k for k, o in get_analysis(analysis).options.items() if o.seeded]
    random = "--set NAME=uniform:LOW:HIGH" + (
        f", or {' or '.join(seeded)} above 0" if seeded else ""
    )
    out = no_effect(
        [("--seed", "seed" in given and not result.random_inputs)],
        f"without random inputs ({random}): every case is fixed by its inputs",
    )
    if cases is not None:
        return out + no_effect(
            [("--repeats", "repeats" in given)], "with --cases (one row, one case)"
        )
    if repeats > 1 and not result.random_inputs:
        out.append(
            f"--repeats {repeats}: the {repeats} repeats of each grid point are identical "
            f"cases, computed {repeats} times (no random inputs: {random})"
        )
    return out


@app.command("study")
def study(
    ctx: typer.Context,
    analysis: Annotated[
        str,
        typer.Argument(
            help="stiffness, static, frequencies, life, friction, ring-modes, noise or simulate.",
        ),
    ],
    output: Annotated[
        Path,
        typer.Option(
            "-o",
            "--output",
            help="Folder of the results (one Parquet file per partition); "
            "rerun with the same folder to finish an interrupted study.",
        ),
    ],
    set_: Annotated[
        list[str] | None,
        typer.Option(
            "--set",
            help="An input and its values, repeatable: NAME=V, NAME=A,B,C, "
            "NAME=START:STOP:COUNT, NAME=log:START:STOP:COUNT or NAME=uniform:LOW:HIGH "
            "(random per case). Names as the analysis' options, e.g. designation, "
            "radial_load_n, speed_rpm, clearance_um.",
        ),
    ] = None,
    cases: Annotated[
        Path | None,
        typer.Option(
            "--cases",
            help="A .csv or .parquet file of cases instead of --set (one row per "
            "case, columns named as the options).",
        ),
    ] = None,
    seed: Annotated[
        int,
        typer.Option(
            "--seed", help="Study seed: random inputs come from the seed and the case index."
        ),
    ] = 0,
    repeats: Annotated[
        int, typer.Option("--repeats", help="Repeat each grid point (with fresh random inputs).")
    ] = 1,
    partition_size: Annotated[
        int | None,
        typer.Option(
            "--partition-size",
            help="Cases per partition (default: from the analysis and the case count).",
        ),
    ] = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = None,
    yes: Annotated[
        bool, typer.Option("--yes", help=f"Run a study of more than {CONFIRM_CASES} cases.")
    ] = False,
    plot: Annotated[
        Path | None,
        typer.Option(
            "--plot",
            help="Also draw one output over two inputs to this .png, .svg or .pdf (see --plot-of).",
        ),
    ] = None,
    plot_of: Annotated[
        str | None,
        typer.Option(
            "--plot-of",
            help="OUTPUT,X,Y for --plot (default: the first output over the "
            "first two inputs that vary).",
        ),
    ] = None,
    json_output: JsonOpt = False,
):
    """Run one analysis over a grid of inputs or a table of cases, on dask.

    Example: bearinglab study stiffness --set designation=6205 --set radial_load_n=0:2000:21
    --set speed_rpm=0,6000 -o stiffness-6205
    """
    from ..study import read_study, run_study

    grid = _grid(set_ or [])
    if cases is None and not grid:
        raise OptionError("--set", None, "at least one --set NAME=VALUES, or --cases FILE")
    if cases is not None and grid:
        raise OptionError("--cases", str(cases), "either --cases or --set, not both")
    # the whole request is checked before any case runs: the figure's file and columns,
    # the output folder (run_study), the scheduler
    output_file("--plot", plot, (".png", ".svg", ".pdf"), figure=True)
    if plot_of is not None and plot is None:
        raise OptionError("--plot-of", plot_of, "use with --plot FILE")
    names = _plot_names(analysis, grid, cases, repeats, plot, plot_of)
    preflight_scheduler(scheduler)
    existed = output.exists()
    fresh = not existed or (output.is_dir() and not any(output.iterdir()))
    from ..engine import Interrupted

    try:
        with progress_bar(analysis, enabled=not json_output, unit="cases") as progress:
            result = run_study(
                analysis,
                grid or None,
                cases=cases,
                output=output,
                seed=seed,
                repeats=repeats,
                partition_size=partition_size,
                scheduler=scheduler,
                workers=workers,
                max_cases=None if yes else CONFIRM_CASES,
                progress=progress,
            )
    except InputError as exc:
        raise _remap(exc) from None
    except Interrupted as exc:
        exc.resume = resume_line(exc, "cases", output, "compute")
        raise
    table = read_study(result.path)
    warnings = _failures(result, table, output if fresh else None, existed)
    warnings += _warnings(result, typed(ctx), analysis, cases, repeats)
    warnings += runner_warnings(scheduler, workers)
    if plot is not None:
        try:
            fig, _ = result.plot(*names)
        except InputError as exc:
            raise OptionError("--plot-of", plot_of or ",".join(names), exc.allowed) from None
        save_plot_figure(fig, plot)
    if json_output:
        _emit_json({**result.to_dict(), "warnings": warnings})
        return
    _print(result, table)
    _print_warnings(warnings)


def _failures(result, table, made: Path | None, existed: bool) -> list[str]:
    """A warning counting the failed cases; when every case failed, a one-line error with
    the first reason, and what this run wrote in ``made`` (a new or empty folder) removed:
    it holds no result and would refuse the corrected study."""
    failed = table[table["error"].notna()]
    if failed.empty:
        return []
    first = failed.iloc[0]
    reason = f"case {first['case']}: {first['error']}"
    if len(failed) < len(table):
        return [
            f"{len(failed)} of {len(table)} cases failed (their reasons are in the table's "
            f"column 'error'); the first, {reason}"
        ]
    if made is not None:
        import shutil

        if existed:
            for item in made.iterdir():
                shutil.rmtree(item) if item.is_dir() else item.unlink()
        else:
            shutil.rmtree(made)
    many = len(table) > 1
    raise BearinglabError(
        (f"all {len(table)} cases of the study failed" if many else "the study's one case failed")
        + (", so nothing was kept" if made is not None else "")
        + ("; the first, " if many else ": ")
        + reason
    )


def _plot_names(analysis, grid, cases, repeats, plot, plot_of) -> list[str] | None:
    """OUTPUT, X, Y of --plot, checked against the columns the study will have (before it
    runs): --plot-of's names, or the first output over the first two inputs that vary."""
    if plot is None:
        return None
    from ..study.runner import study_columns

    try:
        columns = study_columns(analysis, grid or None, cases=cases, repeats=repeats)
    except InputError as exc:
        raise _remap(exc) from None
    if plot_of is None:
        varying = columns["varying"]
        if len(varying) < 2:
            raise OptionError(
                "--plot", str(plot), "a study with two inputs that vary (or --plot-of OUTPUT,X,Y)"
            )
        return [columns["outputs"][0], varying[0], varying[1]]
    names = [n.strip() for n in plot_of.split(",")]
    if len(names) != 3:
        raise OptionError("--plot-of", plot_of, "OUTPUT,X,Y (three column names)")
    known = ["case", *columns["inputs"], *columns["outputs"]]
    for name in names:
        if name not in known:
            raise OptionError(
                "--plot-of",
                plot_of,
                "OUTPUT,X,Y among the study's columns: " + ", ".join(known),
                f"{name!r} is not one of them",
            )
    return names


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
