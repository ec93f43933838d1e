"""Simulated series of recordings to test a trend against (layer 3).

:func:`simulate_series` writes a folder that :func:`~bearinglab.trend.trend_records`
reads: one short record simulated by :func:`bearinglab.dynamics.simulate` per time step
(seed 003's rigid model), each with its own shaft speed (a small random scatter around
the nominal, as a real drive wanders), its own start in the cage's cycle (the settling
time drawn at random, so that the records are not copies of each other) and white
measurement noise on both accelerations; the defects that are present at each record
follow a schedule of steps, so that a defect can appear and grow (width and depth
stepping up). Records are .npz files with an ``index.csv`` of their times.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..errors import InputError, positive_number

#: Relative scatter of the shaft speed from record to record [-].
SPEED_SCATTER = 0.005


def simulate_series(
    folder,
    bearing,
    condition,
    *,
    records: int,
    spacing: float = 10.0,
    steps=(),
    noise: float = 1.0,
    duration: float = 0.1,
    sample_rate: float = 25600.0,
    seed: int = 0,
) -> Path:
    """Write a simulated series of ``records`` recordings to ``folder`` (created).

    Parameters
    ----------
    folder : str or Path
        Where to write ``r00000.npz``... and ``index.csv``; must not hold records yet.
    bearing : BallBearing
        The bearing.
    condition : OperatingCondition
        Load and nominal shaft speed [rad/s].
    records : int
        Number of records (>= 1).
    spacing : float
        Time between records [s].
    steps : sequence of (int, Defect or sequence of Defect)
        From record ``k`` on, the bearing has these defects (until the next step); no
        step: healthy.
    noise : float
        r.m.s. of the white measurement noise on each channel [m/s²].
    duration, sample_rate : float
        Length of each record [s] and its sample rate [Hz].
    seed : int
        Seed of the speed scatter, the settling times and the noise.

    Returns
    -------
    Path
        The folder.
    """
    from ..dynamics import simulate
    from ..signal import Signal, write_signal

    if isinstance(records, bool) or not isinstance(records, (int, np.integer)) or records < 1:
        raise InputError("records", records, "an integer >= 1")
    spacing = positive_number("spacing", spacing, "a time between records > 0 [s]")
    noise = positive_number("noise", noise, "an r.m.s. >= 0 [m/s^2]", zero=True)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    if any(folder.glob("*.npz")):
        raise InputError("folder", str(folder), "a folder without records yet")
    schedule = sorted(
        (int(k), (d,) if not isinstance(d, (list, tuple)) else tuple(d)) for k, d in steps
    )
    rng = np.random.default_rng(seed)
    rows = ["file,time_s"]
    for k in range(int(records)):
        defects = ()
        for first, d in schedule:
            if k >= first:
                defects = d
        speed = condition.shaft_speed * (1.0 + SPEED_SCATTER * rng.standard_normal())
        sim = simulate(
            bearing,
            replace(condition, shaft_speed=speed),
            defects,
            duration=duration,
            sample_rate=sample_rate,
            settle=0.05 + 2 * math.pi / speed * rng.random(),
        )
        channels = {
            name: sim.signal.channel(name) + noise * rng.standard_normal(sim.signal.n_samples)
            for name in ("acc_y", "acc_x")
        }
        name = f"r{k:05d}.npz"
        write_signal(
            folder / name,
            Signal(channels, sim.signal.sample_rate, {"speed_rpm": speed * 30 / math.pi}),
        )
        rows.append(f"{name},{k * spacing:.6g}")
    (folder / "index.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    return folder
