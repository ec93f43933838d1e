"""The diagnosis of a series at and after its alarm, over blocks of consecutive records.

The diagnosis (:func:`bearinglab.diagnosis.analyze_signal`, its public function) refuses a
record shorter than three cage revolutions (``MIN_CAGE_REVOLUTIONS`` of
:mod:`bearinglab.diagnosis.analysis`): a 0.1 s PRONOSTIA snapshot of its bearing at 1800
rpm holds 1.3. A family's significance is therefore computed over a block of the fewest
consecutive records that hold three cage revolutions, joined end to end (each tapered at
its ends, :func:`.tasks.join_records`), and every record of a block carries the block's
result; at the alarm, the block is the records ending at
the alarm record. Snapshots taken seconds apart are independent segments: the joined
record's envelope spectrum is close to the average of the snapshots' spectra, each line
widened by a snapshot's 1/T, with small steps at the joins. Growing inner-race and ball
defects of simulated PRONOSTIA snapshots are named at the alarm
(``tests/property/test_trend_alarm.py``).
"""

from __future__ import annotations

import math
import re
from collections import Counter
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .series import Listing, Record


@dataclass(frozen=True, eq=False)
class BlockDiagnosis:
    """The diagnosis over blocks of ``block_records`` consecutive records of ``channel``
    joined end to end: per record, its block's ``verdicts`` and ``significance`` (family ->
    -log10 p; None where its block failed); the ``alarm`` block's outcome (the records
    ending at the alarm), the ``threshold`` significance, the blocks' ``warnings``, and the
    kinematic ``frequencies``."""

    channel: str
    block_records: int
    frequencies: object
    verdicts: tuple
    significance: tuple
    blocks: tuple
    block_verdicts: tuple
    alarm: dict | None
    threshold: float | None
    warnings: tuple = ()

    @classmethod
    def from_blocks(cls, channel, size, frequencies, blocks, outcome, alarm_outcome, count):
        verdicts: list = [None] * count
        significance: list = [None] * count
        for block, o in zip(blocks, outcome, strict=True):
            for i in block:
                verdicts[i] = o.get("verdict")
                significance[i] = o.get("significance")
        done = [o for o in outcome if "error" not in o]
        notes = _grouped([w for o in done for w in o["warnings"]], len(done))
        failed = [o["error"] for o in outcome if "error" in o]
        if failed:
            notes.append(
                f"{len(failed)} diagnosis block(s) failed: {failed[0][2]} ({failed[0][3]})"
            )
        return cls(
            channel,
            size,
            frequencies,
            tuple(verdicts),
            tuple(significance),
            tuple(tuple(int(i) for i in b) for b in blocks),
            tuple(o.get("verdict") for o in outcome),
            alarm_outcome if alarm_outcome and "error" not in alarm_outcome else None,
            done[0]["threshold"] if done else None,
            tuple(notes),
        )

    def after(self, record: int) -> dict:
        """Verdict -> blocks that start at or after ``record``."""
        return dict(
            Counter(
                v
                for b, v in zip(self.blocks, self.block_verdicts, strict=True)
                if b[0] >= record and v is not None
            )
        )


def _grouped(warnings: list[str], blocks: int) -> list[str]:
    """The blocks' diagnosis warnings, one line per kind (the same words, other numbers),
    with how many blocks gave it and its first wording.

    >>> _grouped(["shaft at 1836 rpm", "shaft at 1840 rpm", "coarse"], 3)
    ['diagnosis, 2 of 3 blocks: shaft at 1836 rpm', 'diagnosis, 1 of 3 blocks: coarse']
    """
    kinds: dict[str, list] = {}
    for w in warnings:
        kinds.setdefault(re.sub(r"[-+]?\d[\d.]*", "#", w), [w, 0])[1] += 1
    return [f"diagnosis, {n} of {blocks} blocks: {w}" for w, n in kinds.values()]


def blocks_of(count: int, size: int) -> list[np.ndarray]:
    """Consecutive blocks of ``size`` of ``count`` records (the last one ends at the last
    record, so that every block holds ``size`` records).

    >>> [b.tolist() for b in blocks_of(7, 3)]
    [[0, 1, 2], [3, 4, 5], [4, 5, 6]]
    """
    starts = list(range(0, count - size + 1, size))
    if starts and starts[-1] + size < count:
        starts.append(count - size)
    return [np.arange(s, s + size) for s in starts]


def block_size(record: Record, frequencies) -> int:
    """Fewest consecutive records that hold the diagnosis' minimum of cage revolutions."""
    from ..diagnosis.analysis import MIN_CAGE_REVOLUTIONS

    duration = record.samples.shape[-1] / record.sample_rate
    return max(1, math.ceil(MIN_CAGE_REVOLUTIONS / (duration * frequencies.hz("ftf")) - 1e-9))


def diagnose_blocks(runner, files: Listing, channel, sample_rate, kin, size, alarm, told):
    """The diagnosis over blocks of ``size`` consecutive records of ``files`` (time order)
    and over the block ending at the alarm, on ``runner`` (:mod:`bearinglab.engine`); None
    when the series is shorter than a block. ``told`` = (progress, done, total): the
    progress of the trend and where it stands."""
    from ..engine import run_partitions
    from .tasks import diagnose_block

    count = len(files.files)
    if size > count:
        return None
    blocks = blocks_of(count, size)
    extra = []
    if alarm is not None and alarm.record >= size - 1:
        extra = [np.arange(alarm.record - size + 1, alarm.record + 1)]
    tasks = [(files.subset(b), channel, sample_rate, kin) for b in (*blocks, *extra)]
    outcome: dict[int, dict] = {}

    def collect(task, result):
        outcome[id(task)] = result

    progress, done, total = told
    units = [size] * len(tasks)
    run_partitions(
        runner, diagnose_block, tasks, units, collect, progress=progress, total=total, done=done
    )
    results = [outcome[id(t)] for t in tasks]
    if all("error" in r for r in results):
        raise InputError(*results[0]["error"])
    return BlockDiagnosis.from_blocks(
        channel,
        size,
        kin,
        blocks,
        results[: len(blocks)],
        results[len(blocks)] if extra else None,
        count,
    )
