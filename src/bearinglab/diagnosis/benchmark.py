"""The diagnosis run over a folder of labelled recordings: :func:`run_benchmark`.

The folder holds a ``labels.csv`` like the one of ``shared/data/real`` (one row per file:
``file``, ``channel``, ``sample_rate_hz``, ``speed_rpm``, the bearing as ``designation`` or
``balls``, ``ball_diameter_mm``, ``pitch_diameter_mm``, ``contact_angle_deg``, and the
label ``fault``: normal, inner, outer, ball, cage; optional ``smith_randall_2015``, and
``defect_width_mm``, the defect's width along the rolling direction, against which the
width read from the record is scored, and ``radial_load_n``, the load it is read under). Each
record is diagnosed by each method asked for on its own and by the methods together (the
verdict users get); records run in parallel on the engine (:mod:`bearinglab.engine`: a
pool of one process per job). :class:`BenchmarkResult` holds the per-record
table, the confusion matrix and the per-class recall; its HTML page (the envelope
spectrum of each record and the lines it matched) is
:func:`bearinglab.report.benchmark.write_benchmark_page`.
"""

from __future__ import annotations

import csv
import io
import math
import re
import statistics
from dataclasses import dataclass, field
from pathlib import Path

from ..engine import reraise_interrupt
from ..errors import InputError
from .methods import parse_methods

#: The verdict when no family passes (diagnosis.verdict.NO_FAULT).
NO_FAULT = "no fault detected"
#: Label in labels.csv -> the verdict that is right.
EXPECTED = {
    "normal": "no fault detected",
    "healthy": "no fault detected",
    "inner": "inner_race",
    "outer": "outer_race",
    "ball": "ball",
    "cage": "cage",
}
#: Other spellings of a label's fault that data sets use (after lower case, "-" and "_"
#: read as spaces): CWRU's "IR", "OR", "B", MFPT's "baseline", "inner race fault" ...
SPELLINGS = {
    "no fault": "normal",
    "no fault detected": "normal",
    "none": "normal",
    "baseline": "normal",
    "normal baseline": "normal",
    "n": "normal",
    "ir": "inner",
    "inner race": "inner",
    "bpfi": "inner",
    "or": "outer",
    "outer race": "outer",
    "bpfo": "outer",
    "b": "ball",
    "rolling element": "ball",
    "roller": "ball",
    "bsf": "ball",
    "ftf": "cage",
}


#: CWRU's fault codes: IR007, OR014@6, B021 (the fault's size in mils, the outer race's
#: clock position).
CWRU_CODE = re.compile(r"(ir|or|b) ?\d+( ?@ ?\d+)?")


def label_fault(text: str) -> str | None:
    """A label's fault as a key of EXPECTED (None when it is none of them).

    >>> label_fault("Inner race fault"), label_fault("OR"), label_fault("healthy")
    ('inner', 'outer', 'healthy')
    >>> label_fault("OR007@6"), label_fault("B021"), label_fault("Normal Baseline")
    ('outer', 'ball', 'normal')
    """
    words = " ".join(str(text).lower().replace("-", " ").replace("_", " ").split())
    words = words.removesuffix(" fault").removesuffix(" defect")
    code = CWRU_CODE.fullmatch(words)
    words = code[1] if code else words
    key = SPELLINGS.get(words, words)
    return key if key in EXPECTED else None


#: Rows and columns of the confusion matrix.
CLASSES = ("no fault detected", "outer_race", "inner_race", "ball", "cage", "compound")


def read_labels(folder) -> list[dict]:
    """Rows of ``folder/labels.csv`` (InputError when missing or without the columns).

    Read as spreadsheets write it: UTF-8 with or without a byte-order mark (else
    Windows-1252), comma, semicolon or tab separated, headers in any case and with spaces
    around them; rows with every cell blank are skipped.
    """
    folder = Path(folder)
    path = folder / "labels.csv"
    if not path.is_file():
        raise InputError("folder", str(folder), "a folder with a labels.csv")
    raw = path.read_bytes()
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = raw.decode("cp1252", errors="replace")
    try:
        dialect = csv.Sniffer().sniff(text.splitlines()[0] if text else "", delimiters=",;\t")
    except csv.Error:
        dialect = csv.excel
    rows = []
    for row in csv.DictReader(io.StringIO(text, newline=""), dialect=dialect):
        row = {
            key.strip().lower(): (value or "").strip()
            for key, value in row.items()
            if isinstance(key, str)
        }
        if any(row.values()):
            rows.append(row)
    need = {"file", "fault"}
    if not rows or not need <= set(rows[0]):
        raise InputError("labels.csv", str(path), f"a header with at least {sorted(need)}")
    for number, row in enumerate(rows, start=2):
        if label_fault(row["fault"]) is None:
            raise InputError(
                "fault",
                row["fault"],
                f"faults among {sorted(EXPECTED)} (or {', '.join(sorted(SPELLINGS))}, or "
                "CWRU's codes such as IR007, OR007@6, B007)",
                hint=f"labels.csv line {number}, {row['file']}",
            )
    return rows


