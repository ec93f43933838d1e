"""Compound and single simulated faults: is a compound reported whole, and a single fault
never made a compound? (issue 27 item 10)

The README's ER-16K (1750 rpm, 50 N, rigid model, 20 kHz) with an outer-race defect
(1.2 x 0.25 mm), a ball defect (1.2 mm), an inner-race defect (1.2 x 0.25 mm), and two of
them together (the README's outer race and ball; outer and inner race; inner race and
ball), at noise 0 (the README's line) and 1 and 5 m/s^2 RMS
(seeds 0-2: the seed draws the noise only; the model is deterministic), each diagnosed by
``raw`` (the default for a simulated record) and ``cpw``. Run from the repository root:

    python benchmarks/compound_simulated.py [--duration 2] [--cache DIR]

``--cache DIR`` keeps the simulated records (npz) there, so that two trees can be compared
on the same records (PYTHONPATH=... for each).
"""

from __future__ import annotations

import argparse
import math
import time
from collections import Counter
from pathlib import Path

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import analyze_signal
from bearinglab.dynamics import Defect, simulate
from bearinglab.kinematics import defect_frequencies
from bearinglab.operating import OperatingCondition
from bearinglab.signal import read_signal, write_signal

CASES = {
    "outer": [Defect("outer", 1.2e-3, 0.25e-3)],
    "inner": [Defect("inner", 1.2e-3, 0.25e-3)],
    "ball": [Defect("ball", 1.2e-3)],
    "outer+ball": [Defect("outer", 1.2e-3, 0.25e-3), Defect("ball", 1.2e-3)],
    "outer+inner": [Defect("outer", 1.2e-3, 0.25e-3), Defect("inner", 1.2e-3, 0.25e-3)],
    "inner+ball": [Defect("inner", 1.2e-3, 0.25e-3), Defect("ball", 1.2e-3)],
}
#: The faults each case should be called (in any order).
EXPECTED = {
    "outer": {"outer_race"},
    "inner": {"inner_race"},
    "ball": {"ball"},
    "outer+ball": {"outer_race", "ball"},
    "outer+inner": {"outer_race", "inner_race"},
    "inner+ball": {"inner_race", "ball"},
}
NOISE = ((0.0, 0), (1.0, 0), (1.0, 1), (1.0, 2), (5.0, 0), (5.0, 1), (5.0, 2))
METHODS = ("raw", "cpw")
FS = 20000.0
RPM = 1750.0


def record(case: str, noise: float, seed: int, duration: float, cache: Path | None):
    """The simulated record (a Signal), from ``cache`` when it is there."""
    path = cache / f"{case}-{noise:g}-{seed}-{duration:g}.npz" if cache else None
    if path is not None and path.exists():
        return read_signal(path)
    bearing, _ = bearing_from_designation("ER-16K")
    condition = OperatingCondition(radial_load=50.0, shaft_speed=RPM * math.pi / 30)
    sim = simulate(
        bearing,
        condition,
        CASES[case],
        model="rigid",
        duration=duration,
        sample_rate=FS,
        noise=noise,
        seed=seed,
    )
    if path is not None:
        write_signal(path, sim.signal)
    return sim.signal


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=2.0)
    parser.add_argument("--cache", type=Path, default=None)
    args = parser.parse_args()
    if args.cache:
        args.cache.mkdir(parents=True, exist_ok=True)
    bearing, _ = bearing_from_designation("ER-16K")
    kin = defect_frequencies(bearing, RPM * math.pi / 30)
    tally: Counter = Counter()
    print(f"{'case':<11} {'noise':>5} {'seed':>4}  " + "  ".join(f"{m:<44}" for m in METHODS))
    for case in CASES:
        for noise, seed in NOISE:
            signal = record(case, noise, seed, args.duration, args.cache)
            row = []
            for method in METHODS:
                start = time.perf_counter()
                d = analyze_signal(signal, None, kin, channel="acc_y", methods=method)
                took = time.perf_counter() - start
                right = set(d.faults) == EXPECTED[case]
                tally[case, method, right] += 1
                tally[case, method, "wrong"] += bool(set(d.faults) - EXPECTED[case])
                row.append(f"{d.verdict:<38}{took * 1e3:5.0f} ms")
            print(f"{case:<11} {noise:>5g} {seed:>4}  " + "  ".join(row))
    print()
    for case in CASES:
        for method in METHODS:
            n = tally[case, method, True] + tally[case, method, False]
            print(
                f"{case:<11} {method:<4} {tally[case, method, True]} of {n} as "
                f"{' + '.join(sorted(EXPECTED[case]))}, {tally[case, method, 'wrong']} with a "
                "fault not simulated"
            )


if __name__ == "__main__":
    main()
