"""Stiffness over a grid of loads and speeds (layer 3), in parallel processes.

Each (axial load, speed) line is one task: its radial loads are solved in ascending order,
each starting from the previous solution (a warm start: two or three Newton steps instead
of a cold start's ten). For a ball bearing, after the line's first case the rest go to the
compiled ring iteration in one call (solver.solve_line); a case it cannot solve goes to
the full solver, with its load and speed continuations, and the line carries on from
there. A roller bearing's line is solved case by case by the slice model, each from the
previous ring displacement. Lines run on the engine (:func:`bearinglab.engine.open_jobs`:
this process or a pool of the machine's cores; a Dask cluster is the route for larger
studies, through :mod:`bearinglab.study`).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable

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


def columns(bearing) -> tuple[str, ...]:
    """The map's columns for ``bearing``: COLUMNS, with max_roller_load_n for a roller
    bearing."""
    if getattr(bearing, "rolling_element", "ball") != "roller":
        return COLUMNS
    return tuple("max_roller_load_n" if c == "max_ball_load_n" else c for c in COLUMNS)


def _line(args) -> list[dict]:
    bearing, radial_loads, axial_load, rpm, angle, options = args
    roller = getattr(bearing, "rolling_element", "ball") == "roller"
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
        batch = not roller and solver.COMPILED_RING and options["race_control"] != "hybrid"
        if state is not None and batch:
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
        except InputError as exc:  # a load this bearing cannot take (a lone tapered row)
            rows.append({**row, "status": f"not solved: {exc}"})
            state = None
            i += 1
            continue
        state = (r.displacement, None if roller else r.ball_centre)
        rows.append(
            {
                **row,
                "radial_displacement_um": r.radial_displacement * 1e6,
                "axial_displacement_um": r.axial_displacement * 1e6,
                "radial_stiffness_n_per_um": r.radial_stiffness * 1e-6,
                "axial_stiffness_n_per_um": r.axial_stiffness * 1e-6,
                ("max_roller_load_n" if roller else "max_ball_load_n"): (
                    r.max_roller_load if roller else float(r.load.max())
                ),
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
    progress: Callable[[int, int], None] | None = None,
    gyroscopic: bool = False,
    race_control: str = "outer",
):
    """C_r, C_a and displacements over every (radial load, axial load, speed).

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
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
        ``progress(done, total)`` in cases, as the engine tells it.
    gyroscopic, race_control :
        As for :func:`bearinglab.quasistatic.solve_load_distribution`; ball bearings
        only [-].

    Returns
    -------
    pandas.DataFrame
        One row per case, columns :func:`columns`; ``status`` is "ok", "no load" or why
        not.
    """
    radial = np.asarray(radial_loads, float)
    if radial.ndim != 1 or not np.all(np.isfinite(radial)) or np.any(radial < 0):
        raise InputError("radial_loads", radial_loads, "finite loads >= 0 [N]")
    if race_control not in solver.RACE_CONTROLS:
        raise InputError("race_control", race_control, " or ".join(map(repr, solver.RACE_CONTROLS)))
    options = {"gyroscopic": bool(gyroscopic), "race_control": race_control}
    if getattr(bearing, "rolling_element", "ball") == "roller":
        for name, moot in (("gyroscopic", gyroscopic), ("race_control", race_control != "outer")):
            if moot:
                raise InputError(
                    name, options[name], "its default for a roller bearing", "ball bearings only"
                )
    tasks = [
        (i, (bearing, radial, float(fa), float(rpm), radial_load_angle, options))
        for i, (rpm, fa) in enumerate((r, a) for r in speeds_rpm for a in axial_loads)
    ]
    lines: list = [[] for _ in tasks]

    def keep(task, rows) -> None:
        lines[task[0]] = rows

    from ..engine import check_workers, open_jobs, run_partitions

    jobs = min(check_workers("workers", workers or os.cpu_count() or 1), len(tasks))
    with open_jobs(max(jobs, 1)) as runner:
        run_partitions(runner, _task, tasks, [len(radial)] * len(tasks), keep, progress=progress)
    import pandas as pd

    return pd.DataFrame([r for line in lines for r in line], columns=list(columns(bearing)))


def _task(task) -> list[dict]:
    return _line(task[1])
