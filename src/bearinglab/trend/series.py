"""A series of recordings of one machine: the folder layouts a trend reads, each record's
time, and the samples of the channels asked for.

Two layouts (:func:`list_records` tells them apart):

- **PRONOSTIA** ([data-PRONOSTIA], [Nectoux2012]) as published: headerless CSV snapshots
  ``acc_NNNNN.csv`` whose six columns are the hour, minute, second and microsecond of each
  sample and the horizontal and vertical accelerations [g], sampled at 25.6 kHz (the
  rate the data set states; the files do not store it). The channels are called
  ``horizontal`` and ``vertical``; a record's time is the time of day of its first
  sample. The snapshot numbers give the order; the clocks, which carry no date, give the
  times, a day added at midnight (:func:`snapshot_times`; a clock that breaks the order
  of the numbers is replaced by the time the number puts it at). The temperature files
  ``temp_NNNNN.csv`` of some runs are not vibration and are left out. Some published
  folders separate the columns with ";" instead of ",": both are read.
- **records**: the files ``analyze`` reads (:data:`bearinglab.signal.SUFFIXES`: .npz,
  .csv with a time column, .wav, .mat), each record's time from an index file
  ``index.csv`` (columns ``file`` and ``time_s`` [s], or ``time`` as an ISO 8601 date and
  time) or from the file itself (``time_s`` [s] or ``start_time`` (ISO 8601) in its
  metadata, which ``write_signal`` stores in .npz and .mat files).

A file that cannot be read is reported by :func:`read_record` as an :class:`InputError`
naming it; the analysis skips it with a warning.
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

import numpy as np

from ..errors import InputError

#: The PRONOSTIA snapshot file names; the number counts snapshots in the order recorded.
PRONOSTIA_FILE = re.compile(r"^acc_(\d+)\.csv$", re.IGNORECASE)
#: PRONOSTIA's sample rate [Hz] (the data set's description; the files do not store it).
PRONOSTIA_SAMPLE_RATE = 25600.0
#: PRONOSTIA's two accelerometers, in the order of the file's columns 5 and 6.
PRONOSTIA_CHANNELS = ("horizontal", "vertical")
#: The index file of a folder of records: one row per file, its time.
INDEX_FILE = "index.csv"
#: Files of a folder of records that are not records.
NOT_RECORDS = {INDEX_FILE, "labels.csv"}
#: Seconds in a day.
DAY = 86400.0
#: Fewest samples per record: the fast kurtogram's smallest record (2 x 128).
MIN_RECORD_SAMPLES = 256

LAYOUTS = ("pronostia", "records")


@dataclass(frozen=True)
class Listing:
    """The recordings of a folder: ``layout`` (pronostia or records), ``files`` (names in
    the folder, in name or snapshot order), when an index file gives them their ``times``
    [s], and the record files of the folder the index leaves out (``unlisted``)."""

    folder: str
    layout: str
    files: tuple[str, ...]
    times: tuple[float, ...] | None = None
    unlisted: tuple[str, ...] = ()

    def subset(self, indices) -> Listing:
        """The records ``indices`` of this listing, in that order."""
        times = None if self.times is None else tuple(self.times[i] for i in indices)
        return Listing(self.folder, self.layout, tuple(self.files[i] for i in indices), times)


@dataclass(frozen=True)
class Record:
    """One recording read: its ``file``, ``time`` [s] (time of day for PRONOSTIA, else the
    index's or the file's own clock), ``sample_rate`` [Hz], ``channels`` (names) and
    ``samples`` (channels x samples, in the sensor's unit); the rate the file stores when
    another was given (``stored_sample_rate``, else None)."""

    file: str
    time: float
    sample_rate: float
    channels: tuple[str, ...]
    samples: np.ndarray
    stored_sample_rate: float | None = None


def list_records(folder) -> Listing:
    """The recordings of ``folder`` and its layout (InputError when there are none).

    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     for name in ("acc_00002.csv", "acc_00001.csv", "temp_00001.csv"):
    ...         _ = (Path(tmp) / name).write_text("9,0,0,0,0.1,0.2\\n")
    ...     listing = list_records(tmp)
    >>> listing.layout, listing.files
    ('pronostia', ('acc_00001.csv', 'acc_00002.csv'))
    """
    from ..signal import SUFFIXES

    path = Path(folder)
    if not path.is_dir():
        raise InputError("folder", str(folder), "an existing folder of recordings")
    names = sorted(p.name for p in path.iterdir() if p.is_file())
    snapshots = sorted(
        (n for n in names if PRONOSTIA_FILE.match(n)),
        key=lambda n: (snapshot_number(n), n),
    )
    if snapshots:
        return Listing(str(folder), "pronostia", tuple(snapshots))
    records = [n for n in names if Path(n).suffix.lower() in SUFFIXES and n not in NOT_RECORDS]
    if INDEX_FILE in names:
        files, times = read_index(path / INDEX_FILE)
        unlisted = tuple(n for n in records if n not in set(files))
        return Listing(str(folder), "records", files, times, unlisted)
    if not records:
        what = "an empty folder" if not names else f"{len(names)} files, none a recording"
        raise InputError(
            "folder",
            str(folder),
            "a folder of recordings: PRONOSTIA snapshots acc_NNNNN.csv, or records "
            f"{', '.join(SUFFIXES)} (with an {INDEX_FILE} of their times)",
            hint=what,
        )
    return Listing(str(folder), "records", tuple(records))


def _parse_time(text: str) -> float:
    """A time as seconds: a number [s], or an ISO 8601 date and time (seconds since 1970,
    UTC when it names no zone)."""
    try:
        value = float(text)
    except ValueError:
        try:
            stamp = datetime.fromisoformat(text.strip())
        except ValueError:
            return math.nan
        if stamp.tzinfo is None:
            stamp = stamp.replace(tzinfo=UTC)
        return stamp.timestamp()
    return value


def read_index(path) -> tuple[tuple[str, ...], tuple[float, ...]]:
    """(files, times [s]) of an index file: a header with ``file`` and ``time_s`` (seconds)
    or ``time`` (ISO 8601 date and time, or seconds)."""
    path = Path(path)
    text = path.read_text(encoding="utf-8-sig", errors="replace")
    rows = [
        {(k or "").strip().lower(): (v or "").strip() for k, v in row.items()}
        for row in csv.DictReader(io.StringIO(text))
    ]
    rows = [r for r in rows if any(r.values())]
    column = next((c for c in ("time_s", "time") if rows and c in rows[0]), None)
    if not rows or "file" not in rows[0] or column is None:
        raise InputError(
            INDEX_FILE,
            str(path),
            "a header with file and time_s (seconds) or time (ISO 8601), one row per record",
        )
    files, times = [], []
    for number, row in enumerate(rows, start=2):
        t = _parse_time(row[column])
        if not math.isfinite(t):
            raise InputError(
                column,
                row[column],
                "a time in seconds or an ISO 8601 date and time",
                hint=f"{INDEX_FILE} line {number}, {row['file']}",
            )
        files.append(row["file"])
        times.append(t)
    return tuple(files), tuple(times)


#: What a PRONOSTIA snapshot must be.
_SNAPSHOT = (
    "a PRONOSTIA snapshot: a headerless CSV of 6 numeric columns (hour, minute, second, "
    f"microsecond, horizontal, vertical [g]), at least {MIN_RECORD_SAMPLES} rows"
)


def _dialect(data: bytes) -> tuple[str, str]:
    """(column separator, decimal mark) of a PRONOSTIA file, from its first line."""
    first = data.split(b"\n", 1)[0]
    if b";" in first:
        return ";", "," if b"," in first else "."
    return ",", "."


def _parse(data: bytes, dialect: tuple[str, str]) -> np.ndarray:
    """The table of CSV bytes (ValueError when pandas cannot read it as numbers)."""
    import pandas as pd

    sep, decimal = dialect
    return pd.read_csv(
        io.BytesIO(data), header=None, sep=sep, decimal=decimal, dtype=np.float64, engine="c"
    ).to_numpy()


def _snapshot(name: str, table: np.ndarray) -> tuple[float, np.ndarray]:
    """(clock [s], samples 2 x n) of one snapshot's table, or InputError naming it."""
    if table.ndim != 2 or table.shape[1] != 6 or table.shape[0] < MIN_RECORD_SAMPLES:
        raise InputError("path", name, _SNAPSHOT, hint=f"it holds a table of {table.shape}")
    if not np.all(np.isfinite(table)):
        raise InputError("path", name, _SNAPSHOT, hint="it has empty or non-finite cells")
    h, m, s, us = table[0, :4]
    clock = 3600.0 * h + 60.0 * m + s + 1e-6 * us
    if not 0.0 <= clock < DAY + 1.0:
        raise InputError("path", name, _SNAPSHOT, hint=f"its first time reads {h:g}:{m:g}:{s:g}")
    return float(clock), np.ascontiguousarray(table[:, 4:6].T)


def read_pronostia_files(paths) -> list:
    """Each PRONOSTIA snapshot of ``paths`` as (time of day of its first sample [s],
    samples: 2 x n [g]), or the InputError that names it.

    The columns are hour, minute, second, microsecond, horizontal and vertical
    acceleration; the microseconds may be written as 1.1879e+05 or 1.6558e+005. Files of
    one dialect are parsed together (one pandas call: its fixed cost is most of a small
    file's); when that fails, each file alone, so that the bad one is named.
    """
    paths = [Path(p) for p in paths]
    out: list = [None] * len(paths)
    groups: dict[tuple, list] = {}
    for i, path in enumerate(paths):
        try:
            data = path.read_bytes()
        except OSError as exc:
            out[i] = InputError("path", path.name, _SNAPSHOT, hint=exc.strerror or "unreadable")
            continue
        if data and not data.endswith(b"\n"):
            data += b"\n"
        groups.setdefault(_dialect(data), []).append((i, data))
    for dialect, members in groups.items():
        rows = [data.count(b"\n") for _, data in members]
        try:
            table = _parse(b"".join(data for _, data in members), dialect)
            if table.shape != (sum(rows), 6):
                raise ValueError("rows")
        except ValueError:
            table = None
        for k, (i, data) in enumerate(members):
            name = paths[i].name
            try:
                if table is not None:
                    part = table[sum(rows[:k]) : sum(rows[: k + 1])]
                else:
                    try:
                        part = _parse(data, dialect)
                    except ValueError as exc:  # parser and empty-data errors
                        hint = " ".join(str(exc).split())[:120]
                        raise InputError("path", name, _SNAPSHOT, hint=hint) from None
                out[i] = _snapshot(name, part)
            except InputError as exc:
                out[i] = exc
    return out


def read_pronostia(path) -> tuple[float, np.ndarray]:
    """(time of day of the first sample [s], samples: 2 x n [g]) of a PRONOSTIA snapshot
    (:func:`read_pronostia_files`); InputError naming it when it cannot be read."""
    (result,) = read_pronostia_files([path])
    if isinstance(result, InputError):
        raise result
    return result


def _metadata_time(metadata: dict) -> float | None:
    """The record's time [s] from its metadata (``time_s`` or ``start_time``), if any."""
    for key in ("time_s", "start_time"):
        value = metadata.get(key)
        if value is None:
            continue
        t = _parse_time(str(value))
        if math.isfinite(t):
            return t
    return None


def _select(record: tuple, file: str, channels, sample_rate) -> Record:
    """A PRONOSTIA record from (clock, samples), with the channels asked for."""
    clock, x = record
    names = PRONOSTIA_CHANNELS
    fs = PRONOSTIA_SAMPLE_RATE if sample_rate is None else float(sample_rate)
    if channels is not None:
        missing = [c for c in channels if c not in names]
        if missing:
            raise InputError("channels", missing[0], f"one of {list(names)}")
        x = x[[names.index(c) for c in channels]]
        names = tuple(channels)
    return Record(file, clock, fs, tuple(names), x)


def _read_one(listing: Listing, index: int, channels, sample_rate) -> Record:
    """Record ``index`` of a folder of records (InputError naming the file)."""
    from ..signal import read_signal

    file = listing.files[index]
    signal = read_signal(Path(listing.folder) / file, sample_rate=sample_rate, channel=channels)
    if listing.times is not None:
        clock = listing.times[index]
    else:
        clock = _metadata_time(signal.metadata)
        if clock is None:
            raise InputError(
                "path",
                file,
                f"a record with a time: a row in {INDEX_FILE} (file, time_s) or time_s / "
                "start_time in its metadata",
            )
    if signal.n_samples < MIN_RECORD_SAMPLES:
        raise InputError(
            "path", file, f"a record of at least {MIN_RECORD_SAMPLES} samples", hint="too short"
        )
    x = np.stack([signal.channel(c) for c in signal.names])
    stored = signal.metadata.get("stored_sample_rate_hz")
    return Record(file, float(clock), signal.sample_rate, signal.names, x, stored)


def read_records(
    listing: Listing,
    indices=None,
    channels: tuple[str, ...] | None = None,
    sample_rate: float | None = None,
) -> list:
    """Records ``indices`` (default all) of ``listing``, with ``channels`` (default all)
    in that order: each a :class:`Record`, or the InputError naming the file that could
    not be read, lacks a channel, has no time or is too short."""
    indices = range(len(listing.files)) if indices is None else indices
    if listing.layout == "pronostia":
        files = [listing.files[i] for i in indices]
        raw = read_pronostia_files([Path(listing.folder) / f for f in files])
        out = []
        for file, r in zip(files, raw, strict=True):
            try:
                out.append(
                    r if isinstance(r, InputError) else _select(r, file, channels, sample_rate)
                )
            except InputError as exc:
                out.append(exc)
        return out
    out = []
    for i in indices:
        try:
            out.append(_read_one(listing, i, channels, sample_rate))
        except InputError as exc:
            out.append(exc)
    return out


def read_record(
    listing: Listing,
    index: int,
    channels: tuple[str, ...] | None = None,
    sample_rate: float | None = None,
) -> Record:
    """Record ``index`` of ``listing`` (:func:`read_records`); InputError naming the file
    when it cannot be read."""
    (record,) = read_records(listing, [index], channels, sample_rate)
    if isinstance(record, InputError):
        raise record
    return record


def _longest_increasing(t: np.ndarray) -> np.ndarray:
    """Indices of a longest strictly increasing subsequence of ``t`` (patience sorting).

    >>> _longest_increasing(np.array([1.0, 2.0, 9.0, 3.0, 4.0])).tolist()
    [0, 1, 3, 4]
    """
    tails: list[float] = []
    tail_index: list[int] = []
    previous = np.full(t.size, -1)
    for i, v in enumerate(t):
        k = int(np.searchsorted(tails, v, side="left"))
        if k == len(tails):
            tails.append(v)
            tail_index.append(i)
        else:
            tails[k] = v
            tail_index[k] = i
        previous[i] = tail_index[k - 1] if k > 0 else -1
    out = []
    i = tail_index[-1] if tail_index else -1
    while i >= 0:
        out.append(i)
        i = previous[i]
    return np.array(out[::-1], dtype=int)


def snapshot_times(numbers, clock) -> tuple[np.ndarray, np.ndarray]:
    """(times [s], indices of clocks out of order) of snapshots recorded in the order of
    their ``numbers``, from their ``clock`` (time of day [s]).

    A day is added where the clock falls back by more than half a day (midnight). A clock
    that breaks the order the numbers give (one off the longest increasing run of clocks)
    cannot be the time of its snapshot: it is replaced by the time its number puts it at,
    interpolated between its neighbours on the run.

    >>> t, bad = snapshot_times([1, 2, 3, 4], [86390.0, 86395.0, 5.0, 10.0])
    >>> t.tolist(), bad.tolist()
    ([86390.0, 86395.0, 86405.0, 86410.0], [])
    >>> t, bad = snapshot_times([1, 11, 21, 31], [100.0, 200.0, 50.0, 400.0])
    >>> t.tolist(), bad.tolist()
    ([100.0, 200.0, 300.0, 400.0], [2])
    """
    n = np.asarray(numbers, dtype=float)
    t = np.asarray(clock, dtype=float).copy()
    t[1:] += DAY * np.cumsum(np.diff(t) < -DAY / 2)
    keep = _longest_increasing(t)
    bad = np.setdiff1d(np.arange(t.size), keep)
    if bad.size:
        t[bad] = np.interp(n[bad], n[keep], t[keep])
    return t, bad


def snapshot_number(file: str) -> int:
    """The snapshot number of a PRONOSTIA file name (acc_00042.csv -> 42)."""
    return int(PRONOSTIA_FILE.match(file)[1])


def time_of_day(seconds: float) -> str:
    """Seconds of the day as hh:mm:ss.ffffff.

    >>> time_of_day(34779.065664)
    '09:39:39.065664'
    """
    s = seconds % DAY
    h, rest = divmod(s, 3600.0)
    m, sec = divmod(rest, 60.0)
    return f"{int(h):02d}:{int(m):02d}:{sec:09.6f}"
