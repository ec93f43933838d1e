"""Seed 001 (Balyakin et al. 2010), bearing 126126: our analogues of figs. 7-10.

Computes S_r, C_r and C_a of the 126126 with the internal geometry estimated in
``bearinglab.validation.seed001`` (Z = 15, D_w = 18.9 mm, d_m = 165 mm, f = 0.53, gothic
arches of 15.2 deg on both rings, P_d = 150 um, 26 deg under a light axial load) and
draws

* fig7: S_r against F_r for F_a = 0, 150, 350, 700 N at 0, 4500, 8000 rpm;
* fig8: S_r against F_r at 8000 rpm for all F_a, with the inflection of each curve;
* fig9: C_r and C_a against F_r at 4500 rpm for each F_a;
* fig10: C_r and C_a against F_a at 4500 rpm for several F_r;

then prints the key numbers next to the paper's. PNGs are written atomically
(bearinglab.plotting.save_figure). Usage::

    python examples/seed001_126126.py [OUT_DIR] [--jobs N] [--step N]

OUT_DIR defaults to ./out. A point where the solver raises ConvergenceError is left out
of the curves and listed at the end with its inputs.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from bearinglab.validation import seed001 as s1

FIG10_RADIAL_LOADS = s1.FIG10_RADIAL_LOADS_N
FIG10_AXIAL_LOADS = s1.FIG10_AXIAL_LOADS_N


def _sweep(task):
    radial, axial, rpm = task
    return task, s1.sweep(radial, axial, rpm)


def compute(step: float, jobs: int) -> dict:
    """Every sweep the figures need, keyed by (kind, load, rpm)."""
    radial = (10.0, 25.0, *np.arange(step, 1200.0 + 0.5 * step, step).tolist())
    tasks = {}
    for rpm in s1.SPEEDS_RPM:
        for fa in s1.AXIAL_LOADS_N:
            tasks[("fr", fa, rpm)] = (tuple(radial), fa, rpm)
    for fa in s1.AXIAL_LOADS_N[1:]:  # fine grids for the inflection
        tasks[("knee", fa, 8000.0)] = (tuple(s1.inflection_grid(fa)), fa, 8000.0)
    for fr in FIG10_RADIAL_LOADS:
        tasks[("fa", fr, 4500.0)] = (fr, FIG10_AXIAL_LOADS, 4500.0)
    order = sorted(tasks, key=lambda k: -np.size(tasks[k][0]) * np.size(tasks[k][1]))
    if jobs > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            done = dict(pool.map(_sweep, [tasks[k] for k in order]))
        return {k: done[tasks[k]] for k in tasks}
    return {k: _sweep(tasks[k])[1] for k in order}


def figures(results: dict, out: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from bearinglab.plotting import save_figure

    e = s1.AXIAL_LOAD_FACTOR
    colours = {0.0: "C0", 4500.0: "C1", 8000.0: "C3"}
    written = []

    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), sharex=True)
    for ax, fa, letter in zip(axes.flat, s1.AXIAL_LOADS_N, "abcd", strict=True):
        for rpm in s1.SPEEDS_RPM:
            c = results[("fr", fa, rpm)]
            ax.plot(
                c.radial_load,
                c.radial_displacement,
                ".-",
                color=colours[rpm],
                label=f"{rpm:.0f} rpm",
            )
        if fa > 0:
            ax.axvline(fa / e, color="0.5", ls=":", label="F_a/F_r = e = 0.68")
        ax.set_title(f"({letter}) F_a = {fa:.0f} N")
        ax.set_ylabel("S_r [um]")
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("F_r [N]")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("126126, P_d = 150 um: radial displacement (cf. seed 001 fig. 7)")
    written.append(save_figure(fig, out / "seed001_fig7_displacement.png"))

    fig, ax = plt.subplots(figsize=(7, 5))
    for k, fa in enumerate(s1.AXIAL_LOADS_N):
        f, d = (
            [results[("fr", fa, 8000.0)].radial_load],
            [results[("fr", fa, 8000.0)].radial_displacement],
        )
        if fa > 0:
            fine = results[("knee", fa, 8000.0)]
            f.append(fine.radial_load)
            d.append(fine.radial_displacement)
        f, d = np.concatenate(f), np.concatenate(d)
        order = np.argsort(f)
        ax.plot(f[order], d[order], "-", color=f"C{k}", label=f"F_a = {fa:.0f} N")
        if fa > 0:
            fine = results[("knee", fa, 8000.0)]
            knee = s1.onset_load(fine.radial_load, fine.radial_displacement)
            ax.axvline(knee, color=f"C{k}", ls=":", lw=1)
            ax.plot([fa / e], [0.0], "v", color=f"C{k}")
    ax.set_xlim(0.0, 1250.0)
    ax.set_xlabel("F_r [N]")
    ax.set_ylabel("S_r [um]")
    ax.set_title(
        "8000 rpm (cf. fig. 8): dotted = our knee (onset), triangle = F_a/F_r = e", fontsize=9
    )
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    written.append(save_figure(fig, out / "seed001_fig8_displacement_8000rpm.png"))

    curves = [
        (f"F_a = {fa:.0f} N", results[("fr", fa, 4500.0)], fa / e if fa > 0 else None)
        for fa in s1.AXIAL_LOADS_N
    ]
    fig = _stiffness_figure(
        plt,
        curves,
        "radial_load",
        "F_r [N]",
        ("C_r = dF_r/dS_r [N/um]", "C_a = dF_a/dS_a [N/um]"),
        "4500 rpm (cf. fig. 9); dotted: F_a/F_r = e",
    )
    written.append(save_figure(fig, out / "seed001_fig9_stiffness_vs_fr.png"))
    curves = [(f"F_r = {fr:.0f} N", results[("fa", fr, 4500.0)], None) for fr in FIG10_RADIAL_LOADS]
    fig = _stiffness_figure(
        plt, curves, "axial_load", "F_a [N]", ("C_r [N/um]", "C_a [N/um]"), "4500 rpm (cf. fig. 10)"
    )
    written.append(save_figure(fig, out / "seed001_fig10_stiffness_vs_fa.png"))
    return written


def _stiffness_figure(plt, curves, along: str, xlabel: str, ylabels, title: str):
    """C_r (left) and C_a (right) of each (label, curve, mark) against the curve's load
    ``along``, with a dotted line at ``mark`` [N] unless it is None."""
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for k, (label, c, mark) in enumerate(curves):
        ax1.plot(getattr(c, along), c.radial_stiffness, ".-", color=f"C{k}", label=label)
        ax2.plot(getattr(c, along), c.axial_stiffness, ".-", color=f"C{k}")
        if mark is not None:
            for ax in (ax1, ax2):
                ax.axvline(mark, color=f"C{k}", ls=":", lw=1)
    ax1.set_ylabel(ylabels[0])
    ax2.set_ylabel(ylabels[1])
    for ax in (ax1, ax2):
        ax.set_xlabel(xlabel)
        ax.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    fig.suptitle(title)
    return fig


def _at(curve, load: float) -> float:
    hit = np.flatnonzero(np.isclose(curve.radial_load, load))
    return float(curve.radial_displacement[hit[0]]) if hit.size else math.nan


def report(results: dict) -> None:
    b = s1.BEARING
    print(
        f"126126 (estimated): Z = {b.ball_count}, D_w = {b.ball_diameter * 1e3:.2f} mm, "
        f"d_m = {b.pitch_diameter * 1e3:.1f} mm, f_i = f_o = {b.inner_groove_factor}, "
        f"alpha_T = {math.degrees(b.inner_arch_angle):.2f} deg, "
        f"P_d = {b.diametral_clearance * 1e6:.0f} um, alpha_0 = 26 deg"
    )
    print("\ninflection at 8000 rpm (paper, fig. 8: F_a/F_r = 0.64...0.71, e = 0.68)")
    print("  F_a [N]  onset F_r [N]  F_a/F_r   max-d2 F_r [N]  F_a/F_r")
    for fa in s1.AXIAL_LOADS_N[1:]:
        c = results[("knee", fa, 8000.0)]
        onset = s1.onset_load(c.radial_load, c.radial_displacement)
        d2 = s1.inflection_load(c.radial_load, c.radial_displacement)
        print(f"  {fa:7.0f}  {onset:13.0f}  {fa / onset:7.3f}   {d2:14.0f}  {fa / d2:7.3f}")
    print("\nS_r at F_r = 1000 N [um] (paper, fig. 7 a-v: about 10 um less at 8000 rpm)")
    print("  F_a [N]   0 rpm   4500 rpm   8000 rpm   S_r(0) - S_r(8000)")
    for fa in s1.AXIAL_LOADS_N:
        v = [_at(results[("fr", fa, rpm)], 1000.0) for rpm in s1.SPEEDS_RPM]
        print(f"  {fa:7.0f}  {v[0]:6.1f}  {v[1]:9.1f}  {v[2]:9.1f}   {v[0] - v[2]:+8.1f}")
    print(
        "\nC_r against F_r at 4500 rpm (paper, fig. 9a: falls, then rises; the fall where "
        "F_a/F_r < e)"
    )
    print(
        "  F_a [N]  C_r first  min (at F_r)      last   fall starts   share of fall at F_a/F_r < e"
    )
    for fa in s1.AXIAL_LOADS_N[1:]:
        c = results[("fr", fa, 4500.0)]
        d = s1.describe_stiffness_fall(c.radial_load, c.radial_stiffness, fa)
        print(
            f"  {fa:7.0f}  {d.initial:9.0f}  {d.minimum:4.0f} ({d.minimum_load:5.0f} N)  "
            f"{d.final:7.0f}   F_a/F_r={fa / d.fall_start:5.2f}   {d.fraction_below_e:6.2f}"
        )
    failures = [f for c in results.values() for f in c.failures]
    print(
        f"\n{len(failures)} of {sum(c.radial_load.size for c in results.values())} solves "
        "raised ConvergenceError" + (":" if failures else "")
    )
    for fr, fa, rpm, msg in failures:
        print(f"  F_r = {fr:g} N, F_a = {fa:g} N, {rpm:g} rpm: {msg[:100]}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default="out", help="output directory (./out)")
    parser.add_argument(
        "--jobs",
        type=int,
        default=min(os.cpu_count() or 1, 4),
        help="worker processes (default: CPUs, at most 4)",
    )
    parser.add_argument(
        "--step", type=float, default=50.0, help="F_r step of the curves [N] (default 50)"
    )
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    results = compute(args.step, args.jobs)
    solved = time.perf_counter() - start
    for path in figures(results, out):
        print(f"wrote {path}")
    report(results)
    n = sum(c.radial_load.size for c in results.values())
    print(
        f"\n{n} solves in {solved:.1f} s with {args.jobs} process(es); total "
        f"{time.perf_counter() - start:.1f} s"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
