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
import math

import numpy as np

from ..errors import ConvergenceError, InputError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from .result import LoadDistribution
from .roller import roller_centrifugal_force, solve_roller_distribution
from .roller_result import RollerLoadDistribution
from .solver import (
    CENTRIFUGAL_FLOOR,
    DOF_NAMES,
    RACE_CONTROLS,
    centrifugal_force,
    inner_ring_expansion,
    solve,
)

__all__ = [
    "DOF_NAMES",
    "MAX_SPEED_FACTOR",
    "RACE_CONTROLS",
    "LoadDistribution",
    "RollerLoadDistribution",
    "centrifugal_force",
    "inner_ring_expansion",
    "roller_centrifugal_force",
    "solve_load_distribution",
    "solve_roller_distribution",
    "speed_limit",
]


#: Highest n d_m the model is validated for [mm/min] (Harris's 218 bearing, 20 000 rpm, is
#: 2.5e6; the property tests run to this limit). Above it the balls' centrifugal force
#: swamps the contact loads and the quasi-static model gives balls flipped to the unloaded
#: side instead of an answer.
MAX_SPEED_FACTOR = 3.0e6


def speed_limit(bearing: BallBearing) -> float:
    """Highest shaft speed this model answers for ``bearing``, n d_m = MAX_SPEED_FACTOR
    [rad/s].

    Parameters
    ----------
    bearing : BallBearing
        The bearing; its pitch diameter d_m sets the limit.

    Returns
    -------
    float
        The speed [rad/s] at which n d_m reaches MAX_SPEED_FACTOR (n in rpm, d_m in mm).
    """
    return MAX_SPEED_FACTOR / (bearing.pitch_diameter * 1e3) * math.pi / 30.0


def check_speed(
    bearing: BallBearing,
    shaft_speed: float,
    hint: str = "beyond it the quasi-static model is not valid: centrifugal force "
    "swamps the contact loads",
) -> None:
    """Refuse a shaft speed [rad/s] above :func:`speed_limit` (InputError named
    ``shaft_speed``, the limit in rpm); ``hint`` says why."""
    limit = speed_limit(bearing)
    if abs(shaft_speed) > limit * (1 + 1e-12):
        # in rpm, the unit a speed limit is read in (n d_m); the request restates it
        raise InputError(
            "shaft_speed",
            float(f"{abs(shaft_speed) * 30 / math.pi:.6g}"),
            "at most {limit} for this bearing (n d_m <= "
            f"{MAX_SPEED_FACTOR:.0e} mm/min with d_m = "
            f"{bearing.pitch_diameter * 1e3:.4g} mm)",
            hint,
            unit="rpm",
            numbers={"limit": limit * 30 / math.pi},
        )


