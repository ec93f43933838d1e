"""Wall time of the commands a user types, against `python -c "import numpy"`, in one run.

Each command runs as a new process (start-up, imports, work, output), ``--runs`` times
after one warm-up run (which also fills numba's on-disk cache); the median is quoted and
divided by the median of the numpy import run in the same loop, command and baseline
alternating so that a change in the machine's speed affects both. Goals (issue 12):
``--help`` <= 2x, ``info 6205`` <= 3x, a warm rigid ``simulate`` of 1 s at 50 kHz
<= 1.5 s, ``analyze`` of a 10 s 12 kHz record <= 1 s.

    .venv/bin/python benchmarks/bench_cli.py [--runs 7]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent / "bearinglab"
REAL = ROOT.parent / "shared" / "data" / "real" / "cwru" / "12k_DE" / "130.mat"
BASELINE = [sys.executable, "-c", "import numpy"]


def _record(folder: Path) -> list[str]:
    """analyze's arguments: the CWRU 130 record (10 s at 12 kHz) when it is there, else a
    simulated 10 s record at 12 kHz written first."""
    if REAL.exists():
        return [
            "analyze",
            str(REAL),
            "--channel",
            "DE",
            "--sample-rate-hz",
            "12000",
            "--designation",
            "6205-2RS",
            "--speed-rpm",
            "1797",
        ]
    path = folder / "sim.npz"
    subprocess.run(
        [
            str(BIN),
            "simulate",
            "6205",
            "--speed-rpm",
            "1797",
            "--radial-load-n",
            "500",
            "--defect",
            "outer:width_mm=0.5",
            "--duration-s",
            "10",
            "--sample-rate-hz",
            "12000",
            "-o",
            str(path),
            "--json",
        ],
        check=True,
        capture_output=True,
    )
    return ["analyze", str(path), "--designation", "6205", "--speed-rpm", "1797"]


def _time(argv: list[str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(argv, capture_output=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed:\n{done.stderr.decode()}")
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        cases = {
            "--help": (["--help"], "ratio", 2.0),
            "info 6205": (["info", "6205"], "ratio", 3.0),
            "frequencies 6205": (["frequencies", "6205", "--speed-rpm", "1797"], "ratio", None),
            "contact 6205": (["contact", "6205", "--ball-load-n", "1000"], "ratio", None),
            "static 6205": (
                ["static", "6205", "--radial-load-n", "1000", "--speed-rpm", "3000"],
                "ratio",
                None,
            ),
            "simulate rigid 1 s, 50 kHz": (
                [
                    "simulate",
                    "ER-16K",
                    "--speed-rpm",
                    "1750",
                    "--radial-load-n",
                    "50",
                    "--defect",
                    "outer:width_mm=1.2,depth_mm=0.25",
                    "--duration-s",
                    "1",
                    "--sample-rate-hz",
                    "50000",
                ],
                "seconds",
                1.5,
            ),
            "analyze 10 s, 12 kHz": (_record(Path(tmp)), "seconds", 1.0),
        }
        base_all: list[float] = []
        print(f"{'command':<30} {'median s':>9} {'numpy s':>8} {'ratio':>6}   goal")
        for name, (argv, kind, goal) in cases.items():
            full = [str(BIN), *argv]
            _time(full)  # warm-up (and numba's cache)
            own, base = [], []
            for _ in range(args.runs):
                own.append(_time(full))
                base.append(_time(BASELINE))
            base_all += base
            t, b = statistics.median(own), statistics.median(base)
            if goal is None:
                verdict = ""
            elif kind == "ratio":
                verdict = f"<= {goal:g}x: {'met' if t / b <= goal else 'NOT met'}"
            else:
                verdict = f"<= {goal:g} s: {'met' if t <= goal else 'NOT met'}"
            print(f"{name:<30} {t:9.3f} {b:8.3f} {t / b:6.2f}   {verdict}")
    print(
        f"numpy import over all runs: median {statistics.median(base_all):.3f} s, "
        f"{len(base_all)} runs"
    )


if __name__ == "__main__":
    main()
