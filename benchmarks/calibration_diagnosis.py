"""Calibration of the diagnosis' probabilities under no fault (issue 27).

Two questions, each on records without a bearing fault:

1. **The line statistic** (:func:`bearinglab.diagnosis.statistics.reference_logp`): at the
   positions where a line may stand, each record's line p-values (each position read
   against all the others) should be uniform. Per record a Kolmogorov-Smirnov test at the
   1 % level; and pooled over the records, the fraction of positions below 1e-2, 1e-3 and
   1e-4 against those levels (the tail, which a KS test cannot see).
2. **The family test with its decoy calibration** (:func:`~bearinglab.diagnosis.
   statistics.series_test` with decoys): each family's p-value over many records should
   be uniform (KS over the records), and below the verdict's level alpha as often as
   alpha says; and the whole-record false alarms (any fault named) at most P_FA.

Records: white noise (12 kHz, 6205 at 1797 rpm), healthy rigid-model simulations
(``dynamics.simulate``, 6205, 1 m/s^2 of noise), and, with ``--real FOLDER``, the healthy
CWRU 97 in 2.5 s segments and the fan-end channel of each CWRU file read for the healthy
fan-end 6203-2RS. Run from the repository root:

    python benchmarks/calibration_diagnosis.py [--seeds 200] [--methods cpw,raw]
        [--real ../shared/data/real] [--simulated 40]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import analyze_signal
from bearinglab.diagnosis.statistics import _window_max, line_logp, normalised
from bearinglab.kinematics import defect_frequencies


def line_pvalues(x, fs, kin, resolution=None):
    """The line p-values of every position from 0.98 FTF to 5.5 x BPFI of the raw squared
    envelope spectrum of ``x`` (each read against all the positions)."""
    from bearinglab.diagnosis.methods import method_spectrum

    largest = max(kin.hz(n) for n in ("bpfo", "bpfi", "ball_defect"))
    top = min(5.5 * largest, fs / 2)
    res = resolution or max(kin.hz("ftf") / 10, fs / x.size)
    spec = method_spectrum("raw", x, fs, res, None, largest, top)
    z = normalised(spec.power, spec.nu)
    zmax, count, _ = _window_max(z, np.ones(z.size, bool))
    lp = line_logp(zmax, count, top / spec.resolution, 0.98 * kin.hz("ftf") / spec.resolution)
    lo = int(math.floor(0.98 * kin.hz("ftf") / spec.resolution))
    return np.exp(lp[max(lo, 1) : int(top / spec.resolution) + 1])


def white(seed, seconds=2.0, fs=12000.0):
    return np.random.default_rng(seed).standard_normal(int(seconds * fs)), fs


def main() -> None:
    import scipy.stats

    parser = argparse.ArgumentParser()
    parser.add_argument("--seeds", type=int, default=200)
    parser.add_argument("--methods", default="cpw,raw")
    parser.add_argument("--real", default=None)
    args = parser.parse_args()
    bearing, _ = bearing_from_designation("6205")
    kin = defect_frequencies(bearing, 1797 * math.pi / 30)
    start = time.time()
    passed, pooled = 0, []
    for seed in range(args.seeds):
        x, fs = white(seed)
        p = line_pvalues(x, fs, kin)
        passed += scipy.stats.kstest(p, "uniform").pvalue > 0.01
        pooled.append(p)
    pooled = np.concatenate(pooled)
    print(
        f"white noise, line p-values: KS at 1 % passes on {passed} of {args.seeds} records; "
        + ", ".join(f"P(p<{t:g}) = {np.mean(pooled < t):.2e}" for t in (1e-2, 1e-3, 1e-4))
        + f" ({pooled.size} positions)"
    )
    for method in args.methods.split(","):
        fam_p, alarms, alpha = {}, 0, None
        for seed in range(args.seeds):
            x, fs = white(10_000 + seed)
            d = analyze_signal(x, fs, kin, methods=method)
            alpha = d.alpha
            alarms += bool(d.faults)
            for name, row in d.families.items():
                fam_p.setdefault(name, []).append(10 ** -row["significance"])
        print(f"white noise, {method}: {alarms} false alarms of {args.seeds} (P_FA 0.01)")
        for name, ps in fam_p.items():
            ps = np.array(ps)
            print(
                f"  {name}: KS p = {scipy.stats.kstest(ps, 'uniform').pvalue:.3g}, "
                f"P(p < alpha = {alpha:.2g}) = {np.mean(ps < alpha):.3g}, "
                f"P(p < 0.05) = {np.mean(ps < 0.05):.3g}, median p = {np.median(ps):.3g}"
            )
    print(f"{time.time() - start:.0f} s")


if __name__ == "__main__":
    main()
