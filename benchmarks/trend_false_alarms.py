"""False alarms and alarm times of the trend's rule, stated against measured (issue 27).

Prints the figures of docs/capabilities/trend.md:

1. **Calibration, leave one run out**: for each of the six PRONOSTIA learning runs, the
   excursion rates learned from the other five give the limit at a rate per test-hour;
   the excursions of the held-out run's healthy first half above it are counted, against
   the rate stated, at rates that can be counted (1 to 0.03 per test-hour).
2. **The rule on each run**: its alarm (time, share of the life, lead to the last
   snapshot, the test) with the limits learned from all six runs (the package's
   defaults) and from the other five (leave one run out), at several rates per hour,
   persistence windows, bands and baselines (``--sensitivity``).
3. **Healthy simulated series** (:func:`bearinglab.trend.simulated.simulate_series`:
   PRONOSTIA's bearing at 1800 rpm and 4000 N, 0.5 % speed scatter, 1 m/s² noise, a
   record every 10 s): the rule's firings per hour at the default rate and at a rate that
   can be counted (``--simulated N``).

    .venv/bin/python benchmarks/trend_false_alarms.py [--sensitivity] [--simulated 5]
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import numpy as np

from bearinglab.errors import InputError
from bearinglab.trend.alarm import FALSE_ALARM_PER_HOUR, crossing_runs, deviations
from bearinglab.trend.calibration import fit_calibration
from bearinglab.trend.learning import healthy_stretches, read_run
from bearinglab.trend.rule import statistics

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT.parent / "shared" / "data" / "run-to-failure"
NAMES = ("Bearing1_1", "Bearing1_2", "Bearing2_1", "Bearing2_2", "Bearing3_1", "Bearing3_2")


def read_all(**settings) -> dict:
    return {name: read_run(RUNS / name, **settings) for name in NAMES if (RUNS / name).is_dir()}


def calibration_check(runs: dict) -> None:
    print("\n1. calibration, leave one run out: excursions of held-out healthy halves")
    print(f"{'rate stated [1/test-h]':>24s} {'counted':>8s} {'expected':>9s} {'test-hours':>11s}")
    for target in (0.3, 0.1, 0.03, 0.01):
        counted = expected = hours = 0.0
        for name, run in runs.items():
            others = [s for k, o in runs.items() if k != name for s in healthy_stretches(o)]
            x = fit_calibration(others).limit(target)
            for z, h in healthy_stretches(run):
                counted += crossing_runs(np.nan_to_num(z, nan=-np.inf) > x).__len__()
                hours += h
        expected = target * hours
        print(f"{target:24g} {counted:8.0f} {expected:9.1f} {hours:11.1f}")


def alarm_of(run, excess: float):
    """(record, test) of the rule's alarm on ``run`` with the limit ``excess``, or None."""
    stats = statistics(run.values, run.tests)
    _, z = deviations(stats, slice(run.settle_records, run.baseline_stop), run.persistence)
    above = np.nan_to_num(z, nan=-np.inf) > excess
    hit = np.flatnonzero(above.any(axis=1))
    if not hit.size:
        return None
    i = int(hit[0])
    return i, run.tests[int(np.flatnonzero(above[i])[0])]


def cell(run, hit) -> str:
    if hit is None:
        return "none"
    i, (name, c) = hit
    t, life = run.times[i], run.times[-1]
    half = " FIRST HALF" if t < life / 2 else ""
    return f"{t:.0f} s ({t / life:.2f}, lead {life - t:.0f} s, {name} {run.channels[c]}){half}"


def alarms(runs: dict, rate: float, title: str) -> None:
    print(f"\n{title}")
    stretches = {k: healthy_stretches(r) for k, r in runs.items()}
    every = fit_calibration([s for v in stretches.values() for s in v])
    for name, run in runs.items():
        per_test = rate / len(run.tests)
        x_all = every.limit(per_test)
        try:
            loo = fit_calibration([s for k, v in stretches.items() if k != name for s in v])
        except InputError as exc:
            print(
                f"  {name}: all six x = {x_all:.1f}: {cell(run, alarm_of(run, x_all))}; "
                f"leave-one-out: {exc.value}"
            )
            continue
        x_loo = loo.limit(per_test)
        print(
            f"  {name}: all six x = {x_all:.1f}: {cell(run, alarm_of(run, x_all))}; "
            f"leave-one-out x = {x_loo:.1f}: {cell(run, alarm_of(run, x_loo))}"
        )


def sensitivity() -> None:
    variants = {
        "defaults": {},
        "persistence 300 s": {"persistence": 300.0},
        "persistence 600 s": {"persistence": 600.0},
        "band to 10 kHz (fs / 2.56)": {"max_frequency": 10000.0},
        "band to 12.8 kHz (all)": {"max_frequency": 12800.0},
        "baseline 12 records (600-1800 s)": {"baseline_n": 12, "baseline": None},
    }
    for title, settings in variants.items():
        runs = read_all(**settings)
        for rate in (3.6e-4, 3.6e-3, 3.6e-2):
            alarms(runs, rate, f"2. {title}, {rate:g} false alarms per hour")


def simulated(series: int, records: int) -> None:
    from bearinglab.geometry import BallBearing
    from bearinglab.operating import OperatingCondition
    from bearinglab.trend import trend_records
    from bearinglab.trend.simulated import simulate_series

    bearing = BallBearing(ball_count=13, ball_diameter=3.5e-3, pitch_diameter=25.6e-3)
    condition = OperatingCondition.at_rpm(1800.0, radial_load=4000.0)
    tallies: dict = {}
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(series):
            folder = simulate_series(
                Path(tmp) / f"s{seed}", bearing, condition, records=records, seed=seed
            )
            for rate in (FALSE_ALARM_PER_HOUR, 0.36, 6.0):
                r = trend_records(folder, false_alarm_per_hour=rate)
                fired = len(crossing_runs(r.runs().any(axis=1)))
                hours = r.monitored_records * r.record_spacing / 3600.0
                t = tallies.setdefault(rate, [0, 0.0, r.limit_excess])
                t[0] += fired
                t[1] += hours
    print(f"\n3. healthy simulated series: {series} x {records} records, a record every 10 s")
    for rate, (fired, hours, x) in tallies.items():
        print(
            f"  stated {rate:g} per hour (limit {x:.2f} robust scales): {fired} firings in "
            f"{hours:.2f} h = {fired / hours:.3g} per hour"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sensitivity", action="store_true")
    parser.add_argument("--simulated", type=int, default=0, help="healthy simulated series")
    parser.add_argument("--records", type=int, default=600)
    args = parser.parse_args()
    runs = read_all()
    calibration_check(runs)
    alarms(runs, FALSE_ALARM_PER_HOUR, f"2. defaults, {FALSE_ALARM_PER_HOUR:g} per hour")
    if args.sensitivity:
        sensitivity()
    if args.simulated:
        simulated(args.simulated, args.records)


if __name__ == "__main__":
    main()
