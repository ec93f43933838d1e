"""What a ball crossing a spall on a race does: the speed of its contact point over the
race, and the distance it bridges at each edge before it loses or regains contact.

Layer 1 (SI). A defect on a race is passed Z times for each revolution of the balls
relative to that race, so the contact point crosses the race at v = 2 pi f R / Z with f the
fault frequency (BPFO or BPFI as measured, slip included) and R the raceway radius
(:func:`contact_speed`). A loaded ball's contacts are compressed by their approach delta:
over a pit the ball loses contact only where the pit has opened that much clearance under
it, x0 past the near edge, and it is loaded again x1 before the far edge, where the
clearance has closed to delta1, the approach once the other balls carry its load
(:func:`bridged_distance`, :func:`ball_approaches`, :func:`bridged_width`). The clearance a
pit opens is the circle-chord geometry of seed 003's rigid model
(:func:`bearinglab.dynamics.defects.edge_drop`); the approaches are Stribeck's static
equilibrium with Hertz contacts (Harris T. A., Kotzalas M. N., *Essential Concepts of
Bearing Technology*, 5th ed., 2007, ch. 7), as :func:`bearinglab.dynamics.rigid.static_offset`
solves it for the rigid model's start.

When the load is not known, ASSUMED_LOAD x the bearing's dynamic rating C stands in for
it (:func:`assumed_loads`): the middle, on a log scale, of LOAD_RANGE, 0.01 C to 0.1 C, the
loads a ball bearing runs at in ordinary service - bearing makers' catalogues put the
least load a ball bearing needs to roll without skidding near 0.01 C and call loads above
about 0.1 C heavy (the project's reading, not checked against one edition).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

#: Radial load assumed when none is given, and the range the interval then spans, as
#: fractions of the dynamic load rating C (the module docstring says why).
ASSUMED_LOAD = math.sqrt(0.01 * 0.1)
LOAD_RANGE = (0.01, 0.1)


def raceway_radius(bearing, race: str) -> float:
    """Radius of the ``race``'s groove bottom ("inner" or "outer"), along which the
    defect's width is measured [m] (the raceway diameters of
    :class:`~bearinglab.geometry.BallBearing`)."""
    if race == "outer":
        return 0.5 * bearing.outer_raceway_diameter
    if race == "inner":
        return 0.5 * bearing.inner_raceway_diameter
    raise InputError("race", race, "inner or outer")


def contact_speed(fault_frequency, ball_count, race_radius):
    """Speed of a ball's contact point over the defective race [m/s].

    A defect on a race is passed Z times for each revolution of the balls relative to
    that race, so f / Z is one ball's rate over it and v = 2 pi f R / Z, with the fault
    frequency f as measured (BPFO for the outer race, BPFI for the inner; slip included).

    Parameters
    ----------
    fault_frequency : float or array
        f, the fault frequency [Hz].
    ball_count : int
        Z [-].
    race_radius : float
        R, the raceway radius [m].

    Examples
    --------
    >>> round(float(contact_speed(107.36, 9, 23.49e-3)), 3)   # 6205 outer race, 1797 rpm
    1.761
    """
    f = np.asarray(fault_frequency, dtype=float)
    return (2.0 * math.pi * f * race_radius / ball_count)[()]


def _drop(distance, ball_radius, race_radius, race):
    """lambda(d) of :func:`bearinglab.dynamics.defects.edge_drop` (circle-chord geometry,
    the race concave for the outer race, convex for the inner) [m]."""
    d = np.minimum(distance, ball_radius)
    ball = ball_radius - np.sqrt(ball_radius**2 - d**2)
    ring = race_radius - np.sqrt(np.maximum(race_radius**2 - d**2, 0.0))
    return ball - ring if race == "outer" else ball + ring


def bridged_distance(approach, ball_radius, race_radius, race: str):
    """Distance from a pit's edge at which a loaded ball loses (or regains) contact [m].

    A ball whose contacts are compressed by ``approach`` delta keeps its load over a pit
    until the pit has opened that much clearance under it: the distance d past the edge
    where lambda(d) = delta, lambda being the drop of the ball's centre into a pit whose
    edge is d away (:func:`bearinglab.dynamics.defects.edge_drop`, seed 003's geometry);
    about sqrt(2 delta r_e) with 1/r_e = 1/r -+ 1/R. Found by bisection (lambda rises
    monotonically with d). A ``approach`` beyond the deepest drop, at d = r, gives r.

    Parameters
    ----------
    approach : float or array
        delta, the approach of the ball's contacts [m], >= 0.
    ball_radius : float
        r [m].
    race_radius : float
        R, the raceway radius [m].
    race : {"inner", "outer"}
        The race with the pit.

    Examples
    --------
    >>> round(float(bridged_distance(10e-6, 3.97e-3, 23.49e-3, "outer")) * 1e3, 3)
    0.309
    """
    delta = np.asarray(approach, dtype=float)
    lo = np.zeros_like(delta)
    hi = np.full_like(delta, ball_radius)
    for _ in range(60):  # 2^-60 of r: far below a nanometre
        mid = 0.5 * (lo + hi)
        above = _drop(mid, ball_radius, race_radius, race) >= delta
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return (0.5 * (lo + hi))[()]


def ball_series_constant(bearing) -> float:
    """Load-deflection constant K of one ball between both races, Q = K delta^1.5
    [N/m^1.5] (Hertz, :func:`bearinglab.contact.hertz.series_constant`)."""
    from ..contact import hertz
    from ..materials import effective_modulus

    e = effective_modulus(bearing.ball_material, bearing.ring_material)
    # both contacts in one call (one solve of the ellipticities: its iterations leave a
    # converged element as it is, so each is the one it would be alone)
    (rx_i, ry_i), (rx_o, ry_o) = bearing.contact_radii("inner"), bearing.contact_radii("outer")
    inner, outer = hertz.load_deflection_constant(np.array([rx_i, rx_o]), np.array([ry_i, ry_o]), e)
    return float(hertz.series_constant(inner, outer))


def _ring_approach(k: float, cosines: np.ndarray, load: float, half_clearance: float) -> float:
    """u with load = sum K [u cos(psi) - P_d/2]_+^1.5 cos(psi), by bisection [m]."""

    def force(u):
        return k * float(np.sum(np.maximum(u * cosines - half_clearance, 0.0) ** 1.5 * cosines))

    lo = min(half_clearance, 0.0)
    while force(lo) > load:  # a preload: the rings are pressed together at u = 0
        lo -= 1e-6
    hi = max(half_clearance, 0.0) + 1e-6
    while force(hi) < load:
        hi *= 2.0
    while hi - lo > 1e-13:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if force(mid) < load else (lo, mid)
    return 0.5 * (lo + hi)


def ball_approaches(
    bearing, radial_load: float, constant: float | None = None
) -> tuple[float, float]:
    """Approaches (delta0, delta1) of the ball on the load line [m]: carrying its load with
    every ball in place, and once it has lost contact over a defect and the others carry
    the whole load (the rings close up by delta1 - delta0).

    Rigid rings, balls equally spaced with one on the load line, Hertz contacts in series
    Q = K delta^1.5 (:func:`ball_series_constant`), the clearance P_d / 2:
    F_r = sum_j K [u cos(psi_j) - P_d/2]_+^1.5 cos(psi_j) (Stribeck's equilibrium, Harris &
    Kotzalas, *Essential Concepts of Bearing Technology*, 2007, ch. 7; the static state
    of seed 003's rigid model, :func:`bearinglab.dynamics.rigid.static_offset`).

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    radial_load : float
        F_r [N], > 0.
    constant : float, optional
        K, when already computed for this bearing (:func:`ball_series_constant`).

    Examples
    --------
    >>> from bearinglab.catalog import bearing_from_designation
    >>> b, _ = bearing_from_designation("6205")
    >>> [round(d * 1e6, 1) for d in ball_approaches(b, 500.0)]
    [9.8, 15.8]
    """
    k = ball_series_constant(bearing) if constant is None else float(constant)
    z = bearing.ball_count
    cosines = np.cos(2.0 * np.pi * np.arange(z) / z)
    half = 0.5 * bearing.diametral_clearance
    u0 = _ring_approach(k, cosines, radial_load, half)
    u1 = _ring_approach(k, cosines[1:], radial_load, half)
    return u0 - half, u1 - half


def bridged_width(bearing, race: str, radial_load: float, constant: float | None = None) -> float:
    """x0 + x1: what the ball bridges at both edges of a pit on ``race`` under
    ``radial_load`` [N] - the event spacing times the contact speed falls short of the
    defect's width by this much, and a defect shorter than it never lets the ball drop
    (:func:`bridged_distance` of :func:`ball_approaches`; ``constant``: its K when
    already computed) [m]."""
    r = 0.5 * bearing.ball_diameter
    radius = raceway_radius(bearing, race)
    d0, d1 = ball_approaches(bearing, radial_load, constant)
    return float(np.sum(bridged_distance(np.array([d0, d1]), r, radius, race)))


def bridged_widths(bearing, race: str, radial_loads, constant: float | None = None) -> list:
    """:func:`bridged_width` under each of ``radial_loads`` [N], the pits' edges found by
    one bisection for all (:func:`bridged_distance` works element by element: each the one
    it would be alone) [m].

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    race : {"inner", "outer"}
        The race with the pit.
    radial_loads : sequence of float
        F_r [N], each > 0.
    constant : float, optional
        K, when already computed for this bearing (:func:`ball_series_constant`).
    """
    r = 0.5 * bearing.ball_diameter
    radius = raceway_radius(bearing, race)
    k = ball_series_constant(bearing) if constant is None else float(constant)
    deltas = np.array([ball_approaches(bearing, load, k) for load in radial_loads])
    distances = bridged_distance(deltas.ravel(), r, radius, race).reshape(deltas.shape)
    return [float(np.sum(row)) for row in distances]


def assumed_loads(bearing) -> tuple[float, float, float]:
    """(assumed, lowest, highest) radial load [N] when none is given: ASSUMED_LOAD and
    LOAD_RANGE times the dynamic load rating C (ISO 281 from the internal geometry,
    :func:`bearinglab.ratings.load_ratings`)."""
    from ..ratings import load_ratings

    c = load_ratings(bearing).dynamic
    return ASSUMED_LOAD * c, LOAD_RANGE[0] * c, LOAD_RANGE[1] * c