def solve_load_distribution(
    bearing: BallBearing,
    condition: OperatingCondition,
    *,
    ball_phase: float | None = None,
    ball_diameter_errors=None,
    film=None,
    lubricant=None,
    temperature: float | None = None,
    gyroscopic: bool = False,
    ring_expansion: bool = False,
    tolerance: float = 1e-9,
    initial=None,
    race_control: str = "outer",
    slices: int | None = None,
    axial_displacement: float | None = None,
) -> LoadDistribution:
    """Quasi-static equilibrium of ``bearing`` under ``condition``.

    A roller bearing (``bearing.rolling_element == "roller"``) is solved by the slice model
    of :func:`bearinglab.quasistatic.roller.solve_roller_distribution` and gives a
    :class:`~bearinglab.quasistatic.roller_result.RollerLoadDistribution` (the same keys
    with "roller" for "ball"); the ball-only options must keep their defaults then.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        Geometry, clearance (P_d < 0 is a preload), arch angles of four-point bearings.
    condition : OperatingCondition
        Loads, imposed misalignments and shaft speed (n d_m up to 3e6 mm/min).
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
        Include the balls' gyroscopic moments, held by friction at the controlling raceway
        (:mod:`bearinglab.quasistatic.gyroscopic`).
    ring_expansion : bool
        Reduce the clearance by the inner ring's centrifugal expansion at this speed
        (:func:`bearinglab.quasistatic.solver.inner_ring_expansion`); the result's
        ``bearing`` then carries the operating clearance.
    tolerance : float
        Ring equilibrium tolerance relative to the load [-].
    initial : array (5,), optional
        Starting ring displacement (e.g. the solution of a nearby case) [m, rad].
    race_control : {"outer", "inner", "hybrid"}
        Jones's raceway control that sets each ball's orbital speed (centrifugal force)
        and spin (gyroscopic moment): the ball rolls without spinning on the outer or the
        inner race; "hybrid" picks the race per ball by Jones's criterion and shares the
        friction as Harris does (gyroscopic.py) [-].
    slices : int or None
        Roller bearings: slices per line contact (None: 30, ISO/TS 16281's example) [-].
    axial_displacement : float or None
        Tapered roller bearings: impose the inner ring's axial displacement instead of
        solving it (the axial force is then the reaction: at 0, the induced axial force) [m].

    Returns
    -------
    LoadDistribution or RollerLoadDistribution

    Raises
    ------
    InputError
        For a speed above :func:`speed_limit` or an unknown ``race_control``.
    ConvergenceError
        When the ball or ring equilibrium cannot be found; for a load the contacts cannot
        carry, the message gives the load against the static rating C0 (ISO 76).
    """
    if getattr(bearing, "rolling_element", "ball") == "roller":
        ball_only = {
            "ball_diameter_errors": ball_diameter_errors is not None,
            "film": film is not None,
            "lubricant": lubricant is not None,
            "gyroscopic": gyroscopic,
            "ring_expansion": ring_expansion,
            "race_control": race_control != "outer",
        }
        for name, given in ball_only.items():
            if given:
                raise InputError(
                    name,
                    locals()[name] if name != "race_control" else race_control,
                    "its default for a roller bearing",
                    "the roller model does not take it (ball bearings only)",
                )
        check_speed(bearing, condition.shaft_speed)
        from .roller import DEFAULT_SLICES, solve_roller_distribution

        try:
            return solve_roller_distribution(
                bearing,
                condition,
                slices=DEFAULT_SLICES if slices is None else slices,
                roller_phase=ball_phase,
                tolerance=tolerance,
                initial=initial,
                axial_displacement=axial_displacement,
            )
        except ConvergenceError as exc:
            raise _in_user_terms(exc, bearing, condition) from exc
    for name, value in (("slices", slices), ("axial_displacement", axial_displacement)):
        if value is not None:
            raise InputError(name, value, "None for a ball bearing", "roller bearings only")
    if race_control not in RACE_CONTROLS:
        raise InputError("race_control", race_control, " or ".join(map(repr, RACE_CONTROLS)))
    check_speed(bearing, condition.shaft_speed)
    if ring_expansion and condition.shaft_speed > 0:
        shrink = 2.0 * inner_ring_expansion(bearing, condition.shaft_speed)
        bearing = dataclasses.replace(
            bearing, diametral_clearance=bearing.diametral_clearance - shrink
        )
    options = {  # solver.solve's, the same in every pass of the coupled solve
        "ball_phase": ball_phase,
        "ball_diameter_errors": ball_diameter_errors,
        "film": film,
        "tolerance": tolerance,
        "initial": initial,
        "gyroscopic": gyroscopic,
        "race_control": race_control,
    }
    try:
        u, b, state, problem = _solve_coupled(bearing, condition, lubricant, temperature, options)
    except ConvergenceError as exc:
        told = _in_user_terms(exc, bearing, condition)
        if told is exc and gyroscopic and condition.shaft_speed > 0:
            told = ConvergenceError(
                f"{exc}; with the gyroscopic moment held by friction "
                f"({race_control} raceway control) there may be no "
                "equilibrium at this speed: the friction needed can "
                "exceed what a lightly loaded contact holds"
            )
        raise told from exc
    q, n_rho, n_z, delta, speed, force, stiffness = state
    if problem.spd[0] <= 0:
        q = np.where(q <= 10 * CENTRIFUGAL_FLOOR, 0.0, q)  # the floor is not a real load
    ring = problem.contacts.ring
    # sign: + when the line from the inner to the outer contact leans towards +z
    angle = signed_contact_angles(ring, n_rho, n_z)
    return LoadDistribution(
        bearing=bearing,
        condition=condition,
        displacement=u,
        ball_angle=problem.psi,
        ball_centre=b,
        ring=ring,
        load=q,
        approach=delta,
        contact_angle=angle,
        film=problem.film,
        stiffness_matrix=stiffness,
        reaction=force,
        groove_radius=problem.contacts.groove_radius,
        orbital_speed=speed[:, 4].copy(),
        ball_centrifugal_force=np.where(problem.spd[0] > 0, speed[:, 6], 0.0),
        gyroscopic_moment=speed[:, 5].copy(),
        race_control=race_control,
        outer_controlled=problem.control == 0,
    )


