"""Stiffness over a grid of loads and speeds (layer 3), in parallel processes.

Each (axial load, speed) line is one task: its radial loads are solved in ascending order,
each starting from the previous solution (a warm start: two or three Newton steps instead
of a cold start's ten). After the line's first case, the rest go to the compiled ring
iteration in one call (solver.solve_line); a case it cannot solve goes to the full solver,
with its load and speed continuations, and the line carries on from there. Lines are
spread over worker processes with ``concurrent.futures`` (a machine's cores; a Dask
cluster is the route for larger studies).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor

import numpy as np

from ..errors import ConvergenceError, InputError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from . import solve_load_distribution, solver
from .solver import _Problem, solve_line

COLUMNS = (
    "radial_load_n",
    "axial_load_n",
    "speed_rpm",
    "radial_displacement_um",
    "axial_displacement_um",
    "radial_stiffness_n_per_um",
    "axial_stiffness_n_per_um",
    "max_ball_load_n",
    "status",
)


def _line(args) -> list[dict]:
    bearing, radial_loads, axial_load, rpm, angle, options = args
    loads = np.sort(np.asarray(radial_loads, float))
    rows, state = [], None  # state: (ring displacement, ball centres) to go on from
    i = 0
    while i < len(loads):
        fr = float(loads[i])
        row = {"radial_load_n": fr, "axial_load_n": float(axial_load), "speed_rpm": float(rpm)}
        if fr == 0 and axial_load == 0:
            rows.append({**row, "status": "no load"})
            state = None
            i += 1
            continue
        if state is not None and solver.COMPILED_RING and options["race_control"] != "hybrid":
            # the rest of the line in one compiled call, each case from the previous one
            done, state = _batch(bearing, loads[i:], axial_load, rpm, angle, state, rows, options)
            i += done
            if i >= len(loads):
                break
            fr = float(loads[i])
            row = {"radial_load_n": fr, "axial_load_n": float(axial_load), "speed_rpm": float(rpm)}
        condition = OperatingCondition(
            radial_load=fr,
            radial_load_angle=angle,
            axial_load=float(axial_load),
            shaft_speed=rpm * math.pi / 30,
        )
        try:  # a cold start, or the case the batch stopped at (with the load continuation)
            r = solve_load_distribution(
                bearing, condition, initial=None if state is None else state[0], **options
            )
        except ConvergenceError as exc:
            rows.append({**row, "status": f"not converged: {exc}"})
            state = None
            i += 1
            continue
        state = (r.displacement, r.ball_centre)
        rows.append(
            {
                **row,
                "radial_displacement_um": r.radial_displacement * 1e6,
                "axial_displacement_um": r.axial_displacement * 1e6,
                "radial_stiffness_n_per_um": r.radial_stiffness * 1e-6,
                "axial_stiffness_n_per_um": r.axial_stiffness * 1e-6,
                "max_ball_load_n": float(r.load.max()),
                "status": "ok",
            }
        )
        i += 1
    return rows


def _batch(bearing, radial_loads, axial_load, rpm, angle, state, rows, options):
    """Solve radial loads (all > 0) from ``state`` in one compiled call; append their rows
    and return how many were solved and the state to go on from. The case it stops at is
    left to the full solver (which has the load and speed continuations)."""
    condition = OperatingCondition(
        radial_load=float(radial_loads[0]),
        radial_load_angle=angle,
        axial_load=float(axial_load),
        shaft_speed=rpm * math.pi / 30,
    )
    problem = _Problem(bearing, condition, angle, None, None, **options)
    e = np.array([math.cos(angle), math.sin(angle)])
    vectors = np.zeros((len(radial_loads), 5))
    vectors[:, 0], vectors[:, 1] = radial_loads * e[0], radial_loads * e[1]
    vectors[:, 2] = axial_load
    us, ks, qmax, status, balls = solve_line(problem, vectors, state[0], state[1])
    done = int(np.argmax(status != 0)) if np.any(status != 0) else len(status)
    for k in range(done):
        rows.append(
            {
                "radial_load_n": float(radial_loads[k]),
                "axial_load_n": float(axial_load),
                "speed_rpm": float(rpm),
                "radial_displacement_um": float(us[k, :2] @ e) * 1e6,
                "axial_displacement_um": us[k, 2] * 1e6,
                "radial_stiffness_n_per_um": float(e @ ks[k, :2, :2] @ e) * 1e-6,
                "axial_stiffness_n_per_um": ks[k, 2, 2] * 1e-6,
                "max_ball_load_n": float(qmax[k]),
                "status": "ok",
            }
        )
    if done:
        state = (us[done - 1], balls)
    return done, state


def stiffness_map(
    bearing: BallBearing,
    radial_loads,
    axial_loads,
    speeds_rpm,
    *,
    radial_load_angle: float = -0.5 * math.pi,
    workers: int | None = None,
    progress: Callable[[int], None] | None = None,
    gyroscopic: bool = False,
    race_control: str = "outer",
):
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
    gyroscopic, race_control :
        As for :func:`bearinglab.quasistatic.solve_load_distribution` [-].

    Returns
    -------
    pandas.DataFrame
        One row per case, columns COLUMNS; ``status`` is "ok", "no load" or why not.
    """
    radial = np.asarray(radial_loads, float)
    if radial.ndim != 1 or not np.all(np.isfinite(radial)) or np.any(radial < 0):
        raise InputError("radial_loads", radial_loads, "finite loads >= 0 [N]")
    if race_control not in solver.RACE_CONTROLS:
        raise InputError("race_control", race_control, " or ".join(map(repr, solver.RACE_CONTROLS)))
    options = {"gyroscopic": bool(gyroscopic), "race_control": race_control}
    tasks = [
        (bearing, radial, float(fa), float(rpm), radial_load_angle, options)
        for rpm in speeds_rpm
        for fa in axial_loads
    ]
    workers = workers or os.cpu_count() or 1
    rows = []
    if workers == 1 or len(tasks) == 1:
        for task in tasks:
            rows.extend(_line(task))
            if progress:
                progress(len(radial))
    else:
        from ..engine import deferred_interrupts

        with ProcessPoolExecutor(max_workers=workers) as pool:
            with deferred_interrupts():  # the workers never see a Ctrl-C: this process stops
                lines = pool.map(_line, tasks)
            for line in lines:
                rows.extend(line)
                if progress:
                    progress(len(radial))
    import pandas as pd

    return pd.DataFrame(rows, columns=list(COLUMNS))
