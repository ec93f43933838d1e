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

import math

import numpy as np

from ..geometry import BallBearing
from ..operating import OperatingCondition
from .result import LoadDistribution
from .solver import DOF_NAMES, centrifugal_force, solve

__all__ = ["DOF_NAMES", "LoadDistribution", "centrifugal_force", "solve_load_distribution"]


def solve_load_distribution(bearing: BallBearing, condition: OperatingCondition, *,
                            ball_phase: float | None = None, ball_diameter_errors=None,
                            film=None, tolerance: float = 1e-9) -> LoadDistribution:
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
    tolerance : float
        Ring equilibrium tolerance relative to the load [-].

    Returns
    -------
    LoadDistribution

    Raises
    ------
    ConvergenceError
        When the ball or ring equilibrium cannot be found (e.g. a load the bearing cannot
        carry); the message names the load and the residual.
    """
    u, b, state, problem, stiffness = solve(bearing, condition, ball_phase=ball_phase,
                                            ball_diameter_errors=ball_diameter_errors,
                                            film=film, tolerance=tolerance)
    q, n_rho, n_z, delta, _ = state
    ring = problem.contacts.ring
    # sign: + when the line from the inner to the outer contact leans towards +z
    sigma = np.where(ring == 0, -1.0, 1.0)
    angle = np.arctan2(sigma * n_z, np.abs(n_rho))
    force, _ = problem.ring_force_and_stiffness(state)
    result = LoadDistribution(
        bearing=bearing, condition=condition, displacement=u, ball_angle=problem.psi,
        ball_centre=b, ring=ring, load=q, approach=delta, contact_angle=angle,
        film=problem.film, stiffness_matrix=stiffness, reaction=force,
        shoulder_angle=problem.contacts.shoulder_angle,
        groove_radius=problem.contacts.groove_radius)
    warnings = []
    if np.any(result.truncated):
        n = int(np.count_nonzero(np.any(result.truncated, axis=1)))
        warnings.append(f"the contact ellipse of {n} ball(s) runs over the groove shoulder: "
                        "Hertz theory no longer holds there and the load is beyond what "
                        "the groove can carry properly")
    if bearing.diametral_clearance < 0:
        warnings.append(f"preloaded: diametral clearance {bearing.diametral_clearance * 1e6:.3g}"
                        " um")
    object.__setattr__(result, "warnings", tuple(warnings))
    return result


