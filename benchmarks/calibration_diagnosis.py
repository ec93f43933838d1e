"""Calibration of the diagnosis' probabilities under no fault (issue 27).

Three questions, each on records without a bearing fault:

1. **The line statistic** (:func:`bearinglab.diagnosis.tail.reference_logp`): at the
   positions where a line may stand, each record's line p-values (each position read
   against all of them) should be uniform. Per record a Kolmogorov-Smirnov test at the
   1 % level; pooled over the records, the fraction of positions below 1e-2, 1e-3 and
   1e-4 against those levels (the tail, which a KS test cannot see).
2. **The chain bound on its own** (:mod:`bearinglab.diagnosis.chain`): the best Fisher
   p-value of each family's scan (its own geometry: a 6205 at 1797 rpm, 12 kHz, the
   default resolution) on records of independent bins whose lines' p-values are exact,
   against the bound, at t = 0.05 ... 1e-4 (``--chain DRAWS``).
3. **The family's p-value** (tail and chain, :func:`~bearinglab.diagnosis.series.
   series_test`) as the diagnosis computes it: over the records, each family's p-value
   below t as often as t at most (P(p < t) / t, with the count), a KS test of their
   uniformity, and the whole-record false alarms (any fault named) against P_FA.

Records: white noise (12 kHz, 6205 at 1797 rpm; ``--seconds``), healthy rigid-model
simulations (``--simulated N``: ``dynamics.simulate``, 6205, 1797 rpm, 2 kN, 1 m/s^2 of
white noise; the default methods for them, raw and cpw), and with ``--real FOLDER`` the healthy
CWRU 97 in 2.5 s segments at its logged speed and 1-2 % either side (drive and fan end)
and the fan-end channel of every CWRU file read for the healthy fan-end 6203-2RS. Run
from the repository root:

    python benchmarks/calibration_diagnosis.py [--seeds 200] [--seconds 2] [--methods cpw,raw]
        [--chain 20000] [--simulated 40] [--real ../shared/data/real]
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import analyze_signal
from bearinglab.diagnosis.series import _window_max
from bearinglab.diagnosis.statistics import normalised
from bearinglab.diagnosis.tail import line_logp
from bearinglab.kinematics import defect_frequencies

LEVELS = (0.2, 0.1, 0.05, 0.01, 0.0025, 0.001)


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


def healthy_real(folder):
    """(samples, rate, DefectFrequencies) of the healthy CWRU 97 in four 2.5 s segments at
    its logged speed and 1, 2 % either side (drive and fan end), and of the fan-end
    channel of every CWRU file read for the healthy fan-end 6203-2RS."""
    import sys

    sys.path.insert(0, str(Path(__file__).parent))
    from null_diagnosis import SPEEDS, _bearing, _channel, _rows

    rows = _rows(folder)
    row = next(r for r in rows if r["fault"] == "normal")
    for channel in ("DE", "FE"):
        x, fs = _channel(folder, row, channel)
        quarter = x.size // 4
        for q in range(4):
            for factor in SPEEDS:
                rpm = factor * float(row["speed_rpm"])
                kin = defect_frequencies(_bearing(row), rpm * math.pi / 30)
                yield x[q * quarter : (q + 1) * quarter], fs, kin
    fan = bearing_from_designation("6203-2RS")[0]
    for row in rows:
        if row["dataset"] != "CWRU":
            continue
        got = _channel(folder, row, "FE")
        if got is not None:
            kin = defect_frequencies(fan, float(row["speed_rpm"]) * math.pi / 30)
            yield got[0], got[1], kin


def white(seed, seconds=2.0, fs=12000.0):
    return np.random.default_rng(seed).standard_normal(int(seconds * fs)), fs


def report(name, records):
    """Print each family's P(p < t) / t and the whole-record false alarms."""
    import scipy.stats

    alarms = sum(bool(faults) for faults, _ in records)
    n = len(records)
    print(f"{name}: {alarms} false alarms of {n} records (P_FA 0.01)")
    families = records[0][1].keys() if records else ()
    for fam in families:
        p = np.array([row[fam] for _, row in records])
        ratios = ", ".join(
            f"{t:g}: {np.mean(p < t) / t:.2f} ({int(np.sum(p < t))})" for t in LEVELS
        )
        ks = scipy.stats.kstest(p, "uniform").pvalue
        print(f"  {fam:10s} P(p < t) / t  {ratios};  KS p = {ks:.3g}")


def line_report(name, records):
    """Print how many records' line p-values pass a KS test of uniformity at 1 %, and the
    pooled fraction of positions below 1e-2, 1e-3 and 1e-4."""
    import scipy.stats

    passed = sum(scipy.stats.kstest(p, "uniform").pvalue > 0.01 for p in records)
    pooled = np.concatenate(records)
    print(
        f"{name}, line p-values: KS at 1 % passes on {passed} of {len(records)} records; "
        + ", ".join(f"P(p<{t:g}) = {np.mean(pooled < t):.2e}" for t in (1e-2, 1e-3, 1e-4))
        + f" ({pooled.size} positions)"
    )


def family_pvalues(d):
    return {name: row["p_value"] for name, row in d.families.items()}


