"""run_study: one analysis over many cases, one Parquet file per partition.

The output folder holds ``_study.json`` (what the study is: analysis, grid or case file,
seed, partitioning) and ``part-NNNNN.parquet``, one row per case, in case order: ``case``,
the inputs given (option names, unit in the name), the outputs (``to_dict()`` keys, unit
in the name) and ``error`` (None, or why that case failed). A partition file appears
whole or not at all (written to a temporary name, then renamed), so rerunning an
interrupted study computes exactly the missing partitions; a folder holding another study
is refused before anything runs. ``pandas.read_parquet(folder)`` reads the table.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from ..engine import Progress, check_count, check_progress, measured_run, open_runner
from ..errors import InputError
from ..files import write_atomically
from .analyses import Analysis, run_cases, warm_up
from .analyses import analysis as get_analysis
from .bearings import check_bearing_given
from .cases import (
    CaseTable,
    Grid,
    Uniform,
    canonical,
    check_writable,
    held_description,
    parse_values,
    partition_size_for,
    partitions,
    unknown_option,
    whole_number,
)

MARKER = "_study.json"
#: Hard ceiling on the cases of one study.
MAX_CASES = 10**9
_ARROW = {
    "number": "float64",
    "integer": "int64",
    "text": "string",
    "texts": "string",
    "path": "string",
    "bool": "bool",
    "f": "float64",
    "i": "int64",
    "s": "string",
}


def _schema(a: Analysis, inputs: list[str], random: set):
    import pyarrow as pa

    fields = [pa.field("case", pa.int64())]
    for name in inputs:
        kind = "number" if name in random else a.options[name].kind
        fields.append(pa.field(name, pa.type_for_alias(_ARROW[kind])))
    fields += [pa.field(k, pa.type_for_alias(_ARROW[t])) for k, t in a.outputs.items()]
    fields.append(pa.field("error", pa.string()))
    return pa.schema(fields)


def _partition(task) -> object:
    """Worker side: compute one partition and return it as an Arrow table."""
    import pyarrow as pa

    name, seed, source, start, stop, inputs, random = task
    a = get_analysis(name)
    rows = source.rows(start, stop) if hasattr(source, "rows") else source
    results = run_cases(a, rows, seed)
    schema = _schema(a, inputs, set(random))
    columns = {f.name: [] for f in schema}
    for case, out in zip(rows, results, strict=True):
        merged = {**case, **out}
        for key, values in columns.items():
            values.append(merged.get(key))
    return pa.table(columns, schema=schema)


@dataclass(frozen=True)
class StudyResult:
    """A finished (or resumed) study: where its table is and how the run went.

    Attributes: ``path`` (the folder), ``analysis``, ``cases``, ``partitions`` (in the
    study), ``computed`` (partitions computed by this run; the others were already
    there), ``computed_cases`` (their cases), ``failed_cases`` (cases with an error),
    ``seconds`` (wall time of this run's partitions), ``workers``, ``scheduler``,
    ``dashboard``, ``inputs`` and ``outputs`` (column names), ``peak_memory`` (worker ->
    peak resident memory [bytes]), ``worker_cpu_seconds`` (worker -> CPU time its
    partitions took [s]), ``random_inputs`` (the inputs the seed draws: random ranges and
    the analysis' own random inputs where they are not 0; none: every case is fixed by its
    inputs alone).
    """

    path: Path
    analysis: str
    cases: int
    partitions: int
    computed: int
    computed_cases: int
    failed_cases: int
    seconds: float
    workers: int
    scheduler: str
    dashboard: str | None
    inputs: tuple
    outputs: tuple
    peak_memory: dict = field(default_factory=dict, repr=False)
    worker_cpu_seconds: dict = field(default_factory=dict, repr=False)
    random_inputs: tuple = ()

    @property
    def cases_per_second(self) -> float | None:
        """Cases computed by this run per wall second (None when nothing ran)."""
        if not self.computed or self.seconds <= 0:
            return None
        return self.computed_cases / self.seconds

    def to_pandas(self):
        """The whole table (one row per case, in case order)."""
        return read_study(self.path)

    def to_dict(self) -> dict:
        """JSON-ready summary of the run."""
        return {
            "output": str(self.path),
            "analysis": self.analysis,
            "cases": self.cases,
            "partitions": self.partitions,
            "partitions_computed": self.computed,
            "partitions_reused": self.partitions - self.computed,
            "cases_computed": self.computed_cases,
            "failed_cases": self.failed_cases,
            "wall_time_s": self.seconds,
            "cases_per_s": self.cases_per_second,
            "worker_cpu_time_s": sum(self.worker_cpu_seconds.values()),
            "workers": self.workers,
            "scheduler": self.scheduler,
            "dashboard": self.dashboard,
            "inputs": list(self.inputs),
            "outputs": list(self.outputs),
        }

    def plot(self, output: str, x: str, y: str, path=None, ax=None):
        """Map of the column ``output`` over the input columns ``x`` and ``y`` of this
        study's table, on ``ax`` (a matplotlib Axes; a new figure by default); with
        ``path``, also saved there (.png, .svg, .pdf; the figure is then closed); returns
        (figure, axes)
        (:func:`bearinglab.study.plots.plot_study`).

        Parameters
        ----------
        output : str
            The column mapped (an output of the study).
        x, y : str
            The input columns along the axes.
        path : str or Path or None
            Also save the figure there (.png, .svg or .pdf; the figure is then closed); None:
            not saved.
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from .plots import plot_study

        return plot_study(self.to_pandas(), output, x, y, path=path, ax=ax)


def read_study(path) -> object:
    """The table of the study folder ``path`` (its part-*.parquet files) as a pandas
    DataFrame, in case order.

    Parameters
    ----------
    path : str or Path
        The study folder (holding part-*.parquet files).
    """
    import pandas as pd
    import pyarrow.parquet as pq

    files = sorted(Path(path).glob("part-*.parquet"))
    if not files:
        raise InputError("path", str(path), "a study folder with results (part-*.parquet)")
    frame = pd.concat([pq.read_table(f).to_pandas() for f in files], ignore_index=True)
    return frame.sort_values("case", kind="stable").reset_index(drop=True)


def _source(a: Analysis, grid, cases, seed: int, repeats: int):
    if (grid is None) == (cases is None):
        raise InputError(
            "grid",
            grid,
            "either a grid of options or a cases file, not "
            + ("both" if grid is not None else "neither"),
        )
    if cases is not None:
        return CaseTable(cases, a.options, a.name)
    if not isinstance(grid, dict) or not grid:
        raise InputError("grid", grid, "a dict option name -> values with at least one option")
    whole_number("repeats", repeats, 1)
    values = {}
    for name, spec in grid.items():
        if name not in a.options:
            raise unknown_option(str(name), a.options, a.name)
        values[name] = parse_values(name, spec, a.options[name])
    return Grid(values, repeats, seed)


def _check_folder(folder: Path, identity: dict) -> None:
    """Refuse a folder that holds anything but this same study (nothing is touched)."""
    held = held_description(folder / MARKER)
    if held is not None:
        if canonical(held.get("identity")) != canonical(identity):
            what = (
                f"analysis {held.get('analysis')!r}, {held.get('cases')} cases, seed "
                f"{held.get('seed')}"
                if held
                else "an unreadable study description"
            )
            raise InputError(
                "output",
                str(folder),
                "a new folder or one holding this same study",
                f"it holds a different study: {what}; choose another "
                "output folder or remove that one",
            )
    elif folder.exists():
        if not folder.is_dir():
            raise InputError("output", str(folder), "a folder (this is a file)")
        if any(p for p in folder.iterdir()):
            raise InputError(
                "output",
                str(folder),
                "a new or empty folder, or one holding this same study",
                "it holds other files and no _study.json",
            )


def run_study(
    analysis: str,
    grid: dict | None = None,
    *,
    cases=None,
    output,
    seed: int = 0,
    repeats: int = 1,
    partition_size: int | None = None,
    scheduler: str | None = None,
    workers: int | None = None,
    max_cases: int | None = None,
    progress: Progress | None = None,
    connect_timeout: float | None = None,
) -> StudyResult:
    """Evaluate ``analysis`` over a grid of inputs or a table of cases, on dask.

    Parameters
    ----------
    analysis : str
        One of :data:`bearinglab.study.ANALYSES` (stiffness, static, frequencies, life,
        friction, ring-modes, noise, simulate).
    grid : dict, optional
        Option name -> values: a value, a list, or text "A,B,C", "START:STOP:COUNT",
        "log:START:STOP:COUNT", "uniform:LOW:HIGH" (:mod:`.cases`). Options not given take
        their defaults (:func:`describe_options`).
    cases : path, optional
        Instead of a grid, a .csv or .parquet file with one case per row.
    output : path
        Folder of the results (created; reused only by the same study).
    seed : int
        Study seed: a case's random inputs come from (seed, case index) only.
    repeats : int
        Grid points repeated this many times (with random options drawn afresh).
    partition_size : int, optional
        Cases per partition (default: from the analysis and the case count).
    scheduler, workers, connect_timeout
        Where to run (:func:`bearinglab.engine.open_runner`).
    max_cases : int, optional
        Refuse a study of more cases than this (the command line's confirmation limit).
    progress : callable, optional
        ``progress(done, total)``, counted in cases (those already in the folder
        included), before the first partition and after each one.

    Returns
    -------
    StudyResult

    Raises
    ------
    bearinglab.engine.Interrupted
        On Ctrl-C, with the cases done; the partitions written are kept, and running the
        same study again computes only the others.
    """
    a = get_analysis(analysis)
    whole_number("seed", seed, 0)
    progress = check_progress(progress)
    source = _source(a, grid, cases, seed, repeats)
    check_bearing_given(set(source.columns))
    count = source.count
    check_count("cases", count, MAX_CASES, max_cases, "run")
    partition_size = partition_size_for(partition_size, count, a.largest)
    random = sorted(k for k, v in getattr(source, "values", {}).items() if isinstance(v, Uniform))
    identity = {
        "analysis": a.name,
        **source.identity(),
        "seed": seed,
        "partition_size": partition_size,
    }
    folder = Path(output)
    _check_folder(folder, identity)
    check_writable("output", folder)
    spans = partitions(count, partition_size)
    width = max(5, len(str(len(spans) - 1)))
    names = [f"part-{i:0{width}d}.parquet" for i in range(len(spans))]
    todo = [i for i, n in enumerate(names) if not (folder / n).exists()]
    inputs = list(source.columns)
    marker = json.dumps(
        {
            "kind": "bearinglab study",
            "bearinglab_version": __version__,
            "analysis": a.name,
            "cases": count,
            "seed": seed,
            "partitions": len(spans),
            "identity": identity,
            "inputs": inputs,
            "outputs": list(a.outputs),
            "defaults": {k: o.default for k, o in a.options.items() if k not in inputs},
        },
        indent=1,
        default=str,
    )
    tasks, units = [], []
    for i in todo:
        start, stop = spans[i]
        part = source if isinstance(source, Grid) else source.rows(start, stop)
        tasks.append((a.name, seed, part, start, stop, inputs, random))
        units.append(stop - start)
    file_of = {(t[3], t[4]): names[i] for t, i in zip(tasks, todo, strict=True)}

    def write(task, table) -> None:
        import pyarrow.parquet as pq

        write_atomically(
            folder / file_of[(task[3], task[4])],
            lambda tmp: pq.write_table(table, tmp, compression="zstd"),
        )

    seconds, memory, cpu = 0.0, {}, {}
    runner_info = ("-", 0, None)
    if tasks:
        # connect first: an unreachable scheduler leaves no folder behind
        with open_runner(scheduler, workers, connect_timeout) as runner:
            folder.mkdir(parents=True, exist_ok=True)
            write_atomically(
                folder / MARKER, lambda tmp: Path(tmp).write_text(marker, encoding="utf-8")
            )
            runner_info = (runner.scheduler, runner.workers, runner.dashboard)
            # a few first cases (the very first may fail, e.g. an unloaded stiffness case)
            first = source.rows(0, min(count, 3))
            seconds, cpu, memory = measured_run(
                runner,
                a.warm,
                (warm_up, (a.name, first)),
                _partition,
                tasks,
                units,
                write,
                progress=progress,
                total=count,
                done=count - sum(units),
            )
    failed = _failed(folder, names)
    return StudyResult(
        folder,
        a.name,
        count,
        len(spans),
        len(tasks),
        sum(units),
        failed,
        seconds,
        runner_info[1],
        runner_info[0],
        runner_info[2],
        tuple(inputs),
        tuple(a.outputs),
        memory,
        cpu,
        source.random_inputs(a.options),
    )


def _failed(folder: Path, names: list[str]) -> int:
    import pyarrow.compute as pc
    import pyarrow.parquet as pq

    total = 0
    for n in names:
        column = pq.read_table(folder / n, columns=["error"]).column("error")
        total += len(column) - int(pc.sum(pc.is_null(column)).as_py() or 0)
    return total


def study_columns(analysis: str, grid: dict | None = None, *, cases=None, repeats: int = 1) -> dict:
    """The columns a study's table will have, known before it runs (the grid or the
    cases file checked as :func:`run_study` checks them): ``inputs`` (the inputs given),
    ``outputs``, and ``varying`` (the inputs that take more than one value)."""
    a = get_analysis(analysis)
    source = _source(a, grid, cases, 0, repeats)
    if isinstance(source, Grid):
        varying = [k for k, v in source.values.items() if isinstance(v, Uniform) or len(set(v)) > 1]
    else:
        varying = [c for c in source.columns if len({repr(r.get(c)) for r in source.records}) > 1]
    return {"inputs": list(source.columns), "outputs": list(a.outputs), "varying": varying}


def describe_options(analysis: str) -> list[dict]:
    """The options of ``analysis`` (a name of :data:`bearinglab.study.ANALYSES` or an
    alias): name, kind, default, help and choices of each (for --help and docs).

    Parameters
    ----------
    analysis : str
        The analysis' name (or an alias), e.g. "static".
    """
    a = get_analysis(analysis)
    return [
        {
            "name": k,
            "kind": o.kind,
            "default": o.default,
            "help": o.help,
            "choices": list(o.choices),
        }
        for k, o in a.options.items()
    ]
