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

import dataclasses

import numpy as np

from ..errors import ConvergenceError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from .gyroscopic import gyroscopic_ball_force
from .result import LoadDistribution
from .solver import (
    CENTRIFUGAL_FLOOR,
    DOF_NAMES,
    centrifugal_force,
    inner_ring_expansion,
    solve,
)

__all__ = ["DOF_NAMES", "LoadDistribution", "centrifugal_force", "inner_ring_expansion",
           "solve_load_distribution"]


def solve_load_distribution(bearing: BallBearing, condition: OperatingCondition, *,
                            ball_phase: float | None = None, ball_diameter_errors=None,
                            film=None, lubricant=None, temperature: float | None = None,
                            gyroscopic: bool = False, ring_expansion: bool = False,
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
        EHL film thickness of each contact [m]: a layer between the surfaces, so for given
        groove centres it adds to the elastic approach (seed 001 eq. 2: the centre
        distance is R_e + R_n - D_w + delta_e + delta_n - h_e - h_n).
    lubricant : bearinglab.lubrication.Lubricant, optional
        When given (and ``film`` is not), the film of every contact is the Hamrock-Dowson
        central film at its own load, contact angle and entrainment speed, iterated with
        the load distribution until it changes by less than 1 nm.
    temperature : float, optional
        Lubricant inlet temperature [K]; the lubricant's reference temperature by default.
    gyroscopic : bool
        Include the balls' gyroscopic moments, held by friction at the outer raceway
        (outer-raceway control, :mod:`bearinglab.quasistatic.gyroscopic`), iterated with
        the load distribution.
    ring_expansion : bool
        Reduce the clearance by the inner ring's centrifugal expansion at this speed
        (:func:`bearinglab.quasistatic.solver.inner_ring_expansion`); the result's
        ``bearing`` then carries the operating clearance.
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
    if ring_expansion and condition.shaft_speed > 0:
        shrink = 2.0 * inner_ring_expansion(bearing, condition.shaft_speed)
        bearing = dataclasses.replace(bearing, diametral_clearance=bearing.diametral_clearance
                                      - shrink)
    kwargs = {"ball_phase": ball_phase, "ball_diameter_errors": ball_diameter_errors,
              "tolerance": tolerance}
    u, b, state, problem, stiffness = solve(bearing, condition, film=film, initial=initial,
                                            **kwargs)
    with_film = lubricant is not None and film is None and condition.shaft_speed > 0
    with_gyro = gyroscopic and condition.shaft_speed > 0
    if with_film or with_gyro:
        # film and gyroscopic friction depend on the loads and contact angles they change:
        # iterate to a fixed point (both depend weakly on them)
        def couplings(state):
            h = (contact_films(bearing, lubricant, condition.shaft_speed,
                               problem.contacts.ring, state, temperature) if with_film else film)
            f = gyroscopic_forces(bearing, condition.shaft_speed, problem.contacts.ring,
                                  state) if with_gyro else None
            return h, f

        h, f = couplings(state)
        for _ in range(20):
            u, b, state, problem, stiffness = solve(bearing, condition, film=h, ball_force=f,
                                                    initial=u, **kwargs)
            h_new, f_new = couplings(state)
            settled = (not with_film or np.max(np.abs(h_new - h)) < 1e-9) and (
                not with_gyro or np.max(np.abs(f_new - f)) <= 1e-6 * max(
                    1.0, float(np.max(np.abs(f)))))
            h, f = h_new, f_new
            if settled:
                break
        else:
            raise ConvergenceError("the EHL film / gyroscopic friction and the load "
                                   "distribution did not settle within 20 passes")
    q, n_rho, n_z, delta, _ = state
    if centrifugal_force(bearing, condition.shaft_speed) < CENTRIFUGAL_FLOOR:
        q = np.where(q <= 10 * CENTRIFUGAL_FLOOR, 0.0, q)   # the floor is not a real load
    ring = problem.contacts.ring
    # sign: + when the line from the inner to the outer contact leans towards +z
    angle = signed_contact_angles(ring, n_rho, n_z)
    force, _ = problem.ring_force_and_stiffness(state)
    result = LoadDistribution(
        bearing=bearing, condition=condition, displacement=u, ball_angle=problem.psi,
        ball_centre=b, ring=ring, load=q, approach=delta, contact_angle=angle,
        film=problem.film, stiffness_matrix=stiffness, reaction=force,
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


def gyroscopic_forces(bearing: BallBearing, shaft_speed: float, ring, state) -> np.ndarray:
    """Gyroscopic friction force on every ball (Z, 2) [N] from the load-weighted contact
    angles of its inner and outer contacts (outer-raceway control); balls without a loaded
    inner and outer contact get none.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and ball material.
    shaft_speed : float
        Inner-ring speed [rad/s].
    ring : array (C,)
        0 inner, 1 outer for each contact column.
    state : tuple
        (loads, n_rho, n_z, ...) of the solver [N, -, -].
    """
    q, n_rho, n_z = state[:3]
    angle = signed_contact_angles(ring, n_rho, n_z)
    picks = {}
    for race in (0, 1):
        cols = ring == race
        total = q[:, cols].sum(axis=1)
        # load-weighted angle: a ball held in both halves of an arch spins about a nearly
        # radial-symmetric axis (no gyroscopic moment); the weighting keeps this continuous
        mean = np.where(total > 0, (q[:, cols] * angle[:, cols]).sum(axis=1)
                        / np.where(total > 0, total, 1.0), 0.0)
        picks[race] = (mean, total > 0)
    force = gyroscopic_ball_force(bearing.ball_diameter, bearing.pitch_diameter,
                                  bearing.ball_material.density, shaft_speed,
                                  picks[0][0], picks[1][0])
    force[~(picks[0][1] & picks[1][1])] = 0.0
    return force


def signed_contact_angles(ring, n_rho, n_z) -> np.ndarray:
    """Contact angles [rad], positive when the line from the inner to the outer contact
    leans towards +z (docs/conventions.md), from the solver's contact normals n = b - c.

    Parameters
    ----------
    ring : array (C,)
        0 inner, 1 outer for each contact column.
    n_rho, n_z : arrays (Z, C)
        Unit normals from the groove centre to the ball centre [-].
    """
    sigma = np.where(ring == 0, -1.0, 1.0)
    return np.arctan2(sigma * n_z, np.abs(n_rho)) + 0.0     # + 0.0: no "-0"