def chain_check(draws, seed=0):
    """The chain bound against the scan's true law on records of independent bins."""
    from bearinglab.diagnosis.chain import chain_logp, chain_steps
    from bearinglab.diagnosis.families import families, tolerances
    from bearinglab.diagnosis.series import _read

    bearing, _ = bearing_from_designation("6205")
    kin = defect_frequencies(bearing, 1797 * math.pi / 30)
    freqs = {k: kin.hz(k) for k in ("shaft", "ftf", "bpfo", "bpfi", "ball_defect")}
    res, top = 12000.0 / 8192, 5.5 * freqs["bpfi"]
    size = int(top / res) + 8
    rng = np.random.default_rng(seed)
    for fam in families(freqs, tolerances()):
        n_max = int(min(8, math.floor(top / (fam.frequency * (1 + fam.above)))))
        step = res / (2.0 * n_max)
        grid = np.arange(
            fam.frequency * (1 - fam.below), fam.frequency * (1 + fam.above) + step / 2, step
        )
        spec = [(n, 0) for n in range(1, n_max + 1)]
        if fam.modulation and fam.orders:
            spec += [(n, s * k) for n in range(1, n_max + 1) for k in (1, 2) for s in (-1, 1)]
            spec += [(0, k) for k in (1, 2)]
        n_arr = np.array([r[0] for r in spec], float)
        k_arr = np.array([r[1] for r in spec], float)
        index, readable = _read(grid, n_arr, k_arr, fam.modulation, top, res, np.ones(size, bool))
        depths = (0, 1, 2) if fam.orders else (0,)
        uses = [readable & (np.abs(k_arr) <= d)[None, :] for d in depths]
        best = np.full(draws, np.inf)
        for chunk in range(0, draws, 2000):
            m = min(2000, draws - chunk)
            u = rng.random((m, size + 2))
            third = np.minimum(np.minimum(u[:, :-2], u[:, 1:-1]), u[:, 2:])
            lp = np.log1p(-np.exp(3.0 * np.log1p(-third)))
            read = lp[:, index - 1]  # draws x rows x lines
            import scipy.special

            for use in uses:
                stat = -2.0 * np.where(use[None], read, 0.0).sum(axis=2)
                logp = np.log(np.maximum(scipy.special.chdtrc(2 * use.sum(axis=1), stat), 1e-300))
                best[chunk : chunk + m] = np.minimum(best[chunk : chunk + m], logp.min(axis=1))
        chains = [chain_steps(index, use) for use in uses]
        distinct = sum(
            len({tuple(np.where(u, index, -1)[r]) for r in range(len(grid))}) for u in uses
        )
        line = []
        for t in (0.05, 0.01, 0.0025, 1e-3, 1e-4):
            truth = np.mean(best <= math.log(t))
            bound = math.exp(chain_logp(math.log(t), chains))
            line.append(
                f"{t:g}: true {truth:.3g} bound {bound:.3g} Bonferroni {min(1, distinct * t):.3g}"
            )
        print(
            f"  chain, {fam.name:10s} ({len(grid)} fundamentals, {n_arr.size} lines): "
            + "; ".join(line)
        )


def main() -> None:

    parser = argparse.ArgumentParser()
    parser.add_argument("--seeds", type=int, default=200)
    parser.add_argument("--seconds", type=float, default=2.0)
    parser.add_argument("--methods", default="cpw,raw")
    parser.add_argument("--chain", type=int, default=0)
    parser.add_argument("--simulated", type=int, default=0)
    parser.add_argument("--real", default=None)
    args = parser.parse_args()
    bearing, _ = bearing_from_designation("6205")
    kin = defect_frequencies(bearing, 1797 * math.pi / 30)
    start = time.time()
    line_report(
        "white noise", [line_pvalues(*white(seed, args.seconds), kin) for seed in range(args.seeds)]
    )
    if args.chain:
        print(f"the chain bound against {args.chain} records of independent bins:")
        chain_check(args.chain)
    for method in args.methods.split(","):
        records = []
        for seed in range(args.seeds):
            x, fs = white(10_000 + seed, args.seconds)
            d = analyze_signal(x, fs, kin, methods=method)
            records.append((d.faults, family_pvalues(d)))
        report(f"white noise {args.seconds:g} s, {method}", records)
    if args.simulated:
        from bearinglab.dynamics import simulate
        from bearinglab.operating import OperatingCondition

        condition = OperatingCondition(radial_load=2000.0, shaft_speed=1797 * math.pi / 30)
        records, lines = [], []
        for seed in range(args.simulated):
            sim = simulate(
                bearing,
                condition,
                [],
                model="rigid",
                duration=2.0,
                sample_rate=12000.0,
                noise=1.0,
                seed=seed,
            )
            d = analyze_signal(sim.signal, None, sim.kinematic)
            records.append((d.faults, family_pvalues(d)))
            lines.append(line_pvalues(sim.signal.channel(), sim.signal.sample_rate, kin))
        report("healthy rigid-model simulations, 2 s, 1 m/s^2 of noise (raw and cpw)", records)
        line_report("healthy rigid-model simulations", lines)
    if args.real:
        records = {m: [] for m in args.methods.split(",")}
        lines = []
        for x, fs, k in healthy_real(Path(args.real)):
            lines.append(line_pvalues(x, fs, k))
            for method in records:
                d = analyze_signal(x, fs, k, methods=method)
                records[method].append((d.faults, family_pvalues(d)))
        for method, rows in records.items():
            report(f"healthy real records (97 in 2.5 s segments, fan-end 6203), {method}", rows)
        line_report("healthy real records", lines)
    print(f"{time.time() - start:.0f} s")


if __name__ == "__main__":
    main()
