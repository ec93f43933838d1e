"""Reading a series of recordings (layer 3): the folder's records, read in chunks in this
process or on dask workers (:mod:`.tasks`), into their health indicators
(:mod:`.indicators`), checked (unreadable or impossible records skipped with a warning
naming them; duplicated times, a sample rate that contradicts the files), and put in time
order (:func:`read_series`). The trend (:mod:`.analysis`) and the learning from runs to
failure (:mod:`.learning`) both read their series here.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .indicators import INDICATORS
from .series import Listing, Record, read_record, snapshot_number, snapshot_times

#: Records read per task.
CHUNK = 64
#: Files named one by one in the warning about unreadable records.
NAMED = 10


@dataclass(frozen=True, eq=False)
class Series:
    """The records read, in time order: ``listing`` (their files and index times),
    ``channels``, ``sample_rate`` [Hz], ``record_samples``, ``start`` (the first record's
    clock [s]), ``times`` [s from the first record], ``values`` (indicator -> records x
    channels), ``velocity`` (records x channels [m/s], or None) and ``warnings``."""

    listing: Listing
    channels: tuple
    sample_rate: float
    record_samples: int
    start: float
    times: np.ndarray
    values: dict
    velocity: np.ndarray | None
    warnings: tuple

    @property
    def files(self) -> tuple:
        return self.listing.files


def read_series(listing: Listing, channels, sample_rate, unit, top, runner, told) -> Series:
    """The records of ``listing`` (channels ``channels``, checked by :func:`probe`) read
    on ``runner`` (:mod:`bearinglab.engine`) into their indicators over 0-``top`` Hz (and
    the velocity in ``unit``), in time order; ``told`` = (progress, total): the trend's
    ``progress(done, total)`` and its total work, called as records are read."""
    from ..engine import run_partitions
    from .tasks import read_chunk

    total = len(listing.files)
    warnings: list[str] = []
    if listing.unlisted:
        warnings.append(
            f"{len(listing.unlisted)} record file(s) of the folder are not in index.csv and "
            f"were left out (e.g. {listing.unlisted[0]})"
        )
    rows: list[dict] = []
    parts = [range(s, min(s + CHUNK, total)) for s in range(0, total, CHUNK)]
    tasks = [(listing.subset(p), channels, sample_rate, unit, p.start, top) for p in parts]
    progress, work = told
    run_partitions(
        runner,
        read_chunk,
        tasks,
        [len(p) for p in parts],
        lambda task, result: rows.extend(result),
        progress=progress,
        total=work,
    )
    good = _good_rows(listing, rows, warnings, listing.folder)
    warnings += _rate_warnings(listing, good, sample_rate)
    warnings += _quality(good)
    clock = _clock(listing, good, warnings)
    order = np.lexsort((np.array([r["file"] for r in good]), clock))
    good = [good[i] for i in order]
    clock = clock[order]
    _distinct_times(good, clock)
    values = {name: np.array([r["values"][name] for r in good], dtype=float) for name in INDICATORS}
    velocity = None if unit is None else np.array([r["velocity"] for r in good], dtype=float)
    files = Listing(
        listing.folder,
        listing.layout,
        tuple(r["file"] for r in good),
        None if listing.times is None else tuple(r["time"] for r in good),
    )
    return Series(
        files,
        tuple(channels),
        float(good[0]["sample_rate"]),
        int(good[0]["samples"]),
        float(clock[0]),
        clock - clock[0],
        values,
        velocity,
        tuple(warnings),
    )


def _quality(good: list[dict]) -> list[str]:
    """The records' channel-quality warnings (clipped, coarse), one line per kind with how
    many records gave it and its first wording."""
    kinds: dict[str, list] = {}
    for r in good:
        for w in r.get("notes", ()):
            kinds.setdefault(re.sub(r"[-+]?\d[\d.e+-]*", "#", w), [w, 0, r["file"]])[1] += 1
    return [f"{n} record(s), e.g. {f}: {w}" for w, n, f in kinds.values()]


def probe(listing: Listing, channels, sample_rate) -> tuple[tuple[str, ...], Record]:
    """The channels to trend (the user's, checked against the first readable record, or
    all of its channels) and that record."""
    first_error = None
    for i in range(len(listing.files)):
        try:
            record = read_record(listing, i, None, sample_rate)
        except InputError as exc:
            if exc.parameter in ("sample_rate", "sample_rate_hz"):
                raise
            first_error = first_error or str(exc)
            continue
        if channels is None:
            return record.channels, record
        wanted = (channels,) if isinstance(channels, str) else tuple(channels)
        if not wanted or len(set(wanted)) != len(wanted):
            raise InputError("channels", list(wanted), "one or more distinct channel names")
        for c in wanted:
            if c not in record.channels:
                raise InputError("channels", c, f"channels of the records: {list(record.channels)}")
        return wanted, record
    raise InputError(
        "folder",
        listing.folder,
        "a folder with at least one readable recording",
        hint=f"none of its {len(listing.files)} records could be read: {first_error}",
    )


def _skipped(failures: list[dict]) -> list[str]:
    """The warning about the records skipped, naming them."""
    if not failures:
        return []
    named = "; ".join(f["error"] for f in failures[:NAMED])
    more = f" (and {len(failures) - NAMED} more)" if len(failures) > NAMED else ""
    return [f"{len(failures)} record(s) skipped: {named}{more}"]


def _distinct_times(good: list[dict], clock) -> None:
    """InputError naming two records that share a time: a trend needs each record at its
    own time (duplicated time stamps make the spacing 0 s and the persistence window
    meaningless)."""
    same = np.flatnonzero(np.diff(clock) == 0)
    if same.size:
        i = int(same[0])
        raise InputError(
            "folder",
            good[i + 1]["file"],
            "records at distinct times (one time per record)",
            hint=f"{same.size} record(s) share their time with the one before, e.g. "
            f"{good[i]['file']} and {good[i + 1]['file']} at {clock[i]:.6g} s: duplicated "
            "time stamps or a file copied",
        )


def _rate_warnings(listing: Listing, good: list[dict], sample_rate) -> list[str]:
    """The warning when a sample rate was given that differs from the one the files store
    (or, for PRONOSTIA, from the data set's 25.6 kHz), as ``analyze`` gives it."""
    from .series import PRONOSTIA_SAMPLE_RATE

    if sample_rate is None:
        return []
    given = float(sample_rate)
    if listing.layout == "pronostia":
        stored, what = PRONOSTIA_SAMPLE_RATE, "PRONOSTIA snapshots are sampled at"
    else:
        rates = [r["stored_sample_rate"] for r in good if r.get("stored_sample_rate")]
        if not rates:
            return []
        stored, what = rates[0], "the files store a sample rate of"
    if abs(stored - given) <= 1e-9 * given:
        return []
    return [
        f"{what} {stored:g} Hz and `sample_rate` = {given:g} Hz was given: every frequency "
        f"of the records reads {given / stored:.4g} times what the files say (the velocity "
        "and its ISO zone, the diagnosis' lines, the indicators' band)"
    ]


def _clock(listing: Listing, good: list[dict], warnings: list[str]) -> np.ndarray:
    """The records' times [s]: PRONOSTIA clocks in the order of the snapshot numbers (a
    clock out of that order replaced, with a warning naming the file), or the index's or
    files' own times (put in time order, with a note when the listing was not)."""
    clock = np.array([r["time"] for r in good])
    if listing.layout == "pronostia":
        numbers = [snapshot_number(r["file"]) for r in good]
        clock, bad = snapshot_times(numbers, clock)
        if bad.size:
            from .series import time_of_day

            named = ", ".join(
                f"{good[i]['file']} (its clock reads {time_of_day(good[i]['time'])})"
                for i in bad[:NAMED]
            )
            warnings.append(
                f"{bad.size} snapshot(s) with a clock out of the order of their numbers, timed "
                f"by their number between their neighbours instead: {named}"
            )
    elif np.any(np.diff(clock) < 0):
        warnings.append(
            "the records are not in time order in the folder listing: they were put in time order"
        )
    return clock


def _good_rows(listing: Listing, rows: list[dict], warnings: list[str], folder) -> list[dict]:
    """The records read (in listing order), after warning about those skipped; InputError
    when none was read or their sample rates differ."""
    failures = sorted((r for r in rows if "error" in r), key=lambda r: r["index"])
    good = sorted((r for r in rows if "error" not in r), key=lambda r: r["index"])
    warnings += _skipped(failures)
    if not good:
        raise InputError(
            "folder",
            str(folder),
            "a folder with at least one readable recording",
            hint=failures[0]["error"] if failures else "",
        )
    fs = good[0]["sample_rate"]
    for r in good:
        if not math.isclose(r["sample_rate"], fs, rel_tol=1e-9):
            raise InputError(
                "folder",
                r["file"],
                f"records of one sample rate ({fs:g} Hz, as {good[0]['file']})",
                hint=f"{r['file']} is at {r['sample_rate']:g} Hz",
            )
    return good
