"""The rigid-ring defect model of seed 003 (4 degrees of freedom).

Seed 003, part 7 ("a 4-DOF dynamic model of a deep-groove ball bearing with a compound
fault", after Sawalhi & Randall 2008 and Patel et al. 2010): the shaft with the inner
ring (x_s, y_s) and the pedestal with the outer ring (x_p, y_p) are rigid masses; the
balls are massless Hertz springs between them, equally spaced and moving with the cage
at the pure-rolling speed; a ball carries load only when its approach is positive
(load-zone switch); localised defects open extra clearance lambda_j(t) as a ball crosses
them (:mod:`bearinglab.dynamics.defects`). Equations (seed 003 eq. 21, rebuilt):

    m_s x_s'' + c_s x_s' + k_s x_s + f_x = F_x + m_u e omega^2 cos(omega t)
    m_p x_p'' + c_p x_p' + k_p x_p - f_x = 0           (and the same in y)
    f = sum_j K [delta_j]_+^1.5 (cos psi_j, sin psi_j) + c_b (v_s - v_p)
    delta_j = (x_s - x_p) cos psi_j + (y_s - y_p) sin psi_j - P_d/2 - lambda_j(t)

K is the series constant of the inner and outer Hertz contacts
(:func:`bearinglab.contact.hertz.series_constant`). For a roller bearing
(``rolling_element`` "roller") the balls are rollers and the law is the line contact's,
Q = c_l [delta_j]_+^(10/9) with ISO/TS 16281's c_l for both contacts
(:func:`bearinglab.contact.line.iso16281_roller_constant`) when the roller is unprofiled;
with a profile, the power law K delta^n fitted (least squares in log-log) to the roller's
slice sum sum_k (c_l/n_s) [delta - 2 P(x_k)]_+^(10/9) between 0.1 and 2 times the
heaviest roller's load 4.08 F_r/Z (:func:`roller_law`). Assumptions (seed 003 sec. 2):
Hertz contacts without plastic flow; balls equally spaced; ball inertia and gyroscopic
moments neglected (moderate speed); defect edges sharp; no slip (the cage turns at the
kinematic speed; see the slip model for what lubricated bearings really do).

Parameters the seed does not print (its Table of model parameters was lost in
translation) are documented on :class:`RigidParameters` with their sources.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..contact import hertz
from ..errors import positive_number
from ..kinematics import frequency_orders
from ..materials import effective_modulus
from . import _kernels as kern


@dataclass(frozen=True)
class RigidParameters:
    """Masses, supports and damping of the rigid-ring model (SI).

    Seed 003 prints none of these values. The pedestal stiffness and damping are the
    shaft-support values circulated as those of Sawalhi N., Randall R. B., "Simulating
    gear and bearing interactions in the presence of faults: Part I", *Mech. Syst.
    Signal Process.* 22 (2008) 1924-1951 (not checked against the paper); the masses
    and the bearing damping are chosen. docs/capabilities/dynamics.md has the table.

    Parameters
    ----------
    shaft_mass : float
        m_s, shaft and inner ring [kg].
    pedestal_mass : float
        m_p, pedestal and outer ring [kg].
    shaft_stiffness, shaft_damping : float
        k_s [N/m], c_s [N s/m]: the shaft's own support to ground besides this bearing.
    pedestal_stiffness, pedestal_damping : float
        k_p [N/m], c_p [N s/m]: pedestal to ground.
    bearing_damping : float
        c_b, viscous damping across the bearing [N s/m].
    unbalance : float
        m_u e, rotating unbalance of the shaft [kg m].
    """

    shaft_mass: float = 1.0
    pedestal_mass: float = 1.0
    shaft_stiffness: float = 0.0
    shaft_damping: float = 0.0
    pedestal_stiffness: float = 7.42e7
    pedestal_damping: float = 1376.8
    bearing_damping: float = 200.0
    unbalance: float = 0.0

    def __post_init__(self) -> None:
        for name, value in asdict(self).items():
            positive = name.endswith("mass")
            allowed = "a positive value" if positive else "a value >= 0 (SI units)"
            positive_number(name, value, allowed, zero=not positive)

    def to_dict(self) -> dict:
        """JSON-ready values (engineering units of docs/json.md, in the keys)."""
        return {
            "shaft_mass_kg": self.shaft_mass,
            "pedestal_mass_kg": self.pedestal_mass,
            "shaft_stiffness_n_per_um": self.shaft_stiffness * 1e-6,
            "shaft_damping_n_s_per_m": self.shaft_damping,
            "pedestal_stiffness_n_per_um": self.pedestal_stiffness * 1e-6,
            "pedestal_damping_n_s_per_m": self.pedestal_damping,
            "bearing_damping_n_s_per_m": self.bearing_damping,
            "unbalance_g_mm": self.unbalance * 1e6,
        }


def roller_law(bearing, radial_load: float) -> tuple[float, float]:
    """(K, n) of a roller between both raceways in the planar model, Q = K delta^n
    [N/m^n, -]: ISO/TS 16281's (c_l, 10/9) for an unprofiled roller, else the fit to the
    slice sum over 0.1-2 times the heaviest roller's load (see the module docstring).

    Parameters
    ----------
    bearing : RollerBearing
        The roller bearing (profile, L_we, D_we, materials).
    radial_load : float
        F_r [N] (sets the load range of the fit).
    """
    from ..contact.line import iso16281_roller_constant, slice_positions
    from ..contact.roller_race import slice_loads
    from ..materials import BEARING_STEEL

    e = effective_modulus(bearing.roller_material, bearing.ring_material)
    c_l = iso16281_roller_constant(
        bearing.roller_length, e, effective_modulus(BEARING_STEEL, BEARING_STEEL)
    )
    if bearing.profile.kind == "flat":
        return c_l, 10.0 / 9.0
    x = slice_positions(bearing.roller_length, 30)
    drop = bearing.profile_drop(x)
    q_ref = max(4.08 * radial_load / bearing.roller_count, 1.0)
    loads = q_ref * np.geomspace(0.1, 2.0, 12)
    deltas = np.array([slice_loads(q, c_l, x, drop)[1] for q in loads])
    n, log_k = np.polyfit(np.log(deltas), np.log(loads), 1)
    return float(np.exp(log_k)), float(n)


def hertz_constant(bearing) -> float:
    """Series load-deflection constant K of one ball's inner and outer contacts [N/m^1.5]."""
    e = effective_modulus(bearing.ball_material, bearing.ring_material)
    k_in = hertz.load_deflection_constant(*bearing.contact_radii("inner"), e)
    k_out = hertz.load_deflection_constant(*bearing.contact_radii("outer"), e)
    return float(hertz.series_constant(k_in, k_out))


