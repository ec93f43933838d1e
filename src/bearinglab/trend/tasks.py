"""The work a trend hands to its workers (top-level functions, so that dask can send
them to other processes): reading a chunk of records into their indicators, and the
diagnosis of a block of consecutive records."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .indicators import record_indicators, velocity_rms
from .series import read_records


def _failure(index: int, file: str, exc: InputError) -> dict:
    return {"index": index, "file": file, "error": str(exc), "parameter": exc.parameter}


def read_chunk(task: tuple) -> list[dict]:
    """Indicators of the records of ``task`` = (listing, channels, sample rate, unit,
    index of its first record in the whole series).

    One row per record: ``index`` (in the whole series), ``file``, and either ``error`` (why it
    was not read) or ``time`` [s], ``sample_rate`` [Hz], ``samples``, ``values``
    (indicator -> one value per channel) and ``velocity`` (per channel [m/s], or None
    without a unit). Records of one length and rate are computed together."""
    listing, channels, sample_rate, unit, start = task
    rows: list[dict] = []
    groups: dict[tuple, list] = {}
    records = read_records(listing, None, channels, sample_rate)
    for i, (file, record) in enumerate(zip(listing.files, records, strict=True), start=start):
        if not isinstance(record, InputError):
            flat = [
                c for c, x in zip(record.channels, record.samples, strict=True) if np.ptp(x) == 0
            ]
            if flat:
                hint = f"{flat[0]} is constant"
                record = InputError("path", file, "a record whose channels vary", hint=hint)
        if isinstance(record, InputError):
            rows.append(_failure(i, file, record))
            continue
        key = (record.sample_rate, record.samples.shape)
        groups.setdefault(key, []).append((i, record))
    for (fs, _), items in groups.items():
        x = np.stack([r.samples for _, r in items])
        values = record_indicators(x, fs)
        velocity = velocity_rms(x, fs, unit) if unit is not None else None
        for j, (i, r) in enumerate(items):
            rows.append(
                {
                    "index": i,
                    "file": r.file,
                    "time": r.time,
                    "sample_rate": fs,
                    "samples": r.samples.shape[-1],
                    "values": {name: v[j] for name, v in values.items()},
                    "velocity": None if velocity is None else velocity[j],
                }
            )
    return rows


def diagnose_block(task: tuple) -> dict:
    """The diagnosis of consecutive records joined end to end: ``task`` = (listing of the
    block's files, channel, sample rate, kinematic frequencies). Returns ``verdict``,
    ``significance`` (family -> -log10 p), ``threshold`` and ``warnings``, or ``error``
    (with the InputError's parameter, value and allowed range)."""
    from ..diagnosis import analyze_signal

    listing, channel, sample_rate, frequencies = task
    try:
        records = read_records(listing, None, (channel,), sample_rate)
        bad = next((r for r in records if isinstance(r, InputError)), None)
        if bad is not None:
            raise bad
        x = np.concatenate([r.samples[0] for r in records])
        d = analyze_signal(x, records[0].sample_rate, frequencies)
    except InputError as exc:
        return {"error": (exc.parameter, exc.value, exc.allowed, exc.hint)}
    return {
        "verdict": d.verdict,
        "significance": dict(d.scores),
        "threshold": d.threshold,
        "warnings": list(d.warnings),
    }
