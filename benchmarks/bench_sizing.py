"""The width of a race defect (issue 29), measured: on the shared recordings and variants
of them, against seed 003's rigid model with defects of known width, and the time it adds
to ``analyze``. Run from the repository root (docs/capabilities/defect_size.md has the
figures):

    python benchmarks/bench_sizing.py data        # ../shared/data/defect-size and real
    python benchmarks/bench_sizing.py variants    # halves, lower sample rates, FE/BA channels
    python benchmarks/bench_sizing.py simulate    # the rigid model's sweep
    python benchmarks/bench_sizing.py speed [--runs 7]

``data``: every record through the benchmark's path (the default method, then the width
of the race fault found, the load assumed) - the status, width, interval and error against
``defect_width_mm``. ``variants``: the seeded defects cut in halves and decimated to
25.6 and 12.8 kHz, and the CWRU files' fan-end and base channels diagnosed by each of
raw, cpw and drs-sk (held out: none was looked at to choose the method). ``simulate``:
6205, outer and inner race, 0.3-4 mm, 200/500/1000 N, 600 and 1800 rpm, 2 s at 51.2 kHz
with 0.01 m/s^2 of noise, preloaded by 10 um (every ball in contact but the one on the
defect) and with the catalogue clearance (12.5 um); the load given to the sizing.
``speed``: ``analyze --json`` of CWRU 130 (10 s at 12 kHz) as a new process, median of
``--runs`` after a warm-up, and in one process the diagnosis and the sizing apart.
"""

from __future__ import annotations

import argparse
import csv
import math
import statistics
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data"


def _row_sizes(folder: Path, row: dict, methods=("cpw",)) -> dict:
    from bearinglab.diagnosis.benchmark import run_record

    return run_record(str(folder), row, methods, keep_spectra=False)


def data() -> None:
    from bearinglab.diagnosis.benchmark import read_labels

    for name in ("defect-size", "real"):
        folder = SHARED / name
        if not (folder / "labels.csv").is_file():
            print(f"{folder}: absent")
            continue
        print(f"\n{folder}")
        errors = []
        for row in read_labels(folder):
            out = _row_sizes(folder, row)
            for size in out["defect_sizes"] or [None]:
                label = out["defect_width_mm"]
                text = "-" if size is None else size["status"]
                if size and size["width_mm"] is not None:
                    text += f" {size['width_mm']:.2f} [{size['low_mm']:.2f}, {size['high_mm']:.2f}]"
                    if label:
                        errors.append(100 * (size["width_mm"] / label - 1))
                        text += f" {errors[-1]:+.0f} %"
                cells = f"{row['file']:34s} {row['fault']:7s} {label or '':6}"
                print(f"  {cells} {out['verdict']:18s} {text}")
        if errors:
            print(f"  sized {len(errors)}, error {min(errors):+.1f} .. {max(errors):+.1f} %")


def _variant_status(x, fs, bearing, rpm) -> str:
    from bearinglab.diagnosis import analyze_signal
    from bearinglab.kinematics import defect_frequencies

    d = analyze_signal(x, fs, defect_frequencies(bearing, rpm * math.pi / 30))
    if d.defect_size is None:
        return d.verdict
    s = d.defect_size
    return s.status if not s.sized else f"{s.width * 1e3:.2f}"


def variants() -> None:
    from scipy.signal import decimate

    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis import analyze_signal
    from bearinglab.kinematics import defect_frequencies
    from bearinglab.signal import read_signal

    bearing = bearing_from_designation("6205")[0]
    folder = SHARED / "defect-size"
    print("seeded defects: whole | halves | 25.6 kHz | 12.8 kHz")
    for row in csv.DictReader(open(folder / "labels.csv")):
        if row["fault"] == "normal":
            continue
        x = read_signal(folder / row["file"], sample_rate=51200).channel(row["channel"])
        rpm = float(row["speed_rpm"])
        n = x.size // 2
        cells = [
            _variant_status(x, 51200.0, bearing, rpm),
            _variant_status(x[:n], 51200.0, bearing, rpm),
            _variant_status(x[n:], 51200.0, bearing, rpm),
            _variant_status(decimate(x, 2, ftype="fir"), 25600.0, bearing, rpm),
            _variant_status(decimate(x, 4, ftype="fir"), 12800.0, bearing, rpm),
        ]
        print(f"  {row['file']:18s} {row['defect_width_mm']:>6s} mm  " + " | ".join(cells))
    print("\nCWRU held-out channels (raw, cpw, drs-sk): race faults sized / sizings")
    real = SHARED / "real"
    counts: dict[str, int] = {}
    for row in csv.DictReader(open(real / "labels.csv")):
        if row["dataset"] != "CWRU":
            continue
        for channel in ("FE", "BA"):
            try:
                s = read_signal(
                    real / row["file"],
                    channel=channel,
                    record=row["record_variable"] or None,
                    sample_rate=float(row["sample_rate_hz"]),
                )
            except Exception:  # noqa: BLE001 - 3001/3005 have neither channel, 97 no BA
                continue
            kin = defect_frequencies(bearing, float(row["speed_rpm"]) * math.pi / 30)
            for method in ("raw", "cpw", "drs-sk"):
                for size in analyze_signal(s, None, kin, methods=method).defect_sizes:
                    counts[size.status] = counts.get(size.status, 0) + 1
                    if size.sized:
                        print(f"  SIZED {row['file']} {channel} {method}: {size.reason}")
    print(f"  {counts}")


