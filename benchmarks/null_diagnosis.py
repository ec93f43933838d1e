"""False alarms of the diagnosis on records without the fault looked for, by method set.

Three null tests (docs/capabilities/diagnosis.md, "Robustness" and "A fourth method"):

1. the healthy CWRU record 97 (48 kHz) cut into four 2.5 s segments, each analysed at the
   logged speed and at 1 and 2 % either side, on its drive-end and fan-end channels
   (40 records);
2. the fan-end channel of every CWRU file that has one, read for the fan-end bearing, a
   6203-2RS that is healthy in every record (the faults were seeded at the drive end);
3. white noise at 12 kHz for a 6205 at 1797 rpm, ``--seeds`` records whose length cycles
   through 1, 2, 3, 4 and 5 s.

Each record's verdict is a false alarm unless it is "no fault detected". Run from the
repository root:

    python benchmarks/null_diagnosis.py ../shared/data/real [--methods cpw,ies,cpw+ies]
        [--seeds 200]

``--methods``: method sets, comma-separated, a set joining methods with "+"; default
cpw,ies. Prints the false alarms per test and set, with the one-sided 95 % upper bound of
the white-noise rate (Clopper-Pearson), and each real record that was called faulty.
"""

from __future__ import annotations

import csv
import math
import sys
import time
from pathlib import Path

import numpy as np

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import NO_FAULT, analyze_signal
from bearinglab.diagnosis.benchmark import _bearing
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal import read_signal

FS = 12000.0
RPM = 1797.0
SPEEDS = (0.98, 0.99, 1.0, 1.01, 1.02)


def _upper(k: int, n: int, level: float = 0.95) -> float:
    """One-sided Clopper-Pearson upper bound of a rate from k events in n trials."""
    import scipy.special

    return 1.0 if k >= n else float(scipy.special.betaincinv(k + 1, n - k, level))


def _rows(folder: Path) -> list[dict]:
    with open(folder / "labels.csv", newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _channel(folder: Path, row: dict, channel: str):
    try:
        fs = float(row["sample_rate_hz"]) if row.get("sample_rate_hz") else None
        s = read_signal(folder / row["file"], sample_rate=fs, channel=channel)
    except InputError as exc:
        if exc.parameter == "channel":
            return None
        raise
    return s.channel(s.names[0]), s.sample_rate


def healthy_segments(folder: Path, sets) -> dict:
    """Set -> list of (channel, segment, speed factor, verdict) called faulty, and the
    count of records."""
    row = next(r for r in _rows(folder) if r["fault"] == "normal")
    out = {m: [] for m in sets}
    total = 0
    for channel in ("DE", "FE"):
        x, fs = _channel(folder, row, channel)
        quarter = x.size // 4
        for q in range(4):
            part = x[q * quarter : (q + 1) * quarter]
            for factor in SPEEDS:
                kin = defect_frequencies(
                    _bearing(row), factor * float(row["speed_rpm"]) * math.pi / 30
                )
                total += 1
                for m in sets:
                    v = analyze_signal(part, fs, kin, methods=tuple(m.split("+"))).verdict
                    if v != NO_FAULT:
                        out[m].append((channel, q, factor, v))
    return out, total


def fan_end(folder: Path, sets) -> dict:
    """Set -> list of (file, verdict) called faulty for the fan-end 6203, and the count."""
    bearing = bearing_from_designation("6203-2RS")[0]
    out = {m: [] for m in sets}
    total = 0
    for row in _rows(folder):
        if row["dataset"] != "CWRU":
            continue
        got = _channel(folder, row, "FE")
        if got is None:
            continue
        x, fs = got
        kin = defect_frequencies(bearing, float(row["speed_rpm"]) * math.pi / 30)
        total += 1
        for m in sets:
            v = analyze_signal(x, fs, kin, methods=tuple(m.split("+"))).verdict
            if v != NO_FAULT:
                out[m].append((row["file"], v))
    return out, total


def white_noise(seeds: int, sets) -> dict:
    """Set -> list of (seed, seconds, verdict) called faulty."""
    bearing = bearing_from_designation("6205")[0]
    kin = defect_frequencies(bearing, RPM * math.pi / 30)
    out = {m: [] for m in sets}
    for seed in range(seeds):
        seconds = 1 + seed % 5
        x = np.random.default_rng(seed).standard_normal(int(seconds * FS))
        for m in sets:
            v = analyze_signal(x, FS, kin, methods=tuple(m.split("+"))).verdict
            if v != NO_FAULT:
                out[m].append((seed, seconds, v))
    return out


def main(folder: Path, sets, seeds: int) -> None:
    start = time.perf_counter()
    healthy, n_healthy = healthy_segments(folder, sets)
    fan, n_fan = fan_end(folder, sets)
    noise = white_noise(seeds, sets)
    print(f"{'method':14s} {'97 segments':>12s} {'FE 6203':>10s} {'white noise':>14s}")
    for m in sets:
        k = len(noise[m])
        print(
            f"{m:14s} {len(healthy[m]):4d} of {n_healthy:3d} {len(fan[m]):3d} of {n_fan:3d} "
            f"{k:4d} of {seeds} ({100 * k / seeds:.2f} %, 95 % bound "
            f"{100 * _upper(k, seeds):.2f} %)"
        )
    for m in sets:
        for item in healthy[m] + fan[m] + noise[m]:
            print(f"  {m}: {item}")
    print(f"{time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    args = sys.argv[1:]
    options = {"--methods": "cpw,ies", "--seeds": "200"}
    for key in options:
        if key in args:
            i = args.index(key)
            options[key] = args[i + 1]
            del args[i : i + 2]
    main(
        Path(args[0] if args else "../shared/data/real"),
        tuple(m for m in options["--methods"].split(",") if m),
        int(options["--seeds"]),
    )
