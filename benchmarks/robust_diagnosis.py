"""How much a verdict rests on one stretch of a record, or on the speed given.

Each labelled record of a folder (``labels.csv`` as ``bearinglab benchmark`` reads it) is
diagnosed five times by each method: whole, each half alone, and whole with the speed
given 1 % low and 1 % high (a tachometer's error). A verdict is right (the labelled fault;
"no fault detected" for a healthy record), wrong (another fault, or any fault on a healthy
record) or a miss ("no fault detected" on a faulty record). Run from the repository root:

    python benchmarks/robust_diagnosis.py ../shared/data/real [more folders...]
        [--methods raw,cpw,drs-sk,ies,cpw+ies]

``--methods``: the method sets, comma-separated; a set joins methods with "+" (diagnosed
together, as ``analyze --method cpw,ies`` does); default METHODS.

The fan-end and base channels of the CWRU files make two more folders: a copy of
labels.csv with ``channel`` set to FE or BA beside links to the recordings
(docs/capabilities/diagnosis.md, "Held-out check").
"""

from __future__ import annotations

import csv
import math
import sys
from collections import Counter
from pathlib import Path

from bearinglab.diagnosis import NO_FAULT, analyze_signal
from bearinglab.diagnosis.benchmark import EXPECTED, _bearing, label_fault
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal import read_signal

METHODS = ("raw", "cpw", "drs-sk", "ies")
#: variant -> (part of the record, factor on the speed given)
VARIANTS = {
    "whole": (slice(None), 1.0),
    "first half": ("first", 1.0),
    "second half": ("second", 1.0),
    "speed -1 %": (slice(None), 0.99),
    "speed +1 %": (slice(None), 1.01),
}


def verdicts(folder: Path, row: dict, methods=METHODS) -> list[tuple]:
    """(variant, method set, verdict) of one labelled record; [] when its channel is
    absent."""
    fs = float(row["sample_rate_hz"]) if row.get("sample_rate_hz") else None
    try:
        signal = read_signal(
            folder / row["file"], sample_rate=fs, channel=row.get("channel") or None
        )
    except InputError as exc:
        if exc.parameter == "channel":
            return []
        raise
    x, fs = signal.channel(signal.names[0]), signal.sample_rate
    rpm = float(row["speed_rpm"]) if row.get("speed_rpm") else signal.metadata["speed_rpm"]
    out = []
    for variant, (part, factor) in VARIANTS.items():
        half = x.size // 2
        y = x[:half] if part == "first" else x[half:] if part == "second" else x[part]
        kin = defect_frequencies(_bearing(row), factor * rpm * math.pi / 30)
        for method in methods:
            names = tuple(method.split("+"))
            out.append((variant, method, analyze_signal(y, fs, kin, methods=names).verdict))
    return out


def main(folders: list[str], methods=METHODS) -> None:
    counts: Counter = Counter()
    wrong = []
    for folder in map(Path, folders):
        with open(folder / "labels.csv", newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        for row in rows:
            expected = EXPECTED[label_fault(row["fault"])]
            for variant, method, verdict in verdicts(folder, row, methods):
                kind = (
                    "right" if verdict == expected else "miss" if verdict == NO_FAULT else "wrong"
                )
                counts[method, kind] += 1
                if kind == "wrong":
                    wrong.append(
                        f"{folder.name}/{row['file']} {row.get('channel', '')} "
                        f"({row['fault']}), {variant}, {method}: {verdict}"
                    )
    print(f"{'method':14s} {'right':>6s} {'wrong':>6s} {'miss':>6s}")
    for method in methods:
        print(
            f"{method:14s} "
            + " ".join(f"{counts[method, k]:6d}" for k in ("right", "wrong", "miss"))
        )
    print("wrong faults:")
    print("\n".join(f"  {w}" for w in wrong) or "  none")


if __name__ == "__main__":
    args = sys.argv[1:]
    chosen = METHODS
    if "--methods" in args:
        i = args.index("--methods")
        chosen = tuple(m for m in args[i + 1].split(",") if m)
        del args[i : i + 2]
    main(args or ["../shared/data/real"], chosen)
