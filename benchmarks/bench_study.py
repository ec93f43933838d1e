"""Scaling of studies and data sets on dask.distributed (issue 13): the same work on a
LocalCluster of 1 and of 2 worker processes, in one run.

1. A 100 000-case stiffness study: 6205, 100 radial loads (50-5000 N) x 25 axial loads
   (0-2000 N) x 40 speeds (0-10 000 rpm), ``run_study("stiffness", ...)``.
2. A 1 000-record data set: 6205-2RS, 1 s at 20 kHz each, rigid model, faults none /
   outer / inner / ball, ``make_dataset(...)``.

Timed: the partitions only (``StudyResult.seconds``, ``DatasetResult.seconds``: from the
first task submitted to the last partition written); starting the cluster and the
warm-up that loads the compiled kernels on each worker are reported apart. Each worker is
one process with one thread (numba, OpenMP and BLAS one thread each, set before the
cluster starts). The speed-up is t(1 worker) / t(2 workers) (goal >= 1.8); peak memory
is each worker process's peak resident set (``ru_maxrss``); the CPU time the workers
spent on the partitions, per item, and each worker's CPU time over the wall time (the
share of a core it got: below 1 when other work competes for the cores) tell a slow run on
a busy machine from overhead of the distribution. The machine's load average is printed
before and after each run.

Run: nice -n 10 .venv/bin/python benchmarks/bench_study.py [--quick] [--json FILE]
(--quick: 10 000 cases and 100 records).
"""

import os

for _var in ("NUMBA_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402 - after the thread settings
import json  # noqa: E402 - after the thread settings
import shutil  # noqa: E402 - after the thread settings
import tempfile  # noqa: E402 - after the thread settings
import time  # noqa: E402 - after the thread settings
from pathlib import Path  # noqa: E402

from bearinglab.dataset import make_dataset  # noqa: E402
from bearinglab.study import run_study  # noqa: E402


def _grid(quick: bool) -> dict:
    return {
        "designation": "6205",
        "radial_load_n": "50:5000:100",
        "axial_load_n": "0:2000:" + ("5" if quick else "25"),
        "speed_rpm": "0:10000:" + ("20" if quick else "40"),
    }


def _load() -> str:
    return "/".join(f"{v:.2f}" for v in os.getloadavg())


def _own_cpu() -> float:
    """CPU time of this process [s]: the client and, for a LocalCluster, its scheduler."""
    import resource

    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def _row(kind, n, result, started, load_before, cpu_before) -> dict:
    memory = sorted(result.peak_memory.values())
    cpu = sorted(result.worker_cpu_seconds.values())
    items = result.computed_cases if kind == "study" else result.computed_records
    return {
        "benchmark": kind,
        "workers": n,
        "items": result.computed_cases if kind == "study" else result.computed_records,
        "seconds": round(result.seconds, 2),
        "per_second": round(
            (result.computed_cases if kind == "study" else result.computed_records)
            / result.seconds,
            1,
        ),
        "startup_and_warmup_s": round(time.perf_counter() - started - result.seconds, 1),
        "peak_memory_mb": [round(m / 2**20) for m in memory],
        "cpu_ms_per_item": round(1e3 * sum(cpu) / items, 2),
        "client_cpu_s": round(_own_cpu() - cpu_before, 1),
        # share of a core each worker got: < 1 when other work competed for the cores
        "core_share": [round(c / result.seconds, 2) for c in cpu],
        "failed": result.failed_cases if kind == "study" else result.failed,
        "load_before": load_before,
        "load_after": _load(),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="10 000 cases, 100 records")
    parser.add_argument("--json", type=Path, help="also write the rows to this file")
    args = parser.parse_args()
    records = 100 if args.quick else 1000
    rows = []
    work = Path(tempfile.mkdtemp(prefix="bench_study-"))
    try:
        for n in (1, 2):
            load, t0, c0 = _load(), time.perf_counter(), _own_cpu()
            r = run_study(
                "stiffness",
                _grid(args.quick),
                output=work / f"study-{n}",
                workers=n,
                scheduler="local",
            )
            rows.append(_row("study", n, r, t0, load, c0))
            print(rows[-1], flush=True)
        for n in (1, 2):
            load, t0, c0 = _load(), time.perf_counter(), _own_cpu()
            d = make_dataset(
                work / f"set{n}",
                records,
                workers=n,
                scheduler="local",
                duration_s=1.0,
                sample_rate_hz=20000.0,
                model="rigid",
                faults=["none", "outer", "inner", "ball"],
                max_records=None,
            )
            rows.append(_row("dataset", n, d, t0, load, c0))
            print(rows[-1], flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print()
    print(
        "| benchmark | workers | items | wall s | per s | speed-up | CPU ms per item | "
        "core share per worker | client CPU s | startup+warm-up s | peak MB per worker | "
        "load before -> after |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        one = next(r for r in rows if r["benchmark"] == row["benchmark"] and r["workers"] == 1)
        speedup = one["seconds"] / row["seconds"]
        print(
            f"| {row['benchmark']} | {row['workers']} | {row['items']} | {row['seconds']} | "
            f"{row['per_second']} | x{speedup:.2f} | {row['cpu_ms_per_item']} | "
            f"{', '.join(map(str, row['core_share']))} | {row['client_cpu_s']} | "
            f"{row['startup_and_warmup_s']} | "
            f"{', '.join(map(str, row['peak_memory_mb']))} | {row['load_before']} -> "
            f"{row['load_after']} |"
        )
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
