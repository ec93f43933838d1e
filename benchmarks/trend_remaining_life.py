"""The remaining-life estimate, leave one run out over the six PRONOSTIA learning runs
(issue 29).

Each run is held out in turn; the alarm's calibration and the lives are learned from the
other five (:func:`bearinglab.trend.learning.learn_from_runs`). The held-out run is cut at 5
points evenly spaced between its alarm (or half its life, when the alarm comes after 95 %
of it) and 95 % of its life, as the challenge cut its test runs, and the series up to each
cut is trended and its remaining life estimated as a user would see it. Scored with the
PHM 2012 challenge's formula ([Nectoux2012b]): Er = 100 (actual - estimate) / actual,
accuracy exp(-ln(0.5) Er / 5) for Er <= 0 and exp(ln(0.5) Er / 20) for Er > 0, the score
their mean. Also: the median |Er|, the estimates more than twice the actual, how often the
80 % interval holds the actual, and the time the estimate takes beside the trend's.

The package's method (trajectory similarity, :mod:`bearinglab.trend.similarity`) is printed
cut by cut; then, on the same cuts, the summary of the method it replaced (the lives'
lognormal-t law before the alarm, the r.m.s. trend or the alarm-to-failure law after it:
what :mod:`bearinglab.trend.life` does with learned parameters that hold no trajectories)
and of a constant 1290 s (the constant that scores 0.297 on the challenge's test runs,
chosen there in hindsight).

    .venv/bin/python benchmarks/trend_remaining_life.py
"""

from __future__ import annotations

import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from bearinglab.trend.learning import learn_from_runs, read_run
from bearinglab.trend.life import life_of, phm2012_accuracy
from bearinglab.trend.rule import evaluate

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT.parent / "shared" / "data" / "run-to-failure"
NAMES = ("Bearing1_1", "Bearing1_2", "Bearing2_1", "Bearing2_2", "Bearing3_1", "Bearing3_2")
CUTS = 5


def truncated(run, k: int):
    """``run`` (a RunSeries) up to its record ``k`` - 1."""
    return replace(run, times=run.times[:k], values={n: v[:k] for n, v in run.values.items()})


def alarm_record(run, calibration):
    ev = evaluate(
        run.times,
        run.values,
        run.channels,
        run.settle_records,
        run.baseline_stop,
        run.rule,
        calibration,
        [],
    )
    return None if ev["alarm"] is None else ev["alarm"].record


def without_trajectories(learned):
    """``learned`` with the lives, leads and end levels only (the method before)."""
    life = {k: v for k, v in learned.life.items() if k != "trajectories"}
    return replace(learned, life=life)


class Constant:
    """A constant remaining life [s] with no interval."""

    def __init__(self, value: float):
        self.estimate = self.low = self.high = value
        self.basis = "constant"


CONSTANT = Constant(1290.0)


def estimates(runs: dict, variant: str):
    """(rows of (run, cut time, actual, RemainingLife), seconds spent estimating)."""
    rows = []
    spent = 0.0
    for name, run in runs.items():
        others = {k: v for k, v in runs.items() if k != name}
        learned = learn_from_runs(others, f"the five learning runs other than {name}")
        if variant == "before":
            learned = without_trajectories(learned)
        alarm = alarm_record(run, learned.calibration)
        life = float(run.times[-1])
        t_alarm = None if alarm is None else float(run.times[alarm])
        start = t_alarm if t_alarm is not None and t_alarm < 0.95 * life else 0.5 * life
        for cut in np.linspace(start, 0.95 * life, CUTS):
            k = int(np.searchsorted(run.times, cut, side="right"))
            part = truncated(run, k)
            seen = alarm if alarm is not None and alarm < k else None
            tic = time.perf_counter()
            if variant == "constant":
                rows.append((name, float(part.times[-1]), life - float(part.times[-1]), CONSTANT))
                continue
            est = life_of(
                learned,
                part.times,
                part.values,
                part.settle_records,
                part.baseline_stop,
                part.persistence,
                seen,
                history=1,
            )
            spent += time.perf_counter() - tic
            actual = life - float(part.times[-1])
            rows.append((name, float(part.times[-1]), actual, est))
    return rows, spent


def summary(rows) -> tuple:
    """(median |Er| [%], score, estimates more than twice the actual, interval holding)."""
    errors, accuracy, over, inside = [], [], 0, 0
    for _, _, actual, est in rows:
        errors.append(abs(100.0 * (actual - est.estimate) / actual))
        accuracy.append(float(phm2012_accuracy(actual, est.estimate)))
        over += est.estimate > 2 * actual
        inside += est.low <= actual <= est.high
    return float(np.median(errors)), float(np.mean(accuracy)), over, inside


def main() -> None:
    runs = {name: read_run(RUNS / name) for name in NAMES if (RUNS / name).is_dir()}
    rows, spent = estimates(runs, "similarity")
    print(
        f"{'run':11s} {'cut [s]':>8s} {'actual [s]':>10s} {'estimate [s]':>12s} "
        f"{'80 % interval [s]':>22s} {'Er [%]':>8s} {'A':>6s}  basis"
    )
    errors, accuracy, over, inside = [], [], 0, 0
    for name, cut, actual, est in rows:
        er = 100.0 * (actual - est.estimate) / actual
        a = float(phm2012_accuracy(actual, est.estimate))
        errors.append(abs(er))
        accuracy.append(a)
        over += est.estimate > 2 * actual
        inside += est.low <= actual <= est.high
        print(
            f"{name:11s} {cut:8.0f} {actual:10.0f} {est.estimate:12.0f} "
            f"{f'{est.low:.0f} - {est.high:.0f}':>22s} {er:8.0f} {a:6.3f}  {est.basis}"
        )
    n = len(rows)
    print(
        f"\n{n} estimates: median |Er| {np.median(errors):.0f} %, score {np.mean(accuracy):.3f}, "
        f"{over} more than twice the actual, interval holds the actual in {inside} of {n}; "
        f"{1e3 * spent / n:.1f} ms per estimate"
    )
    for variant, words in (
        ("before", "the method before (lognormal-t lives, r.m.s. trend, alarm-to-failure)"),
        ("constant", "a constant 1290 s"),
    ):
        med, score, over, inside = summary(estimates(runs, variant)[0])
        print(
            f"{words}: median |Er| {med:.0f} %, score {score:.3f}, {over} more than twice "
            f"the actual, interval holds the actual in {inside} of {n}"
        )


if __name__ == "__main__":
    main()