def simulate(speeds=(600.0, 1800.0)) -> None:
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis import size_defect
    from bearinglab.diagnosis.spall import bridged_width
    from bearinglab.dynamics import Defect
    from bearinglab.dynamics import simulate as run
    from bearinglab.operating import OperatingCondition

    catalogue = bearing_from_designation("6205")[0]
    fs = 51200.0
    for clearance in (-10e-6, catalogue.diametral_clearance):
        b = replace(catalogue, diametral_clearance=clearance)
        for rpm in speeds:
            print(f"\nclearance {clearance * 1e6:+.1f} um, {rpm:g} rpm: width [mm] -> result")
            for location in ("outer", "inner"):
                for load in (200.0, 500.0, 1000.0):
                    limit = bridged_width(b, location, load) * 1e3
                    cells = []
                    for w in (0.3, 0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 4.0):
                        c = OperatingCondition(radial_load=load, shaft_speed=rpm * math.pi / 30)
                        sim = run(
                            b,
                            c,
                            [Defect(location, width=w * 1e-3)],
                            duration=2.0,
                            sample_rate=fs,
                            noise=0.01,
                            seed=1,
                        )
                        f = sim.kinematic.hz("bpfo" if location == "outer" else "bpfi")
                        s = size_defect(
                            sim.signal.channel("acc_y"),
                            fs,
                            b,
                            f"{location}_race",
                            f,
                            radial_load=load,
                        )
                        if s.sized:
                            cells.append(f"{w:g}: {100 * (s.width * 1e3 / w - 1):+.0f}%")
                        else:
                            cells.append(f"{w:g}: {'small' if s.status[0] == 't' else 'not'}")
                    print(
                        f"  {location} {load:5.0f} N (bridged {limit:.2f} mm): " + ", ".join(cells)
                    )


def speed(runs: int) -> None:
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis import analyze_signal
    from bearinglab.kinematics import defect_frequencies
    from bearinglab.signal import read_signal

    path = SHARED / "real" / "cwru" / "12k_DE" / "130.mat"
    argv = [
        sys.executable,
        "-m",
        "bearinglab.cli",
        "analyze",
        str(path),
        "--channel",
        "DE",
        "--sample-rate-hz",
        "12000",
        "--designation",
        "6205-2RS",
        "--speed-rpm",
        "1797",
        "--json",
    ]
    walls = []
    for i in range(runs + 1):
        t = time.perf_counter()
        subprocess.run(argv, check=True, capture_output=True)
        if i:
            walls.append(time.perf_counter() - t)
    print(
        "analyze --json (with the sizing), 10 s at 12 kHz: median "
        f"{statistics.median(walls):.3f} s ({min(walls):.3f}-{max(walls):.3f}) over {runs} runs"
    )
    signal = read_signal(path, channel="DE", sample_rate=12000)
    kin = defect_frequencies(bearing_from_designation("6205-2RS")[0], 1797 * math.pi / 30)
    diag, size = [], []
    for _ in range(runs):
        t = time.perf_counter()
        d = analyze_signal(signal, None, kin)
        t1 = time.perf_counter()
        assert d.defect_sizes is not None  # the sizing, read on first access
        diag.append(t1 - t)
        size.append(time.perf_counter() - t1)
    print(
        f"in one process: diagnosis {statistics.median(diag):.3f} s, sizing "
        f"{statistics.median(size):.3f} s (medians of {runs})"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("what", choices=("data", "variants", "simulate", "speed"))
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    np.seterr(all="ignore")
    {"data": data, "variants": variants, "simulate": simulate}.get(
        args.what, lambda: speed(args.runs)
    )()


if __name__ == "__main__":
    main()
