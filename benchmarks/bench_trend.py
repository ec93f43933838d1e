"""Wall time of ``bearinglab trend`` (issue 23), as whole processes, in one run.

Series timed: the development run Bearing1_1 as shared (282 snapshots of 2560 samples,
every 10th of the published 2803), and a 2800-snapshot series in PRONOSTIA's published
layout, a full run's length: Bearing1_1's snapshots, each written about ten times onto a
10 s clock, in a temporary folder (``--folder`` keeps it between calls). Each command
runs ``--runs`` times after one warm-up; the median is quoted, with the median of
``python -c "import numpy"`` from the same loop for scale. Then, in this process, the share
of the trend's time that its remaining-life estimate takes (issue 29: at most 10 %).

    .venv/bin/python benchmarks/bench_trend.py [--runs 3] [--folder /tmp/run2800]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np
from bench_cli import _time  # a command's wall time as a new process

ROOT = Path(__file__).resolve().parents[1]
RUN = ROOT.parent / "shared" / "data" / "run-to-failure" / "Bearing1_1"
BIN = [sys.executable, "-m", "bearinglab.cli"]
BASELINE = [sys.executable, "-c", "import numpy"]
GEOMETRY = ["--balls", "13", "--ball-diameter-mm", "3.5", "--pitch-diameter-mm", "25.6"]
FS = 25600.0


def long_series(folder: Path, count: int = 2800) -> Path:
    """``count`` PRONOSTIA snapshots in ``folder``: the development run's, in order, each
    used count / 282 times, with clocks 10 s apart (written once)."""
    import pandas as pd

    folder.mkdir(parents=True, exist_ok=True)
    if len(list(folder.glob("acc_*.csv"))) == count:
        return folder
    sources = sorted(RUN.glob("acc_*.csv"))
    start = 9 * 3600 + 39 * 60 + 39.0
    for i in range(count):
        x = pd.read_csv(sources[i * len(sources) // count], header=None).to_numpy()[:, 4:6]
        t = start + 10.0 * i + np.arange(len(x)) / FS
        hour, rest = np.divmod(t, 3600.0)
        minute, rest = np.divmod(rest, 60.0)
        second, micro = np.divmod(rest, 1.0)
        table = np.column_stack([hour, minute, second, np.round(micro * 1e6), x])
        np.savetxt(folder / f"acc_{i + 1:05d}.csv", table, fmt="%d,%d,%d,%d,%.3f,%.3f")
    return folder


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--folder", type=Path, default=None)
    args = parser.parse_args()
    if not RUN.is_dir():
        raise SystemExit(f"{RUN} is not here")
    with tempfile.TemporaryDirectory() as tmp:
        big = long_series(args.folder or Path(tmp) / "run2800")
        cases = {
            "Bearing1_1 (282)": [*BIN, "trend", str(RUN), "--json"],
            "Bearing1_1 (282), diagnosis": [
                *BIN,
                "trend",
                str(RUN),
                *GEOMETRY,
                "--speed-rpm",
                "1800",
                "--json",
            ],
            "2800 snapshots": [*BIN, "trend", str(big), "--json"],
            "2800 snapshots, --jobs 2": [*BIN, "trend", str(big), "--jobs", "2", "--json"],
            "2800 snapshots, diagnosis": [
                *BIN,
                "trend",
                str(big),
                *GEOMETRY,
                "--speed-rpm",
                "1800",
                "--json",
            ],
        }
        base = []
        print(f"{'command':40s} {'median [s]':>10s}  runs [s]")
        for name, argv in cases.items():
            _time(argv)  # warm-up
            times = []
            for _ in range(args.runs):
                times.append(_time(argv))
                base.append(_time(BASELINE))
            runs = " ".join(f"{t:.2f}" for t in times)
            print(f"{name:40s} {statistics.median(times):10.2f}  {runs}")
        numpy = 'python -c "import numpy"'
        print(f"{numpy:40s} {statistics.median(base):10.2f}")
        life_share({"Bearing1_1 (282)": RUN, "2800 snapshots": big}, args.runs)


def life_share(series: dict, runs: int) -> None:
    """In this process: the trend's time without its remaining-life estimate, the
    estimate's, and their ratio (medians)."""
    import time

    from bearinglab.trend import trend_records
    from bearinglab.trend.life import remaining_life

    print(f"\n{'in process':40s} {'trend [s]':>10s} {'life [s]':>9s} {'share':>6s}")
    for name, folder in series.items():
        trend_records(folder)  # warm-up
        spent, life = [], []
        for _ in range(runs):
            tic = time.perf_counter()
            result = trend_records(folder)
            spent.append(time.perf_counter() - tic)
            tic = time.perf_counter()
            remaining_life(result)
            life.append(time.perf_counter() - tic)
        t, lf = statistics.median(spent), statistics.median(life)
        print(f"{name:40s} {t - lf:10.3f} {lf:9.3f} {lf / (t - lf):6.1%}")


if __name__ == "__main__":
    main()