def _number(row: dict, column: str, what: str) -> float | None:
    """The number in ``column`` of a labels row (None when blank; InputError naming the
    column when it is not a number > 0)."""
    text = row.get(column) or ""
    if not text:
        return None
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise InputError(column, text, f"{what}: a number > 0, without a unit")
    return value


def _bearing(row: dict):
    """The bearing of a labels row: its designation, or balls and diameters [mm]."""
    from ..catalog import bearing_from_designation
    from ..geometry import BallBearing

    if row.get("designation"):
        return bearing_from_designation(row["designation"].strip())[0]
    try:
        return BallBearing(
            ball_count=int(float(row["balls"])),
            ball_diameter=float(row["ball_diameter_mm"]) * 1e-3,
            pitch_diameter=float(row["pitch_diameter_mm"]) * 1e-3,
            contact_angle=math.radians(float(row.get("contact_angle_deg") or 0)),
        )
    except (KeyError, TypeError, ValueError):
        raise InputError(
            "labels.csv",
            row.get("file"),
            "a designation, or balls, ball_diameter_mm and pitch_diameter_mm",
        ) from None


def _category(verdict: str) -> str:
    return "compound" if verdict.startswith("compound") else verdict


def outcome(verdict: str | None, expected: str) -> str:
    """``right``, ``wrong`` (a fault that is not the label's, or any fault on a healthy
    record: what costs an engineer most), ``missed`` (no fault on a faulty record) or
    ``error``.

    >>> outcome("ball", "ball"), outcome("outer_race", "ball"), outcome(NO_FAULT, "ball")
    ('right', 'wrong', 'missed')
    """
    if verdict is None or verdict == "error":
        return "error"
    if verdict == expected:
        return "right"
    return "missed" if verdict == NO_FAULT else "wrong"


def run_record(folder: str, row: dict, methods: tuple, keep_spectra: bool = True) -> dict:
    """Diagnose one labelled record by each method and by all together (a worker)."""
    from ..kinematics import defect_frequencies
    from ..signal import read_signal
    from .analysis import analyze_signal

    out = {
        "file": row["file"],
        "fault": row["fault"].strip().lower(),
        "smith_randall_2015": row.get("smith_randall_2015") or None,
        "expected": EXPECTED[label_fault(row["fault"])],
        "error": None,
        "defect_size": None,
        "defect_sizes": [],
        "defect_width_mm": None,
        "sizing_error_percent": None,
    }
    try:
        out["defect_width_mm"] = _number(row, "defect_width_mm", "the defect's width in mm")
        load = _number(row, "radial_load_n", "the radial load on the bearing in N")
        fs = _number(row, "sample_rate_hz", "the sample rate in Hz")
        record, channel = row.get("record_variable") or None, row.get("channel") or None
        try:
            signal = read_signal(
                Path(folder) / row["file"], sample_rate=fs, channel=channel, record=record
            )
        except InputError as exc:
            if exc.parameter != "record":
                raise
            raise InputError("record_variable", record, exc.allowed) from None
        channel = signal.names[0] if channel is not None else None  # bearing.gs from gs
        # a blank (or absent) speed: the one the file stores (CWRU XnnnRPM, MFPT rate);
        # "auto": the speed the signal shows, within 5 % of the stored one
        auto = (row.get("speed_rpm") or "").lower() == "auto"
        rpm = None if auto else _number(row, "speed_rpm", "the shaft speed in rpm or auto")
        rpm = rpm or signal.metadata.get("speed_rpm")
        if rpm is None:
            raise InputError(
                "speed_rpm", row.get("speed_rpm") or "", "a speed in rpm (the file has none)"
            )
        kin = defect_frequencies(_bearing(row), float(rpm) * math.pi / 30)
        runs = (
            {"+".join(methods): methods}
            if len(methods) == 1
            else {**{m: (m,) for m in methods}, "+".join(methods): methods}
        )
        for name, ms in runs.items():
            d = analyze_signal(
                signal,
                None,
                kin,
                channel=channel,
                methods=ms,
                shaft_speed="auto" if auto else None,
                radial_load=load,
            )
            out[name] = d.verdict
            if ms == methods:
                out["verdict"] = d.verdict
                out["significance"] = {k: round(v, 3) for k, v in d.scores.items()}
                out["threshold"] = d.threshold
                out["measured_rpm"] = d.speed.get("measured_rpm")
                out["warnings"] = list(d.warnings)
                out["reason"] = d.reason
                out["defect_sizes"] = [size.to_dict() for size in d.defect_sizes]
                out["defect_size"] = out["defect_sizes"][0] if d.defect_sizes else None
                width = d.defect_size.width if d.defect_size is not None else None
                if width is not None and out["defect_width_mm"] is not None:
                    out["sizing_error_percent"] = 100.0 * (width * 1e3 / out["defect_width_mm"] - 1)
                if keep_spectra:
                    out["diagnosis"] = d
    except Exception as exc:  # noqa: BLE001 - one bad record must not stop the benchmark
        reraise_interrupt(exc)  # a Ctrl-C is no failed record
        out["error"] = f"{type(exc).__name__}: {exc}"
        out["verdict"] = "error"
    out["right"] = out.get("verdict") == out["expected"]
    out["outcome"] = outcome(out.get("verdict"), out["expected"])
    return out


