"""False alarms of the trend's rule, nominal against measured (issue 23).

Prints the figures of docs/capabilities/trend.md:

1. Healthy simulated series (:func:`bearinglab.trend.simulated.simulate_series`:
   PRONOSTIA's bearing at 1800 rpm and 4000 N, 0.5 % speed scatter, 1 m/s² measurement
   noise, a record every 10 s), the default baseline: how often each test's limit is
   exceeded by a single record, and how often the whole rule fires, against the levels
   the rule states.
2. The healthy stretches of the development runs (chosen from the plots before any rule
   was run: Bearing1_1 up to 10 000 s, a third of its life, its horizontal rms starting to
   rise near 12 000 s; Bearing3_1 up to 4 800 s, its failure starting at 4 900 s), with
   the baseline slid across the stretch to pool more records: the same figures, and those
   of the Gaussian limit mean + 6 sigma of the baseline for comparison.
3. The reference rule and ours on each development run: alarm time and lead, and how
   they move with the rule's settings (``--sensitivity``).

    .venv/bin/python benchmarks/trend_false_alarms.py [--series 5] [--records 600]
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import numpy as np

from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.trend import plain_rule, trend_records
from bearinglab.trend.alarm import FALSE_ALARM_PER_HOUR, STATISTICS, baseline_limits

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT.parent / "shared" / "data" / "run-to-failure"
BEARING = BallBearing(ball_count=13, ball_diameter=3.5e-3, pitch_diameter=25.6e-3)
#: The healthy stretch of each development run [s] (see the module docstring).
HEALTHY = {"Bearing1_1": 10000.0, "Bearing3_1": 4800.0}
#: Levels per test and record at which the exceedances are counted (1e-7: the default
#: 1e-6 per record over 10 tests).
LEVELS = (1e-1, 1e-2, 1e-3, 1e-6, 1e-7)


def statistics(result) -> np.ndarray:
    """records x tests: the test statistics of a trend."""
    return np.column_stack(
        [STATISTICS[name](result.values[name][:, c]) for name, c in result.tests]
    )


def counts(stats, base: slice, stop: int, level: float, r: int) -> tuple[int, int, int, int]:
    """(records above a limit, record-tests, windows where some test fires, windows) of
    the records base.stop..stop-1 against limits of ``level`` for runs of ``r``."""
    limits = baseline_limits(stats, base, level, r)
    above = np.column_stack(
        [stats[base.stop : stop, j] > lim.limit for j, lim in enumerate(limits)]
    )
    if above.shape[0] < r:
        return int(above.sum()), above.size, 0, 0
    kernel = np.ones(r, dtype=int)
    runs = np.column_stack(
        [
            np.convolve(above[:, j].astype(int), kernel, mode="valid") >= r
            for j in range(above.shape[1])
        ]
    )
    return int(above.sum()), above.size, int(runs.any(axis=1).sum()), runs.shape[0]


def gaussian(stats, base: slice, stop: int, sigmas: float = 6.0) -> tuple[int, int]:
    """(record-tests above mean + ``sigmas`` sd of the baseline, record-tests)."""
    b = stats[base]
    limit = b.mean(axis=0) + sigmas * b.std(axis=0, ddof=1)
    above = stats[base.stop : stop] > limit
    return int(above.sum()), above.size


def _report(title: str, tallies: dict, gauss=None) -> None:
    print(f"\n{title}")
    head = ("level per test", "r", "single record: measured", "rule: nominal", "rule: measured")
    print(f"{head[0]:>15s} {head[1]:>2s} {head[2]:>24s} {head[3]:>14s} {head[4]:>22s}")
    for (level, r), (a, n, f, w) in tallies.items():
        single = "" if r != 1 else f"{a / n:.2e} ({a}/{n})"
        rule = f"{f / max(w, 1):.2e} ({f}/{w})"
        print(f"{level:15.0e} {r:2d} {single:>24s} {level * 10:14.0e} {rule:>22s}")
    if gauss is not None:
        rate = gauss[0] / gauss[1]
        print(f"Gaussian mean + 6 sd of the baseline: {rate:.2e} ({gauss[0]}/{gauss[1]})")


def simulated(series: int, records: int) -> None:
    from bearinglab.trend.simulated import simulate_series

    condition = OperatingCondition.at_rpm(1800.0, radial_load=4000.0)
    tallies: dict = {}
    default_alarms = monitored = 0
    gauss = [0, 0]
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(series):
            folder = simulate_series(
                Path(tmp) / f"s{seed}", BEARING, condition, records=records, seed=seed
            )
            result = trend_records(folder)
            default_alarms += result.alarm is not None
            monitored += result.monitored_records
            stats = statistics(result)
            base = slice(result.settle_records, result.baseline_stop)
            for level in LEVELS:
                for r in (1, 2, 3):
                    got = counts(stats, base, len(result.files), level, r)
                    tallies[(level, r)] = tuple(
                        a + b for a, b in zip(tallies.get((level, r), (0,) * 4), got, strict=True)
                    )
            g = gaussian(stats, base, len(result.files))
            gauss = [gauss[0] + g[0], gauss[1] + g[1]]
    print(
        f"healthy simulated series: {series} x {records} records; default rule "
        f"({FALSE_ALARM_PER_HOUR:g} per hour): {default_alarms} alarms over {monitored} "
        "monitored records"
    )
    _report("healthy simulated series", tallies, gauss)


def real() -> None:
    for run, end in HEALTHY.items():
        folder = RUNS / run
        if not folder.is_dir():
            continue
        result = trend_records(folder)
        stats = statistics(result)
        stop = int(np.searchsorted(result.times, end, side="right"))
        n = result.baseline_records
        tallies: dict = {}
        gauss = [0, 0]
        for start in range(result.settle_records, stop - n - 10):
            base = slice(start, start + n)
            for level in LEVELS:
                for r in (1, 2, 3):
                    got = counts(stats, base, stop, level, r)
                    tallies[(level, r)] = tuple(
                        a + b for a, b in zip(tallies.get((level, r), (0,) * 4), got, strict=True)
                    )
            g = gaussian(stats, base, stop)
            gauss = [gauss[0] + g[0], gauss[1] + g[1]]
        _report(
            f"{run}: healthy stretch to {end:g} s, baselines of {n} records slid over it",
            tallies,
            gauss,
        )
        ref = plain_rule(result.values["rms"][:, 0])
        last = result.times[-1]
        a = result.alarm
        print(
            f"{run}: ours {result.times[a.record]:.0f} s ({a.indicator}, {a.channel}), lead "
            f"{last - result.times[a.record]:.0f} s; reference rule "
            + (
                "none"
                if ref is None
                else f"{result.times[ref]:.0f} s, lead {last - result.times[ref]:.0f} s"
            )
        )


#: Settings tried by --sensitivity, one change from the defaults at a time.
VARIANTS = {
    "defaults": {},
    "false_alarm_per_hour 3.6e-3": {"false_alarm_per_hour": 3.6e-3},
    "false_alarm_per_hour 3.6e-5": {"false_alarm_per_hour": 3.6e-5},
    "persistence 3 records": {"persistence_records": 3},
    "persistence 4 records": {"persistence_records": 4},
    "no settling": {"settle": 0.0},
    "settling 1800 s": {"settle": 1800.0},
    "baseline 60 records": {"baseline_records": 60},
}


def sensitivity() -> None:
    print("\nalarm time and lead before the last snapshot [s], one setting changed at a time")
    runs = sorted(p.name for p in RUNS.glob("Bearing*") if p.is_dir())
    for name, kwargs in VARIANTS.items():
        cells = []
        for run in runs:
            r = trend_records(RUNS / run, **kwargs)
            a = r.alarm
            if a is None:
                cells.append(f"{run} -")
                continue
            t = r.times[a.record]
            half = "" if t >= r.times[-1] / 2 else " FIRST HALF"
            cells.append(f"{run} {t:.0f} ({r.times[-1] - t:.0f}, {a.indicator}{half})")
        print(f"{name:24s} " + "; ".join(cells))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--series", type=int, default=5)
    parser.add_argument("--records", type=int, default=600)
    parser.add_argument("--sensitivity", action="store_true", help="only the settings' table")
    args = parser.parse_args()
    if args.sensitivity:
        sensitivity()
        return
    real()
    simulated(args.series, args.records)


if __name__ == "__main__":
    main()
