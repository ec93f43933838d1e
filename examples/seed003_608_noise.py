"""Seed 003 part 4 (Zhang, Yang & An 2018): noise of the C&U 608, our analogues of figs. 9-20.

The paper computes the noise of a C&U 608 deep-groove ball bearing at 720 rpm under a
radial load of 0.05 kN with raceway waviness of number 7 and ball-size errors, at point A
10 mm from the bearing centre (mean SPL 29.832 dB, fig. 14), and how the mean SPL changes
with the waviness number (figs. 15-16), the waviness amplitude (fig. 17), the speed (fig.
18), the load (fig. 19) and the ball-size error band (fig. 20). This script runs the same
chain on bearinglab's model (``bearinglab.noise.bearing_noise``: the quasi-static orbit of
seed 003 eqs. 14-18, the inner ring as a vibrating cylinder, eq. 19, the balls as
pulsating spheres, eq. 23) and draws into OUT_DIR (default ./figures_608):

* fig09_inner_ring.png      inner-ring centre orbit, x and y displacement and velocity
                            against time (fig. 9);
* fig10_ball_centres.png    ball-centre displacements from the pitch circle: radial for
                            every ball, x and y of ball 0, against time (fig. 10);
* fig11_ball_velocity.png   ball-centre radial velocities (the pulsating-sphere source) and
                            ball 0's x and y velocity (fig. 11);
* fig12_14_spl_time.png     SPL against time of the inner ring (x, y, total), the balls and
                            everything, with the mean SPL (figs. 12-14);
* pressure_spectrum.png     spectrum of the sound pressure with its lines matched to the
                            ball-pass frequencies (seed 002);
* directivity.png           SPL round the bearing at 10 mm (seed 002);
* fig15_16_waviness_number.png, fig17_amplitude.png, fig18_speed.png, fig19_load.png,
  fig20_ball_band.png       mean SPL against each parameter (the others at the base case).

Choices (the paper does not print them; docs/capabilities/noise.md explains each):
the 608's internal geometry is bearinglab's catalogue estimate (Z = 7, D_w = 3.85 mm,
d_m = 15 mm, f_i = 0.515, f_o = 0.525, P_d = 7.5 um: the paper's Table 1 is missing);
waviness amplitude 0.2 um (half the peak to peak) on the inner and the outer raceway,
both of order 7, phase 0; ball-size errors uniform in a 2 um band centred on the nominal
diameter, drawn with seed 1 (``BallSizeErrors.random(7, 2e-6, seed=1)``); point A straight
above the centre (+y; the paper gives only the distance); air at 20 deg C (1.21 kg/m^3,
343 m/s); one cage revolution (0.224 s at 720 rpm) in 1024 instants (``--points``); the
sweeps: amplitude 0.1-2 um, speed 360-1440 rpm, load 25-200 N, band 1-3 um, waviness
number 5-9. With these choices the base case gives a mean SPL of about 11 dB, not the
paper's 29.8 dB (the level scales with the unprinted amplitude: about 2 um would give it).

Usage::

    python examples/seed003_608_noise.py [OUT_DIR] [--points N] [--quick]

``--quick`` runs two values per sweep (for a smoke test). PNGs are written atomically
(bearinglab.plotting.save_figure). Runs in about a minute.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from bearinglab.catalog import bearing_from_designation
from bearinglab.imperfections import BallSizeErrors, Imperfections, Waviness
from bearinglab.kinematics import defect_frequencies
from bearinglab.noise import SEED003_POINT_A, bearing_noise
from bearinglab.operating import OperatingCondition
from bearinglab.signal import find_peaks, match_peaks
from bearinglab.units import rpm_to_rad_s

#: The base case: seed 003's operating point and our choices for what it does not print.
BASE = {"rpm": 720.0, "load": 50.0, "amplitude": 0.2e-6, "order": 7, "band": 2e-6}
SEED = 1
#: The sweeps (figs. 15-20), in the units of BASE.
SWEEPS = {
    "order": ("waviness number N_w", 1.0, "", (5, 6, 7, 8, 9)),
    "amplitude": ("waviness amplitude", 1e-6, "um", (0.1e-6, 0.2e-6, 0.4e-6, 0.8e-6, 2e-6)),
    "rpm": ("speed", 1.0, "rpm", (360.0, 540.0, 720.0, 1080.0, 1440.0)),
    "load": ("radial load", 1.0, "N", (25.0, 50.0, 100.0, 150.0, 200.0)),
    "band": ("ball-size error band", 1e-6, "um", (1e-6, 1.5e-6, 2e-6, 2.5e-6, 3e-6)),
}
FIGURE_OF = {
    "order": "fig15_16_waviness_number",
    "amplitude": "fig17_amplitude",
    "rpm": "fig18_speed",
    "load": "fig19_load",
    "band": "fig20_ball_band",
}
FIGURE_TITLE = {
    "order": "figs. 15-16",
    "amplitude": "fig. 17",
    "rpm": "fig. 18",
    "load": "fig. 19",
    "band": "fig. 20",
}
PUBLISHED_MEAN_SPL_DB = 29.832


def run(points: int, rpm: float, load: float, amplitude: float, order: int, band: float):
    """bearing_noise of the 608 at one case (seed-003 chain, our choices)."""
    bearing, _ = bearing_from_designation("608")
    imperfections = Imperfections(
        [Waviness("inner", order, amplitude), Waviness("outer", order, amplitude)],
        ball_size_errors=BallSizeErrors.random(bearing.ball_count, band, seed=SEED),
    )
    condition = OperatingCondition(radial_load=load, shaft_speed=rpm_to_rad_s(rpm))
    return bearing_noise(bearing, condition, imperfections, points=points, point=SEED003_POINT_A)


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _ball_figure(plt, t, radial, x, y, radial_label: str, xy_label: str, title: str):
    """Every ball's ``radial`` series above, ball 0's ``x`` and ``y`` below, against time."""
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    axes[0].plot(t, radial, lw=0.8)
    axes[0].set_ylabel(radial_label)
    axes[0].set_title(title)
    axes[1].plot(t, x, label="ball 0, x")
    axes[1].plot(t, y, label="ball 0, y")
    axes[1].set_ylabel(xy_label)
    axes[1].set_xlabel("time [s]")
    axes[1].legend()
    fig.tight_layout()
    return fig


def draw_base(noise, out: Path) -> list[Path]:
    """Figs. 9-14, the pressure spectrum and the directivity of the base case."""
    from bearinglab.plotting import save_figure

    plt = _pyplot()
    o, s = noise.orbit, noise.sound
    t = o.time
    written = []

    fig = plt.figure(figsize=(12, 7))
    grid = fig.add_gridspec(2, 2, width_ratios=(1, 1.3))
    o.plot(ax=fig.add_subplot(grid[:, 0]))
    ax = fig.add_subplot(grid[0, 1])
    ax.plot(t, o.x * 1e6, label="x")
    ax.plot(t, o.y * 1e6, label="y")
    ax.set_ylabel("displacement [um]")
    ax.legend()
    ax2 = fig.add_subplot(grid[1, 1], sharex=ax)
    v = o.ring_velocity
    ax2.plot(t, v[:, 0] * 1e3, label="x")
    ax2.plot(t, v[:, 1] * 1e3, label="y")
    ax2.set_ylabel("velocity [mm/s]")
    ax2.set_xlabel("time [s]")
    ax2.legend()
    fig.suptitle("fig. 9: inner-ring centre (720 rpm, 50 N, N_w = 7)")
    fig.tight_layout()
    written.append(save_figure(fig, out / "fig09_inner_ring.png"))

    pitch = 0.5 * o.bearing.pitch_diameter
    dx = o.ball_x - pitch * np.cos(o.ball_angle)
    dy = o.ball_y - pitch * np.sin(o.ball_angle)
    fig = _ball_figure(
        plt,
        t,
        o.ball_radial_displacement * 1e6,
        dx[:, 0] * 1e6,
        dy[:, 0] * 1e6,
        "radius - d_m/2 [um]",
        "displacement [um]",
        "fig. 10: ball centres (every ball: radial; ball 0: x and y)",
    )
    written.append(save_figure(fig, out / "fig10_ball_centres.png"))
    fig = _ball_figure(
        plt,
        t,
        o.ball_radial_velocity * 1e3,
        np.gradient(dx[:, 0], t) * 1e3,
        np.gradient(dy[:, 0], t) * 1e3,
        "d rho / dt [mm/s]",
        "velocity [mm/s]",
        "fig. 11: ball-centre velocities (pulsating-sphere sources)",
    )
    written.append(save_figure(fig, out / "fig11_ball_velocity.png"))

    fig, axes = plt.subplots(3, 1, figsize=(9, 9), sharex=True)
    rows = (("inner_ring_x", "inner_ring_y", "inner_ring"), ("balls",), ("total",))
    titles = ("fig. 12: inner ring", "fig. 13: balls", "fig. 14: inner ring and balls")
    for ax, parts, title in zip(axes, rows, titles, strict=True):
        for part in parts:
            if part in s.parts and np.any(s.parts[part]):
                level = s.spl_time(part)
                ax.plot(t, level, lw=0.8, label=f"{part}: mean {np.mean(level):.1f} dB")
        ax.set_ylabel("SPL [dB]")
        ax.set_title(title)
        ax.legend(fontsize=8)
    axes[2].axhline(
        PUBLISHED_MEAN_SPL_DB,
        color="k",
        ls=":",
        lw=0.8,
        label=f"paper's mean {PUBLISHED_MEAN_SPL_DB} dB",
    )
    axes[2].legend(fontsize=8)
    axes[2].set_xlabel("time [s]")
    fig.tight_layout()
    written.append(save_figure(fig, out / "fig12_14_spl_time.png"))

    kin = defect_frequencies(o.bearing, o.condition.shaft_speed)
    spec = s.spectrum()
    top = min(0.5 * s.sample_rate, 10.5 * kin.hz("bpfi"))
    names = ("shaft", "ftf", "bpfo", "bpfi", "bsf", "ball_defect")
    lines = match_peaks(
        find_peaks(spec, count=16, max_frequency=top, prominence=1.0),
        {n: kin.hz(n) for n in names},
        harmonics=10,
        slip_tolerance=0.0,
        resolution=spec.resolution,
    )
    fig, ax = plt.subplots(figsize=(10, 4.5))
    shown = spec.frequency <= top
    ax.plot(spec.frequency[shown], spec.amplitude[shown], color="0.3", lw=0.8)
    for i, name in enumerate(("bpfo", "bpfi")):
        marks = kin.hz(name) * np.arange(1, 11)
        ax.vlines(
            marks[marks <= top],
            0,
            spec.amplitude[shown].max(),
            colors=f"C{i}",
            linestyles="--",
            lw=0.8,
            label=f"{name.upper()} and harmonics",
        )
    for p in lines:
        if p["matched"]:
            ax.annotate(
                f"{p['harmonic']}x {p['matched']}",
                (p["frequency_hz"], p["amplitude"]),
                fontsize=7,
                rotation=60,
            )
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("pressure amplitude [Pa]")
    ax.set_title(
        "sound pressure at point A: spectrum (seed 002: lines at the ball-pass frequencies)"
    )
    ax.legend(fontsize=8)
    fig.tight_layout()
    written.append(save_figure(fig, out / "pressure_spectrum.png"))

    fig, _ = s.directivity().plot()
    written.append(save_figure(fig, out / "directivity.png"))
    return written


def sweep(points: int, quick: bool) -> dict:
    """Mean SPL for every value of every sweep: name -> (values, levels, noise results)."""
    out = {}
    for name, (_, _, _, values) in SWEEPS.items():
        chosen = (values[0], values[-1]) if quick else values
        runs = [run(points, **(BASE | {name: v})) for v in chosen]
        out[name] = (chosen, [r.to_dict()["spl_time_mean_db"] for r in runs], runs)
    return out


def draw_sweeps(results: dict, out: Path) -> list[Path]:
    from bearinglab.plotting import save_figure

    plt = _pyplot()
    written = []
    for name, (values, levels, runs) in results.items():
        label, scale, unit, _ = SWEEPS[name]
        x = np.asarray(values, float) / scale
        if name == "order":  # figs. 15-16: SPL over time per number, then the means
            fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
            for v, r in zip(values, runs, strict=True):
                ax1.plot(r.sound.time, r.sound.spl_time(), lw=0.7, label=f"N_w = {v}")
            ax1.set_xlabel("time [s]")
            ax1.set_ylabel("SPL [dB]")
            ax1.legend(fontsize=8)
            ax = ax2
        else:
            fig, ax = plt.subplots(figsize=(6, 4.5))
        ax.plot(x, levels, "o-")
        ax.set_xlabel(f"{label}{f' [{unit}]' if unit else ''}")
        ax.set_ylabel("mean SPL at point A [dB]")
        ax.set_title(f"{FIGURE_TITLE[name]}: mean SPL against {label}")
        ax.grid(alpha=0.3)
        fig.tight_layout()
        written.append(save_figure(fig, out / f"{FIGURE_OF[name]}.png"))
    return written


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "out", nargs="?", default="figures_608", help="output directory (./figures_608)"
    )
    parser.add_argument(
        "--points", type=int, default=1024, help="instants per run over one cage revolution (1024)"
    )
    parser.add_argument("--quick", action="store_true", help="two values per sweep")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    base = run(args.points, **BASE)
    written = draw_base(base, out)
    d = base.to_dict()
    print(
        f"608, 720 rpm, 50 N, N_w = 7, 0.2 um, 2 um band: mean SPL "
        f"{d['spl_time_mean_db']:.1f} dB (paper {PUBLISHED_MEAN_SPL_DB} dB), L_eq inner ring "
        f"{d['spl_leq_inner_ring_db']:.1f} dB, balls {d['spl_leq_balls_db']:.1f} dB"
    )
    results = sweep(args.points, args.quick)
    for name, (values, levels, _) in results.items():
        label, scale, unit, _ = SWEEPS[name]
        pairs = ", ".join(
            f"{v / scale:g}{unit and ' ' + unit}: {lv:.1f}"
            for v, lv in zip(values, levels, strict=True)
        )
        print(f"mean SPL [dB] against {label}: {pairs}")
    written += draw_sweeps(results, out)
    print(f"{len(written)} figures in {out} ({time.perf_counter() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