@dataclass(frozen=True)
class BenchmarkResult:
    """Diagnosis of a folder of labelled records.

    ``records``: one dict per record (``file``, ``fault``, ``smith_randall_2015``,
    ``expected``, ``verdict`` with the methods together, one key per method with its own
    verdict, ``right``, ``outcome`` (right, wrong, missed or error: :func:`outcome`),
    ``significance``, ``threshold``, ``measured_rpm``, ``warnings``, ``reason``,
    ``error``, and the width of a race defect found: ``defect_size`` (the verdict's first
    race fault's, null without one), ``defect_sizes``, the label's ``defect_width_mm`` and
    ``sizing_error_percent``); ``methods``; ``folder``.
    """

    folder: str
    methods: tuple
    records: tuple
    diagnoses: dict = field(default_factory=dict, repr=False)

    @property
    def columns(self) -> list[str]:
        """Verdict columns: each method, then the methods together."""
        together = "+".join(self.methods)
        return [*self.methods, together] if len(self.methods) > 1 else [together]

    def confusion(self, column: str | None = None) -> dict:
        """Confusion matrix of ``column`` (default: the methods together): expected ->
        verdict class -> count.

        Parameters
        ----------
        column : str or None
            A method's verdict column, or the methods joined by "+"; None: the methods
            together.
        """
        column = column or "+".join(self.methods)
        matrix = {c: dict.fromkeys((*CLASSES, "error"), 0) for c in CLASSES}
        for r in self.records:
            got = _category(r.get(column) or "error") if not r["error"] else "error"
            matrix[r["expected"]][got if got in matrix[r["expected"]] else "error"] += 1
        return {k: v for k, v in matrix.items() if sum(v.values())}

    def count(self, column: str, kind: str) -> int:
        """Records of ``column`` whose :func:`outcome` is ``kind`` (right, wrong, missed,
        error).

        Parameters
        ----------
        column : str
            A method's verdict column, or the methods joined by "+".
        kind : {"right", "wrong", "missed", "error"}
            The :func:`outcome` counted.

        Returns
        -------
        int
            The number of records with that outcome.
        """
        return sum(
            outcome(None if r["error"] else r.get(column), r["expected"]) == kind
            for r in self.records
        )

    def recall(self, column: str | None = None) -> dict:
        """Per class: right / records of that class [-], for the verdicts of ``column``
        (a method, or by default the methods together).

        Parameters
        ----------
        column : str or None
            A method's verdict column, or the methods joined by "+"; None: the methods
            together.
        """
        return {k: row[k] / sum(row.values()) for k, row in self.confusion(column).items()}

    def accuracy(self, column: str | None = None) -> float:
        """Share of records right [-], for the verdicts of ``column`` (a method, or by
        default the methods together).

        Parameters
        ----------
        column : str or None
            A method's verdict column, or the methods joined by "+"; None: the methods
            together.
        """
        column = column or "+".join(self.methods)
        return sum(r.get(column) == r["expected"] for r in self.records) / len(self.records)

    def sizing(self) -> dict:
        """The widths read against the labels': ``labelled`` (records whose label gives a
        width), ``sized`` (of those, sized), ``median_abs_error_percent`` and
        ``max_abs_error_percent`` (over those sized; null when none), and
        ``sized_without_label`` (records sized whose label gives no width)."""
        labelled = [r for r in self.records if r.get("defect_width_mm") is not None]
        errors = [
            abs(r["sizing_error_percent"])
            for r in labelled
            if r.get("sizing_error_percent") is not None
        ]
        unlabelled = [
            r
            for r in self.records
            if r.get("defect_width_mm") is None
            and (r.get("defect_size") or {}).get("status") == "sized"
        ]
        return {
            "labelled": len(labelled),
            "sized": len(errors),
            "median_abs_error_percent": float(statistics.median(errors)) if errors else None,
            "max_abs_error_percent": max(errors) if errors else None,
            "sized_without_label": len(unlabelled),
        }

    def to_dict(self) -> dict:
        """JSON-ready summary and per-record table (with the :meth:`sizing` summary)."""
        cols = self.columns
        return {
            "folder": self.folder,
            "methods": list(self.methods),
            "columns": cols,
            "records": [{k: v for k, v in r.items() if k != "diagnosis"} for r in self.records],
            "right": {c: self.count(c, "right") for c in cols},
            "wrong": {c: self.count(c, "wrong") for c in cols},
            "missed": {c: self.count(c, "missed") for c in cols},
            "total": len(self.records),
            "confusion": {c: self.confusion(c) for c in cols},
            "recall": {c: self.recall(c) for c in cols},
            "sizing": self.sizing(),
        }

    def to_pandas(self):
        """Per-record table (one row per record)."""
        import pandas as pd

        keys = [
            "file",
            "fault",
            "smith_randall_2015",
            "expected",
            *self.columns,
            "right",
            "outcome",
            "measured_rpm",
            "error",
        ]
        return pd.DataFrame([{k: r.get(k) for k in keys} for r in self.records], columns=keys)

    def plot(self, ax=None, column: str | None = None):
        """Confusion matrix of ``column`` (a method, or by default the methods together)
        as an image with counts, on ``ax`` (a matplotlib Axes; a new figure by default);
        returns (figure, axes).

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        column : str or None
            A method's verdict column, or the methods joined by "+"; None: the methods
            together.
        """
        from ..plotting import _pyplot

        plt = _pyplot()
        matrix = self.confusion(column)
        rows = list(matrix)
        cols = [c for c in (*CLASSES, "error") if any(matrix[r][c] for r in rows)]
        if ax is None:
            fig, ax = plt.subplots(figsize=(1.4 * len(cols) + 2, 0.6 * len(rows) + 1.6))
        else:
            fig = ax.figure
        data = [[matrix[r][c] for c in cols] for r in rows]
        ax.imshow(data, cmap="Blues")
        for i, row in enumerate(data):
            for j, v in enumerate(row):
                ax.text(j, i, str(v), ha="center", va="center")
        ax.set_xticks(range(len(cols)), cols, rotation=30, ha="right")
        ax.set_yticks(range(len(rows)), rows)
        ax.set_xlabel("verdict")
        ax.set_ylabel("label")
        ax.set_title(f"{column or '+'.join(self.methods)}: {self.accuracy(column):.0%} right")
        fig.tight_layout()
        return fig, ax