def pack(bearing, condition, params: RigidParameters, table, cage_phase: float = 0.0):
    """The kernel's parameter array for ``bearing`` under ``condition``."""
    orders = frequency_orders(
        bearing.element_count,
        bearing.element_diameter,
        bearing.pitch_diameter,
        bearing.contact_angle,
    )
    w = condition.shaft_speed
    load = condition.load_vector()
    p = np.zeros(kern.RIGID_PARAMETER_COUNT)
    p[kern.M_S], p[kern.M_P] = params.shaft_mass, params.pedestal_mass
    p[kern.K_S], p[kern.C_S] = params.shaft_stiffness, params.shaft_damping
    p[kern.K_P], p[kern.C_P] = params.pedestal_stiffness, params.pedestal_damping
    if getattr(bearing, "rolling_element", "ball") == "roller":
        p[kern.K_HERTZ], p[kern.EXPONENT] = roller_law(bearing, condition.radial_load)
    else:
        p[kern.K_HERTZ], p[kern.EXPONENT] = hertz_constant(bearing), 1.5
    p[kern.HALF_CLEARANCE] = 0.5 * bearing.diametral_clearance
    p[kern.C_BEARING] = params.bearing_damping
    p[kern.BALLS] = bearing.element_count
    p[kern.CAGE_SPEED] = float(orders["ftf"]) * w
    p[kern.SPIN_SPEED] = float(orders["bsf"]) * w  # ball spin relative to the cage
    p[kern.SHAFT_SPEED] = w
    p[kern.F_X], p[kern.F_Y] = load[0], load[1]
    p[kern.UNBALANCE] = params.unbalance
    p[kern.BALL_RADIUS] = 0.5 * bearing.element_diameter
    p[kern.INNER_RADIUS] = 0.5 * bearing.inner_raceway_diameter
    p[kern.OUTER_RADIUS] = 0.5 * bearing.outer_raceway_diameter
    p[kern.CAGE_PHASE] = cage_phase
    return p


def static_offset(k, psi, force, half_clearance, theta, exponent=1.5) -> np.ndarray:
    """Displacement of the inner ring relative to the outer at static equilibrium [m].

    Solves F = sum_j K [u cos(psi_j - theta) - P_d/2]_+^n cos(psi_j - theta) for the
    approach u along the load direction theta, balls frozen at ``psi`` (the transverse
    force is small and is left to the settling time); n the ``exponent`` (1.5 balls).
    """
    if force == 0.0:
        return np.zeros(2)
    cosines = np.cos(np.asarray(psi) - theta)

    def residual(u):
        d = np.clip(u * cosines - half_clearance, 0.0, None)
        return float(k * np.sum(d**exponent * cosines)) - force

    lo = max(half_clearance, 0.0)
    hi = lo + 1e-6
    while residual(hi) < 0:
        hi *= 2.0
    # bisection of the monotonic residual to 1e-13 m: only the start of the integration,
    # which the settling time refines (scipy.optimize would cost ~0.3 s to import)
    while hi - lo > 1e-13:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if residual(mid) < 0 else (lo, mid)
    u = 0.5 * (lo + hi)
    return u * np.array([math.cos(theta), math.sin(theta)])


def static_state(p) -> np.ndarray:
    """Initial state at the static equilibrium of the defect-free bearing: the bearing
    carries the load, the pedestal spring (and the shaft spring, if any) share it."""
    force = math.hypot(p[kern.F_X], p[kern.F_Y])
    y = np.zeros(8)
    if force == 0.0:
        return y
    theta = math.atan2(p[kern.F_Y], p[kern.F_X])
    z = int(p[kern.BALLS])
    psi = p[kern.CAGE_PHASE] + 2 * np.pi * np.arange(z) / z
    k_s, k_p = p[kern.K_S], p[kern.K_P]
    share = 1.0 if k_s == 0.0 else k_p / (k_p + k_s)  # approximate when k_s > 0
    u = static_offset(
        p[kern.K_HERTZ], psi, force * share, p[kern.HALF_CLEARANCE], theta, p[kern.EXPONENT]
    )
    x_p = (force * share / k_p if k_p > 0 else 0.0) * np.array([math.cos(theta), math.sin(theta)])
    y[2:4] = x_p
    y[0:2] = x_p + u
    return y


#: Absolute tolerances of the state: displacements [m] and velocities [m/s].
ATOL = np.array([1e-11] * 4 + [1e-8] * 4)
