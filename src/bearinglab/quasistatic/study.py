"""Stiffness over a grid of loads and speeds (layer 3), in parallel processes.

Each (axial load, speed) line is one task: its radial loads are solved in ascending order,
each starting from the previous solution (a warm start: two or three Newton steps instead
of a cold start's ten). Lines are spread over worker processes with
``concurrent.futures`` (a machine's cores; a Dask cluster is the route for larger studies).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pandas as pd

from ..errors import ConvergenceError, InputError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from . import solve_load_distribution

COLUMNS = ("radial_load_n", "axial_load_n", "speed_rpm", "radial_displacement_um",
           "axial_displacement_um", "radial_stiffness_n_per_um", "axial_stiffness_n_per_um",
           "max_ball_load_n", "status")


def _line(args) -> list[dict]:
    bearing, radial_loads, axial_load, rpm, angle = args
    rows, initial = [], None
    for fr in np.sort(radial_loads):
        row = {"radial_load_n": float(fr), "axial_load_n": float(axial_load),
               "speed_rpm": float(rpm)}
        if fr == 0 and axial_load == 0:
            rows.append({**row, "status": "no load"})
            initial = None
            continue
        condition = OperatingCondition(radial_load=float(fr), radial_load_angle=angle,
                                       axial_load=float(axial_load),
                                       shaft_speed=rpm * math.pi / 30)
        try:
            r = solve_load_distribution(bearing, condition, initial=initial)
        except ConvergenceError as exc:
            rows.append({**row, "status": f"not converged: {exc}"})
            initial = None
            continue
        initial = r.displacement
        rows.append({**row, "radial_displacement_um": r.radial_displacement * 1e6,
                     "axial_displacement_um": r.axial_displacement * 1e6,
                     "radial_stiffness_n_per_um": r.radial_stiffness * 1e-6,
                     "axial_stiffness_n_per_um": r.axial_stiffness * 1e-6,
                     "max_ball_load_n": float(r.load.max()), "status": "ok"})
    return rows


def stiffness_map(bearing: BallBearing, radial_loads, axial_loads, speeds_rpm, *,
                  radial_load_angle: float = -0.5 * math.pi, workers: int | None = None,
                  progress: Callable[[int], None] | None = None) -> pd.DataFrame:
    """C_r, C_a and displacements over every (radial load, axial load, speed).

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    radial_loads, axial_loads : sequences of float
        Loads [N] (radial >= 0).
    speeds_rpm : sequence of float
        Inner-ring speeds [rpm].
    radial_load_angle : float
        Direction of the radial load [rad].
    workers : int, optional
        Worker processes; 1 solves in this process; default: the machine's cores.
    progress : callable, optional
        Called with the number of cases just finished.

    Returns
    -------
    pandas.DataFrame
        One row per case, columns COLUMNS; ``status`` is "ok", "no load" or why not.
    """
    radial = np.asarray(radial_loads, float)
    if radial.ndim != 1 or not np.all(np.isfinite(radial)) or np.any(radial < 0):
        raise InputError("radial_loads", radial_loads, "finite loads >= 0 [N]")
    tasks = [(bearing, radial, float(fa), float(rpm), radial_load_angle)
             for rpm in speeds_rpm for fa in axial_loads]
    workers = workers or os.cpu_count() or 1
    rows = []
    if workers == 1 or len(tasks) == 1:
        for task in tasks:
            rows.extend(_line(task))
            if progress:
                progress(len(radial))
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            for line in pool.map(_line, tasks):
                rows.extend(line)
                if progress:
                    progress(len(radial))
    return pd.DataFrame(rows, columns=list(COLUMNS))