def run_benchmark(
    folder, methods=None, jobs: int = 1, progress=None, keep_spectra: bool = True
) -> BenchmarkResult:
    """Diagnose every record of ``folder/labels.csv``.

    Parameters
    ----------
    folder : str or Path
        Folder with ``labels.csv`` and the files it names.
    methods : str or sequence, optional
        Methods (default: :data:`bearinglab.diagnosis.DEFAULT_METHODS`); each is also run
        on its own.
    jobs : int
        Records diagnosed at once (a pool of processes,
        :func:`bearinglab.engine.open_jobs`); 1: in this process.
    progress : callable, optional
        ``progress(done, total)``, counted in records, before the first record and after
        each one.
    keep_spectra : bool
        Keep each record's Diagnosis (for the HTML page's spectra).

    Returns
    -------
    BenchmarkResult
    """
    from ..engine import check_progress, check_workers, open_jobs, run_partitions
    from .analysis import DEFAULT_METHODS

    rows = read_labels(folder)
    names = parse_methods(DEFAULT_METHODS if methods is None else methods)
    jobs = min(check_workers("jobs", jobs), len(rows))  # no idle processes
    progress = check_progress(progress)
    results: list[dict | None] = [None] * len(rows)

    def keep(task, result) -> None:
        results[task[0]] = result

    tasks = [(i, str(folder), row, names, keep_spectra) for i, row in enumerate(rows)]
    with open_jobs(max(jobs, 1)) as runner:
        run_partitions(runner, _run_task, tasks, [1] * len(tasks), keep, progress=progress)
    diagnoses = {r["file"]: r.pop("diagnosis") for r in results if "diagnosis" in r}
    return BenchmarkResult(str(folder), names, tuple(results), diagnoses)


def _run_task(task: tuple) -> dict:
    """:func:`run_record` of ``task`` = (index, folder, row, methods, keep_spectra)."""
    return run_record(*task[1:])
