"""The ``study`` request: its inputs (the study's own, declared here, and the table's) and
:func:`study_from`, which checks the whole request before any case runs, calls
:func:`~bearinglab.study.runner.run_study` once and says what the run made moot."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..analyses.base import FILES, Analysis
from ..errors import BearinglabError, InputError
from ..inputs import INPUTS, Input, input_for, no_effect

#: More cases than this need `yes`.
CONFIRM_CASES = 100_000

#: The study's inputs, in the order the command line lists them.
STUDY_INPUTS: dict[str, Input] = {
    "analysis": Input(
        "text",
        ...,
        "stiffness, static, frequencies, life, friction, ring-modes, noise or simulate.",
    ),
    "output": FILES["output"].with_(
        default=...,
        help="Folder of the results (one Parquet file per partition); rerun with the same "
        "folder to finish an interrupted study.",
    ),
    "set": Input(
        "texts",
        None,
        "An input and its values, repeatable: NAME=V, NAME=A,B,C, NAME=START:STOP:COUNT, "
        "NAME=log:START:STOP:COUNT or NAME=uniform:LOW:HIGH (random per case). Names as the "
        "analysis' inputs, e.g. designation, radial_load_n, speed_rpm, clearance_um.",
        sets=("grid", "option"),
    ),
    "cases": Input(
        "path",
        None,
        "A .csv or .parquet file of cases instead of `set` (one row per case, columns named "
        "as the inputs).",
    ),
    "study_seed": Input(
        "integer",
        0,
        "Study seed: random inputs come from the seed and the case index.",
        low=0,
        aliases=("seed",),
        sets="seed",
    ),
    "repeats": Input(
        "integer",
        1,
        "Repeat each grid point (with fresh random inputs).",
        low=1,
        what="a number of repeats",
    ),
    "partition_size": INPUTS["partition_size"],
    "scheduler": INPUTS["scheduler"],
    "workers": INPUTS["workers"],
    "yes": INPUTS["yes"].with_(help=f"Run a study of more than {CONFIRM_CASES} cases."),
    "plot_of": Input(
        "text",
        None,
        "OUTPUT,X,Y for `plot` (default: the first output over the first two inputs that vary).",
    ),
}


@dataclass(frozen=True)
class StudyOutcome:
    """A study run: its ``result`` (:class:`~.runner.StudyResult`), its ``table`` (one row
    per case), the columns its figure draws (``figure``: OUTPUT, X, Y, or None) and the
    ``warnings`` (failed cases, inputs the run made moot)."""

    result: object
    table: object
    figure: tuple | None = None
    warnings: tuple = field(default_factory=tuple)

    def to_dict(self) -> dict:
        return {**self.result.to_dict(), "warnings": list(self.warnings)}

    def to_pandas(self):
        return self.table

    def plot(self):
        """The figure's output over its two inputs (`plot_of`); (fig, ax)."""
        return self.result.plot(*self.figure)


def grid_of(items) -> dict:
    """The grid of `set`: NAME=VALUES items -> {name: values text}.

    >>> grid_of(["designation=6205", "radial_load_n=100:2000:20"])
    {'designation': '6205', 'radial_load_n': '100:2000:20'}
    """
    grid: dict = {}
    for item in items or []:
        name, eq, values = str(item).partition("=")
        name = name.strip()
        if not eq or not name:
            raise InputError(
                "set", item, "NAME=VALUES, e.g. radial_load_n=100:2000:20 or designation=6205,6206"
            )
        if name in grid:
            raise InputError("set", item, f"each input once ({name} is given twice)")
        grid[name] = values
    return grid


def figure_columns(values: dict, grid: dict) -> tuple | None:
    """OUTPUT, X, Y of the study's figure, checked against the columns the study will
    have before it runs: `plot_of`'s names, or the first output over the first two inputs
    that vary; None without a figure (``values["plot"]`` not given)."""
    from .runner import study_columns

    plot_of = values.get("plot_of")
    if values.get("plot") is None:
        if plot_of is not None:
            raise InputError("plot_of", plot_of, "use with `plot`")
        return None
    columns = study_columns(
        values["analysis"], grid or None, cases=values.get("cases"), repeats=values["repeats"]
    )
    if plot_of is None:
        varying = columns["varying"]
        if len(varying) < 2:
            raise InputError(
                "plot", str(values["plot"]), "a study with two inputs that vary (or `plot_of`)"
            )
        return columns["outputs"][0], varying[0], varying[1]
    names = [n.strip() for n in plot_of.split(",")]
    if len(names) != 3:
        raise InputError("plot_of", plot_of, "OUTPUT,X,Y (three column names)")
    known = ["case", *columns["inputs"], *columns["outputs"]]
    for name in names:
        if name not in known:
            raise InputError(
                "plot_of",
                plot_of,
                "OUTPUT,X,Y among the study's columns: " + ", ".join(known),
                f"{name!r} is not one of them",
            )
    return tuple(names)


