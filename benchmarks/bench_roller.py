"""Speed of the roller-bearing load distribution against the ball bearing's (issue 28:
``static`` of a 14-roller bearing with 30 slices within 2x of the same for a 6205).

1. In one process, warm (kernels compiled and loaded): the median time of
   ``solve_load_distribution`` for a 6205 (9 balls) at 2000 N and for Harris's 209
   cylindrical roller bearing (14 rollers, 30 slices) at 4450 N, and for a 30205 tapered
   roller bearing (the rollers' equilibrium with the rib) at 2000 N radial, 1500 N axial.
2. In a new process each (what a ``static`` command pays besides the command line): the
   imports, the kernels loaded from numba's cache and one solve, median of five runs.

Run: .venv/bin/python benchmarks/bench_roller.py
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
import time

SETUP = {
    "6205 (9 balls)": (
        "from bearinglab.catalog import bearing_from_designation\n"
        "b, _ = bearing_from_designation('6205')\n"
        "c = OperatingCondition(radial_load=2000.0)\n"
    ),
    "209 cylindrical (14 rollers, 30 slices)": (
        "from bearinglab.catalog import bearing_from_designation\n"
        "b, _ = bearing_from_designation('209 cylindrical (Harris)', rollers=True)\n"
        "c = OperatingCondition(radial_load=4450.0)\n"
    ),
    "30205 tapered (12 rollers, 30 slices, rib)": (
        "from bearinglab.catalog import bearing_from_designation\n"
        "b, _ = bearing_from_designation('30205', rollers=True)\n"
        "c = OperatingCondition(radial_load=2000.0, axial_load=1500.0)\n"
    ),
}
HEAD = (
    "import time\n"
    "t0 = time.perf_counter()\n"
    "from bearinglab.operating import OperatingCondition\n"
    "from bearinglab.quasistatic import solve_load_distribution\n"
)


def warm(setup: str, repeats: int = 200) -> float:
    """Median seconds of one solve in this process, after a first (compiling) call."""
    space: dict = {}
    exec(HEAD + setup, space)  # noqa: S102 - the benchmark's own code
    solve, b, c = space["solve_load_distribution"], space["b"], space["c"]
    solve(b, c)
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        solve(b, c)
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def cold(setup: str, runs: int = 5) -> float:
    """Median seconds of imports + one solve in a new process (kernels from the cache)."""
    code = HEAD + setup + "solve_load_distribution(b, c)\nprint(time.perf_counter() - t0)\n"
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)  # cache
    out = []
    for _ in range(runs):
        done = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)
        out.append(float(done.stdout.decode().strip().splitlines()[-1]))
    return statistics.median(out)


def main() -> None:
    rows = {}
    for name, setup in SETUP.items():
        rows[name] = {"warm_ms": warm(setup) * 1e3, "new_process_s": cold(setup)}
    ball = rows["6205 (9 balls)"]
    for row in rows.values():
        row["warm_ratio_to_6205"] = row["warm_ms"] / ball["warm_ms"]
        row["new_process_ratio_to_6205"] = row["new_process_s"] / ball["new_process_s"]
    print(json.dumps(rows, indent=2))


if __name__ == "__main__":
    main()
