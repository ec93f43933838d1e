"""make_dataset: labelled synthetic vibration records, made on dask, in the
bearing-datasets layout (:mod:`.layout`).

A record (:func:`.record.make_record`) is the acceleration of bearinglab's dynamic
model with the record's defects and form errors, passed through the transfer path and
given white measurement noise. Records are made a partition at a time on the workers;
each partition's signals and metadata are written as they arrive (never the whole set in
memory); a rerun makes only the missing partitions, and metadata.parquet and
manifest.json are written once all are there. A record that fails is left out and listed
(``failed.csv`` in ``_bearinglab/``).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from ..engine import (
    Progress,
    check_count,
    check_progress,
    measured_run,
    open_runner,
    reraise_interrupt,
)
from ..errors import InputError
from ..files import write_atomically, write_text_atomically
from ..study.cases import (
    canonical,
    check_writable,
    held_description,
    partition_size_for,
    partitions,
    whole_number,
)
from . import layout
from .record import make_record
from .sampling import DatasetSpec

OWN = "_bearinglab"
MARKER = "dataset.json"
#: Hard ceiling on the records of one set.
MAX_RECORDS = 10**7
#: Largest partition [records]: about a few seconds of the rigid model at 1 s, 20 kHz.
LARGEST_PARTITION = 20


def _partition(task):
    """Worker side: make the records of one partition; (signal table, metadata rows)."""
    spec, seed, name, start, stop, width, file = task
    ids, signals, rows = [], [], []
    for i in range(start, stop):
        recording = f"rec{i:0{width}d}"
        try:
            x, r, (bearing, kin) = make_record(spec, seed, i)
        except Exception as exc:  # noqa: BLE001 - a failed record never stops the set
            reraise_interrupt(exc)  # a Ctrl-C is no failed record: the record is made again
            from ..study.analyses import error_text

            rows.append(
                {
                    "recording_id": recording,
                    "error": error_text(exc),
                    "error_input": exc.parameter if isinstance(exc, InputError) else None,
                }
            )
            continue
        row = layout.metadata_row(name, recording, r, bearing, kin, x.size, r["sample_rate_hz"])
        row.update(
            {
                "signal_file": file,
                "signal_row_group": 0,
                "signal_row": len(ids),
                "sha256": layout.digest(x),
                "error": None,
                "error_input": None,
            }
        )
        ids.append(row["signal_id"])
        signals.append(x)
        rows.append(row)
    return layout.signal_table(ids, signals), rows


@dataclass(frozen=True)
class DatasetResult:
    """A finished data set: ``path``, ``name``, ``records`` asked for, ``written`` and
    ``failed`` records, ``partitions``, ``computed`` (by this run), ``seconds`` (this run's
    wall time), ``workers``, ``scheduler``, ``dashboard``, ``peak_memory`` [bytes] and
    ``worker_cpu_seconds`` [s] per worker process, and the ``spec`` the records were
    drawn from (:class:`.sampling.DatasetSpec`)."""

    path: Path
    name: str
    records: int
    written: int
    failed: int
    partitions: int
    computed: int
    computed_records: int
    seconds: float
    workers: int
    scheduler: str
    dashboard: str | None
    peak_memory: dict = field(default_factory=dict, repr=False)
    worker_cpu_seconds: dict = field(default_factory=dict, repr=False)
    spec: DatasetSpec | None = field(default=None, repr=False, compare=False)

    @property
    def records_per_second(self) -> float | None:
        """Records made by this run per wall second."""
        return self.computed_records / self.seconds if self.computed and self.seconds > 0 else None

    def to_pandas(self):
        """The metadata table (one row per signal)."""
        import pandas as pd

        return pd.read_parquet(self.path / "metadata.parquet")

    def to_dict(self) -> dict:
        """JSON-ready summary; ``open_with`` is how bearing-datasets opens the set."""
        return {
            "output": str(self.path),
            "name": self.name,
            "records": self.records,
            "records_written": self.written,
            "records_failed": self.failed,
            "partitions": self.partitions,
            "partitions_computed": self.computed,
            "partitions_reused": self.partitions - self.computed,
            "records_computed": self.computed_records,
            "wall_time_s": self.seconds,
            "records_per_s": self.records_per_second,
            "worker_cpu_time_s": sum(self.worker_cpu_seconds.values()),
            "workers": self.workers,
            "scheduler": self.scheduler,
            "dashboard": self.dashboard,
            "open_with": f"bearing_datasets.open({self.name!r}, root={str(self.path.parent)!r})",
        }

    def plot(self, ax=None):
        """Records per fault type, radial load [N] against speed [rpm] (a scatter of the
        set's coverage), on ``ax`` (a matplotlib Axes; a new figure by default); returns
        (figure, axes).

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from ..plotting import figure_axes

        meta = self.to_pandas()
        fig, ax = figure_axes(ax, figsize=(7, 4))
        for i, (fault, part) in enumerate(meta.groupby("fault_type")):
            ax.scatter(
                part["speed_rpm"], part["load"], s=8, color=f"C{i}", label=f"{fault} ({len(part)})"
            )
        ax.set_xlabel("speed [rpm]")
        ax.set_ylabel("radial load [N]")
        ax.legend(fontsize=8)
        return fig, ax


def _check_folder(folder: Path, identity: dict) -> None:
    held = held_description(folder / OWN / MARKER)
    if held is not None:
        if canonical(held.get("identity")) != canonical(identity):
            raise InputError(
                "output",
                str(folder),
                "a new folder or one holding this same data set",
                f"it holds a different data set ({held.get('records')}"
                f" records, seed {held.get('seed')}); choose another output "
                "folder or remove that one",
            )
    elif folder.exists() and (not folder.is_dir() or any(folder.iterdir())):
        raise InputError(
            "output",
            str(folder),
            "a new or empty folder, or one holding this same data set",
            "it holds other files",
        )


def make_dataset(
    output,
    records: int,
    *,
    seed: int = 0,
    partition_size: int | None = None,
    scheduler: str | None = None,
    workers: int | None = None,
    max_records: int | None = None,
    progress: Progress | None = None,
    connect_timeout: float | None = None,
    **ranges,
) -> DatasetResult:
    """Make ``records`` labelled synthetic vibration records in the bearing-datasets layout.

    Parameters
    ----------
    output : path
        The data set's folder; its name is the data set's name
        (``bearing_datasets.open(name, root=parent)`` reads it).
    records : int
        Number of records.
    seed : int
        Record i's inputs come from (seed, i) only.
    partition_size, scheduler, workers, connect_timeout
        As for :func:`bearinglab.study.run_study`.
    progress : callable, optional
        ``progress(done, total)``, counted in records (those already in the folder
        included), before the first partition and after each one.
    max_records : int, optional
        Refuse more records than this (the command line's confirmation limit).
    **ranges
        What to randomise: a value (fixed), a pair (low, high) (uniform), a list (choices),
        or text "V", "LOW:HIGH", "A,B,C" (:class:`.sampling.DatasetSpec`):
        ``bearings`` (designations or dicts of geometry options; default 6205-2RS),
        ``speed_rpm`` (1700-1800), ``radial_load_n`` (200-2000), ``faults`` (classes
        among none, outer, inner, ball, compound; cage is refused: the models have no cage
        defect), ``defect_width_mm`` (0.2-1.5), ``defect_depth_mm`` (0.1-0.3),
        ``defect_position_deg`` (outer race, -135 to -45), ``waviness_amplitude_um`` (0),
        ``waviness_orders`` (2-30), ``ball_size_error_um`` (0), ``noise_ms2`` (0.5-5),
        ``resonances`` (list of (frequency range, damping range); default one at
        2.5-4.5 kHz with damping 0.02-0.08), ``sample_rate_hz`` (20000), ``duration_s``
        (1), ``model`` (rigid).

    Returns
    -------
    DatasetResult

    Raises
    ------
    bearinglab.engine.Interrupted
        On Ctrl-C, with the records done; the partitions written are kept, and making
        the same set again makes only the others.
    """
    whole_number("seed", seed, 0)
    progress = check_progress(progress)
    spec = DatasetSpec(records, **ranges)
    check_count("records", records, MAX_RECORDS, max_records, "make")
    partition_size = partition_size_for(partition_size, records, LARGEST_PARTITION)
    folder = Path(output)
    name = folder.resolve().name
    if not name:
        raise InputError("output", str(output), "a folder with a name (the data set's name)")
    identity = {
        "spec": spec.identity(),
        "seed": seed,
        "partition_size": partition_size,
        "name": name,
    }
    _check_folder(folder, identity)
    check_writable("output", folder)
    spans = partitions(records, partition_size)
    width = max(6, len(str(records - 1)))
    pwidth = max(5, len(str(len(spans) - 1)))
    own = folder / OWN
    metas = [own / f"meta-{i:0{pwidth}d}.parquet" for i in range(len(spans))]
    files = [f"part-{layout.DTYPE}-{i:0{pwidth}d}.parquet" for i in range(len(spans))]
    todo = [i for i in range(len(spans)) if not metas[i].exists()]
    marker = json.dumps(
        {
            "kind": "bearinglab dataset",
            "bearinglab_version": __version__,
            "records": records,
            "seed": seed,
            "identity": identity,
        },
        indent=1,
        default=str,
    )
    tasks = [(spec, seed, name, *spans[i], width, files[i]) for i in todo]
    units = [spans[i][1] - spans[i][0] for i in todo]
    where = {spans[i]: i for i in todo}

    def write(task, result) -> None:
        import pandas as pd
        import pyarrow.parquet as pq

        table, rows = result
        i = where[(task[3], task[4])]
        write_atomically(
            folder / "signals" / files[i],
            lambda tmp: pq.write_table(table, tmp, compression="zstd"),
        )
        frame = pd.DataFrame(rows)
        write_atomically(metas[i], lambda tmp: frame.to_parquet(tmp, index=False))

    existed = folder.exists()
    fresh = not existed or not any(folder.iterdir())
    try:
        seconds, memory, cpu, info = _run(
            folder,
            own,
            marker,
            spec,
            seed,
            tasks,
            units,
            write,
            records,
            scheduler,
            workers,
            connect_timeout,
            progress,
        )
        written, failed = _finish(folder, name, metas, seed, records, spec)
    except InputError:
        # a set no record of which can be made (the same on every rerun): nothing is kept
        # of what this run wrote; an interrupted run keeps its partitions (a rerun resumes)
        if fresh and folder.exists():
            _remove(folder, keep_folder=existed)
        raise
    return DatasetResult(
        folder,
        name,
        records,
        written,
        failed,
        len(spans),
        len(tasks),
        sum(units),
        seconds,
        info[1],
        info[0],
        info[2],
        memory,
        cpu,
        spec,
    )


def _run(
    folder,
    own,
    marker,
    spec,
    seed,
    tasks,
    units,
    write,
    records,
    scheduler,
    workers,
    connect_timeout,
    progress,
):
    """Make the partitions ``tasks`` (none: nothing to do); (wall time, peak memory and
    CPU time per worker, (scheduler, workers, dashboard))."""
    if not tasks:
        return 0.0, {}, {}, ("-", 0, None)
    # connect first: an unreachable scheduler leaves no folder behind
    with open_runner(scheduler, workers, connect_timeout) as runner:
        (folder / "signals").mkdir(parents=True, exist_ok=True)
        own.mkdir(exist_ok=True)
        write_text_atomically(own / MARKER, marker)
        info = (runner.scheduler, runner.workers, runner.dashboard)
        seconds, cpu, memory = measured_run(
            runner,
            ("bearinglab.dynamics",),
            (_warm, (spec, seed)),
            _partition,
            tasks,
            units,
            write,
            progress=progress,
            total=records,
            done=records - sum(units),
        )
    return seconds, memory, cpu, info


def _remove(folder: Path, keep_folder: bool) -> None:
    """Remove what a run wrote in ``folder`` (and the folder itself unless ``keep_folder``:
    it was there, empty, before)."""
    import shutil

    if not keep_folder:
        shutil.rmtree(folder, ignore_errors=True)
        return
    for item in folder.iterdir():
        if item.is_dir():
            shutil.rmtree(item, ignore_errors=True)
        else:
            item.unlink(missing_ok=True)


def _warm(args) -> None:
    """A short first record on each worker: loads the compiled model."""
    spec, seed = args
    import dataclasses

    make_record(
        dataclasses.replace(spec, duration_s=0.02, sample_rate_hz=20000.0, resonances=()),
        seed,
        0,
        check=False,
    )


def _finish(folder: Path, name: str, metas: list[Path], seed: int, records: int, spec=None):
    """metadata.parquet and manifest.json from the partitions' metadata."""
    import pandas as pd
    import pyarrow as pa
    import pyarrow.parquet as pq

    frame = pd.concat([pd.read_parquet(m) for m in metas], ignore_index=True)
    if "error_input" not in frame.columns:  # partitions written before it was kept
        frame["error_input"] = None
    bad = frame[frame["error"].notna()]
    good = frame[frame["error"].isna()].drop(columns=["error", "error_input"])
    if len(bad):
        failed = bad[["recording_id", "error"]]
        write_atomically(folder / OWN / "failed.csv", lambda tmp: failed.to_csv(tmp, index=False))
    if good.empty:
        first = bad.iloc[0]
        name = first["error_input"] if isinstance(first["error_input"], str) else "records"
        value = records if name == "records" else getattr(spec, name, None)
        raise InputError(
            name,
            value,
            "settings with which at least one record can be made",
            (f"all {len(bad)} records failed" if len(bad) > 1 else "the one record failed")
            + f"; the first, {first['recording_id']}: {first['error']}",
        )
    digests = dict(zip(good["signal_id"], good.pop("sha256"), strict=True))
    good = layout.order_columns(good.reset_index(drop=True))
    for column in (
        "signal_row_group",
        "signal_row",
        "n_samples",
        "fault_severity_level",
        "record_seed",
    ):
        good[column] = good[column].astype("int64")
    good["sensor_at_fault"] = good["sensor_at_fault"].astype(bool)
    write_atomically(
        folder / "metadata.parquet",
        lambda tmp: pq.write_table(
            pa.Table.from_pandas(good, preserve_index=False), tmp, compression="zstd"
        ),
    )
    citation = (
        f"Synthetic records made with bearinglab {__version__} (seed {seed}); "
        "models: seed 003 rigid / seed 004 slip, see bearinglab's docs"
    )
    text = json.dumps(layout.manifest(name, good, __version__, citation, digests), indent=1)
    write_atomically(
        folder / "manifest.json", lambda tmp: Path(tmp).write_text(text, encoding="utf-8")
    )
    return len(good), len(bad)