def moot(result, given: set, values: dict) -> list[str]:
    """The inputs the run made moot: `study_seed` and `repeats` without random inputs,
    `repeats` with `cases`, `workers` off a LocalCluster."""
    from ..engine import scheduler_of
    from .analyses import analysis as get_analysis

    seeded = [k for k, o in get_analysis(values["analysis"]).options.items() if o.seeded]
    random = "`set` NAME=uniform:LOW:HIGH" + (
        f", or {' or '.join(seeded)} above 0" if seeded else ""
    )
    out = no_effect(
        [("study_seed", "study_seed" in given and not result.random_inputs)],
        f"without random inputs ({random}): every case is fixed by its inputs",
    )
    repeats = values["repeats"]
    if values.get("cases") is not None:
        out += no_effect([("repeats", "repeats" in given)], "with `cases` (one row, one case)")
    elif repeats > 1 and not result.random_inputs:
        out.append(
            f"`repeats` {repeats}: the {repeats} repeats of each grid point are identical "
            f"cases, computed {repeats} times (no random inputs: {random})"
        )
    where = scheduler_of(values.get("scheduler"))
    return out + no_effect(
        [("workers", values.get("workers") is not None and where != "local")],
        f"with the scheduler {where!r} (it sizes a LocalCluster only)",
    )


def failures(table, made, existed: bool) -> list[str]:
    """A warning counting the failed cases; when every case failed, an error with the
    first reason, and what this run wrote in ``made`` (a new or empty folder) removed: it
    holds no result and would refuse the corrected study."""
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


def study_from(values: dict, *, progress=None, given=None, plot=None) -> StudyOutcome:
    """The ``study`` request: the whole request checked before any case runs (the grid or
    the cases, the figure's columns with ``plot`` the figure's file, the output folder,
    the scheduler), then :func:`~.runner.run_study` once; ``given``: the inputs the user
    gave (default: those not None), for the warnings about inputs without effect."""
    from pathlib import Path

    from ..engine import Interrupted
    from .runner import read_study, run_study

    grid = grid_of(values.get("set"))
    if values.get("cases") is None and not grid:
        raise InputError("set", None, "at least one `set` NAME=VALUES, or `cases` FILE")
    if values.get("cases") is not None and grid:
        raise InputError("cases", str(values["cases"]), "either `cases` or `set`, not both")
    try:
        figure = figure_columns({**values, "plot": plot}, grid)
    except InputError as exc:
        if input_for(exc.parameter, STUDY_INPUTS) is None and exc.parameter != "plot":
            raise InputError(f"set {exc.parameter}", exc.value, exc.allowed, exc.hint) from None
        raise
    output = Path(values["output"])
    existed = output.exists()
    fresh = not existed or (output.is_dir() and not any(output.iterdir()))
    try:
        result = run_study(
            values["analysis"],
            grid or None,
            cases=values.get("cases"),
            output=output,
            seed=values["study_seed"],
            repeats=values["repeats"],
            partition_size=values.get("partition_size"),
            scheduler=values.get("scheduler"),
            workers=values.get("workers"),
            max_cases=None if values.get("yes") else CONFIRM_CASES,
            progress=progress,
        )
    except InputError as exc:
        if exc.parameter == "cases" and "confirmation" in exc.allowed:
            raise InputError(
                "cases",
                exc.value,
                f"at most {CONFIRM_CASES} cases without `yes`",
                "confirm with `yes` to run them all",
            ) from None
        if input_for(exc.parameter, STUDY_INPUTS) is None:  # an input of the analysis
            where = "cases" if values.get("cases") is not None else "set"
            raise InputError(f"{where} {exc.parameter}", exc.value, exc.allowed, exc.hint) from None
        raise
    except Interrupted as exc:
        if exc.total is not None:
            exc.resume = (
                f"{exc.done} of {exc.total} cases are kept in {output}; run the same command "
                f"again to compute the other {exc.total - exc.done}"
            )
        raise
    table = read_study(result.path)
    given = {k for k, v in values.items() if v is not None} if given is None else set(given)
    warnings = failures(table, output if fresh else None, existed) + moot(result, given, values)
    return StudyOutcome(result, table, figure, tuple(warnings))


STUDY = Analysis(
    "study",
    "One analysis over a grid of inputs or a table of cases, on dask (run_study).",
    STUDY_INPUTS,
    run=study_from,
    files={
        "plot": FILES["plot"].with_(
            help="Also draw one output over two inputs to this .png, .svg or .pdf (see `plot_of`)."
        )
    },
)