def _solve_coupled(bearing, condition, lubricant, temperature, options):
    """The solve (solver.solve with the keyword arguments ``options``), repeated until what
    depends on its result settles: the film (at its loads) and, for ``hybrid``, which race
    controls each ball. (The cage speed of balls not driven by both races, the mean
    orbital speed of those that are, is settled inside the ball kernel.)"""
    u, b, state, problem, _ = solve(bearing, condition, **options)
    if condition.shaft_speed <= 0:
        return u, b, state, problem
    # the re-solves below keep this problem, its film and raceway control updated in place
    kwargs = {"tolerance": options["tolerance"], "problem": problem}
    with_film = lubricant is not None and options["film"] is None
    for _ in range(30):
        changed = False
        if with_film:
            h = contact_films(
                bearing, lubricant, condition.shaft_speed, problem.contacts.ring, state, temperature
            )
            changed |= bool(np.max(np.abs(h - problem.film)) >= 1e-9)
            problem.film = np.ascontiguousarray(h)
        if options["race_control"] == "hybrid":
            outer = outer_raceway_controls(bearing, problem, state) | ~_driven(problem, state)
            changed |= bool(np.any(outer != (problem.control == 0)))
            problem.set_control(outer)
        if not changed:
            return u, b, state, problem
        u, b, state, problem, _ = solve(bearing, condition, initial=u, **kwargs)
    raise ConvergenceError(
        "the EHL film / raceway control and the load distribution did not settle within 30 passes"
    )


def _driven(problem, state) -> np.ndarray:
    """Balls that touch both races (Z,)."""
    q = state[0]
    return np.any(q[:, problem.inner] > 0, axis=1) & np.any(q[:, ~problem.inner] > 0, axis=1)


def outer_raceway_controls(bearing: BallBearing, problem, state) -> np.ndarray:
    """Jones's criterion per ball (Harris & Kotzalas, *Advanced Concepts*, ch. 3): outer
    raceway control where Q_o a_o E(k_o) cos(alpha_i - alpha_o) > Q_i a_i E(k_i) (Z,).

    Parameters
    ----------
    bearing : BallBearing
        Geometry and materials.
    problem : solver._Problem
        The solve's problem (contact columns).
    state : tuple
        (loads, n_rho, n_z, ...) of the solver [N, -, -].
    """
    from ..contact import hertz
    from ..geometry import contact_radii
    from ..materials import effective_modulus

    q, n_rho, n_z = state[:3]
    angle = signed_contact_angles(problem.contacts.ring, n_rho, n_z)
    e_prime = effective_modulus(bearing.ball_material, bearing.ring_material)
    moment, mean = {}, {}
    for race, name, f in (
        (0, "inner", bearing.inner_groove_factor),
        (1, "outer", bearing.outer_groove_factor),
    ):
        cols = problem.contacts.ring == race
        load = q[:, cols].sum(axis=1)
        a = np.where(
            load > 0, (q[:, cols] * angle[:, cols]).sum(axis=1) / np.where(load > 0, load, 1.0), 0.0
        )
        rx, ry = contact_radii(bearing.ball_diameter, bearing.pitch_diameter, f, np.abs(a), name)
        c = hertz.point_contact(np.maximum(load, 1e-9), rx, np.full_like(rx, ry), e_prime)
        moment[race] = load * c.semi_major * c.second_kind
        mean[race] = a
    return moment[1] * np.cos(mean[0] - mean[1]) > moment[0]


def _in_user_terms(
    exc: ConvergenceError, bearing: BallBearing, condition: OperatingCondition
) -> ConvergenceError:
    """A solver failure for a load beyond the static rating, told as that load against C0
    (ISO 76, ratings/basic.py); other failures keep the solver's words."""
    try:
        from ..ratings import equivalent_static_load, load_ratings

        c0 = load_ratings(bearing).static
        p0 = equivalent_static_load(bearing, condition.radial_load, abs(condition.axial_load))
    except (InputError, ValueError):  # no rating for this geometry: keep the solver's
        return exc
    if p0 <= c0:
        return exc
    return ConvergenceError(
        f"the contacts cannot carry this load: F_r = {condition.radial_load:.6g} N, "
        f"F_a = {condition.axial_load:.6g} N give a static equivalent load P0 = {p0:.6g} N, "
        f"{p0 / c0:.3g} times the static rating C0 = {c0:.6g} N (ISO 76; s0 = "
        f"{c0 / p0:.3g}): no equilibrium exists for it"
    )


def contact_films(
    bearing: BallBearing,
    lubricant,
    shaft_speed: float,
    ring,
    state,
    temperature: float | None = None,
) -> np.ndarray:
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
        film[:, cols] = film_thickness(
            bearing,
            lubricant,
            np.maximum(q[:, cols], light),
            shaft_speed,
            name,
            temperature=temperature,
            contact_angle=angle[:, cols],
            kind="central",
        )
    return film


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
    return np.arctan2(sigma * n_z, np.abs(n_rho)) + 0.0  # + 0.0: no "-0"
