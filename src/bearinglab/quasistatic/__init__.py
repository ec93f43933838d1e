"""Quasi-static load distribution and stiffness of ball bearings (seed 001, seed 002
eqs. 1-5, seed 003 noise section eqs. 1-8).

>>> import math
>>> from bearinglab.geometry import BallBearing
>>> from bearinglab.operating import OperatingCondition
>>> b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
>>> r = solve_load_distribution(b, OperatingCondition(radial_load=1000.0))
>>> round(r.to_dict()["max_ball_load_n"])    # Stribeck: 4.37 F_r / Z = 486 N
487
"""

from __future__ import annotations

import numpy as np

from ..errors import ConvergenceError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from .result import LoadDistribution
from .solver import CENTRIFUGAL_FLOOR, DOF_NAMES, centrifugal_force, solve

__all__ = ["DOF_NAMES", "LoadDistribution", "centrifugal_force", "solve_load_distribution"]


def solve_load_distribution(bearing: BallBearing, condition: OperatingCondition, *,
                            ball_phase: float | None = None, ball_diameter_errors=None,
                            film=None, lubricant=None, temperature: float | None = None,
                            tolerance: float = 1e-9, initial=None) -> LoadDistribution:
    """Quasi-static equilibrium of ``bearing`` under ``condition``.

    Parameters
    ----------
    bearing : BallBearing
        Geometry, clearance (P_d < 0 is a preload), arch angles of four-point bearings.
    condition : OperatingCondition
        Loads, imposed misalignments and shaft speed.
    ball_phase : float, optional
        Azimuth of ball 1 [rad]; by default the direction of the radial load (a ball
        under the load, seed 001's phi_0 = 0). Sweep it over 2 pi / Z for the orbit.
    ball_diameter_errors : array (Z,), optional
        D_wj - D_w of each ball [m] (seed 003 noise section eq. 7).
    film : float or array (Z, C), optional
        EHL film thickness subtracted from each contact's approach [m] (seed 001 eq. 2).
    lubricant : bearinglab.lubrication.Lubricant, optional
        When given (and ``film`` is not), the film of every contact is the Hamrock-Dowson
        central film at its own load, contact angle and entrainment speed, iterated with
        the load distribution until it changes by less than 1 nm.
    temperature : float, optional
        Lubricant inlet temperature [K]; the lubricant's reference temperature by default.
    tolerance : float
        Ring equilibrium tolerance relative to the load [-].
    initial : array (5,), optional
        Starting ring displacement (e.g. the solution of a nearby case) [m, rad].

    Returns
    -------
    LoadDistribution

    Raises
    ------
    ConvergenceError
        When the ball or ring equilibrium cannot be found (e.g. a load the bearing cannot
        carry); the message names the load and the residual.
    """
    kwargs = {"ball_phase": ball_phase, "ball_diameter_errors": ball_diameter_errors,
              "tolerance": tolerance}
    u, b, state, problem, stiffness = solve(bearing, condition, film=film, initial=initial,
                                            **kwargs)
    if lubricant is not None and film is None and condition.shaft_speed > 0:
        for _ in range(10):
            film = contact_films(bearing, lubricant, condition.shaft_speed, problem.contacts.ring,
                                 state, temperature)
            u, b, state, problem, stiffness = solve(bearing, condition, film=film, initial=u,
                                                    **kwargs)
            if np.max(np.abs(problem.film - contact_films(
                    bearing, lubricant, condition.shaft_speed, problem.contacts.ring, state,
                    temperature))) < 1e-9:
                break
        else:
            raise ConvergenceError("the EHL film and the load distribution did not settle "
                                   "within 10 passes")
    q, n_rho, n_z, delta, _ = state
    if centrifugal_force(bearing, condition.shaft_speed) < CENTRIFUGAL_FLOOR:
        q = np.where(q <= 10 * CENTRIFUGAL_FLOOR, 0.0, q)   # the floor is not a real load
    ring = problem.contacts.ring
    # sign: + when the line from the inner to the outer contact leans towards +z
    sigma = np.where(ring == 0, -1.0, 1.0)
    angle = np.arctan2(sigma * n_z, np.abs(n_rho)) + 0.0     # + 0.0: no "-0"
    force, _ = problem.ring_force_and_stiffness(state)
    result = LoadDistribution(
        bearing=bearing, condition=condition, displacement=u, ball_angle=problem.psi,
        ball_centre=b, ring=ring, load=q, approach=delta, contact_angle=angle,
        film=problem.film, stiffness_matrix=stiffness, reaction=force,
        shoulder_angle=problem.contacts.shoulder_angle,
        groove_radius=problem.contacts.groove_radius)
    return result


def contact_films(bearing: BallBearing, lubricant, shaft_speed: float, ring, state,
                  temperature: float | None = None) -> np.ndarray:
    """Hamrock-Dowson central film of every (ball, contact) at its load and angle [m].

    Unloaded contacts get the film of a light load (1 % of the largest contact load, at
    least 1 mN): the film that would form as they engage.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and materials.
    lubricant : bearinglab.lubrication.Lubricant
        The lubricant.
    shaft_speed : float
        Inner-ring speed [rad/s].
    ring : array (C,)
        0 inner, 1 outer for each contact column.
    state : tuple
        (loads, n_rho, n_z, ...) of the solver [N, -, -].
    temperature : float, optional
        Inlet temperature [K].
    """
    from ..lubrication import film_thickness

    q, n_rho = state[0], state[1]
    light = max(1e-2 * float(np.max(q)), 1e-3)
    angle = np.arccos(np.clip(np.abs(n_rho), 0.0, 1.0))
    film = np.empty_like(q)
    for race, name in ((0, "inner"), (1, "outer")):
        cols = ring == race
        film[:, cols] = film_thickness(bearing, lubricant, np.maximum(q[:, cols], light),
                                       shaft_speed, name, temperature=temperature,
                                       contact_angle=angle[:, cols], kind="central")
    return film
