"""The seed-004 slip model: balls free to slide under EHL, with a cage.

Hou X., Fan J., Ma J., Fu X., "Influence of sliding effect on frequency of rolling
element defect in ball bearing", *J. Mech. Electr. Eng.* 41(2) (2024) 271-279 (seed
004). Each ball j has radial (rho_j), orbital (psi_j) and spin (phi_j) freedom, the
cage its own rotation (theta_c), the inner ring (turning at a constant speed) and the
outer ring translate in the radial plane. In the notation of ``_slip_kernels``:

- approaches (eq. 2): delta_i = u_i . e_j - rho_j - P_d/4 - lambda_i + h_i,
  delta_o = rho_j - u_o . e_j - P_d/4 - lambda_o + h_o; lambda from the surface table
  (defects); the film h is a layer between the surfaces, so for given centres it adds
  to the approach (the seed prints -h, which would make the film open clearance);
- normal forces (eq. 3 with eqs. 7-9): N = [K delta^1.5 + C delta' min(1, delta/delta_s)]_+
  with the Hertz constant K and the film damping C of eq. 8,
  C = 6 pi eta_0 R_x^1.5 a / (1.414 h^1.5) (the ramp over the first delta_s of approach
  is ours, see ``damping_onset``);
  the film's normal stiffness (eqs. 7, 9) is in series with Hertz' and >100 times
  stiffer at these loads, so it is represented by the film thickness alone;
- slip speeds (eq. 13): dV_i = (omega_i - omega_m) d_i/2 - omega_r D_w/2,
  dV_o = omega_r D_w/2 - omega_m d_o/2; tractions F = mu(dV) N (eq. 10) with mu from
  eq. 12 (``traction="seed004"``, a power-law shear stress averaged over the Hertz
  pressure and capped at the lubricant's limiting shear coefficient) or the Bair-Winer
  limiting-shear model (``traction="bair_winer"``: Bair S., Winer W. O., *J. Lubr.
  Technol.* 101 (1979) 258-265, tau = tau_L (1 - exp(-eta gamma'/tau_L)),
  tau_L = (tau_L/p) p, eta = eta_0 exp(alpha p), averaged over the Hertz pressure);
- ball-cage contact (eq. 4): N_c = K_c (psi_j - theta_c - 2 pi j/Z) d_m/2 + C_c V_c
  (with an optional pocket clearance), friction mu_c N_c with mu_c =
  ``SlipParameters.cage_friction``, by default eq. 11 (Masjedi-Khonsari boundary curve)
  at the slide-roll ratio 2 of a pure-sliding pocket contact, 0.1;
- ball drag (eq. 14): F = pi rho_e C_d R_b^2 (2 R_m omega_m)^1.95 / 8, rho_e the mass
  density of the oil-air mixture (the seed's rho_e/g, a weight density over g);
- spin drag (not in the seed; ``SlipParameters.spin_drag``, off by default): the moment
  of a sphere spinning in the oil-air mixture, M = 0.5 rho_e R_b^5 C_R |omega_r| omega_r,
  C_R(Re_r) of Dennis, Singh & Ingham (*J. Fluid Mech.* 101 (1980) 257-279), see
  :func:`._slip_kernels.spin_drag`;
- cage drag (eq. 15): M = 0.5 rho_e C_b R_co^3 (R_co^2 - R_ci^2) omega_c^2
  + 0.125 mu_e rho_e A_c R_ci^3 omega_c^2, opposing the rotation;
- ball-defect impacts (eqs. 16-19): while a ball defect faces the inner race (spin
  phase within [pi, pi + theta_d]) the force m_b (omega_i - omega_m)^2 d_i/2 pushes the
  ball out and the inner ring in; facing the outer race, m_b omega_m^2 (d_o - D_w)/2
  (the printed forms with cos(theta) ~ 1 for defects of a few degrees);
- equations of motion (eqs. 20-24) in polar form: m_b (rho'' - r omega_m^2) = radial
  forces, m_b (r omega_m' + 2 rho' omega_m) = tangential forces, J_b omega_r' =
  (F_i - F_o - mu_c |N_c|) D_w/2; J_c omega_c' = (d_m/2) sum N_c - M_e; rings
  m a = sum of reactions + loads; gravity acts on the balls. The spin equation also
  carries -M of the spin drag when it is on.

Departures from the print, each stated where it is made: J_b = (2/5) m_b R_b^2 (the
seed prints m_b R_b^2, the inertia of a thin ring); the outer ring sits on a housing
spring k_o, c_o (the seed's eq. 21 has none, and a free outer ring would drift); the
film and its damping are evaluated once, at the largest Stribeck ball load and the
pure-rolling entrainment speed. Values the seed does not give are in
:class:`SlipParameters` with their sources.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Literal

import numpy as np

from ..contact import hertz
from ..errors import InputError, positive_number
from ..lubrication import LUBRICANTS, Lubricant
from ..lubrication.ehl import entrainment_speed, hamrock_dowson_film
from ..materials import effective_modulus
from ..operating import speed_error
from . import _slip_kernels as sk

Traction = Literal["seed004", "bair_winer"]
TRACTIONS = ("seed004", "bair_winer")
GRAVITY = 9.81
#: Largest cage_friction accepted: above it the pocket would be dry (see SlipParameters).
MAX_CAGE_FRICTION = 0.3


@dataclass(frozen=True)
class SlipParameters:
    """Values of the slip model that the bearing and lubricant do not give (SI).

    Parameters
    ----------
    traction : {"seed004", "bair_winer"}
        Race traction model [-].
    flow_index : float
        n of eq. 12 [-]; 1 (Newtonian, then G_oil drops out) because seed 004 gives none.
    oil_shear_modulus : float
        G_oil of eq. 12 [Pa] (only used when flow_index < 1); 0.5 GPa, a typical
        limiting elastic shear modulus (Johnson & Tevaarwerk 1977 range 0.5-1 GPa).
    regularisation_speed : float
        Slip speed below which the traction coefficient is taken linear in it [m/s]: a
        numerical device (the traction curve is nearly vertical at zero slip); the
        tests show the ball speeds do not depend on it below 1e-3 m/s.
    cage_stiffness, cage_damping : float
        K_c [N/m], C_c [N s/m] of the ball-pocket contact (eq. 4, "equivalent stiffness
        under lubrication"); not given by the seed: 1e6 N/m (a ball pressing a
        lubricated pressed-steel or polymer pocket with a few newtons) and 10 N s/m
        (about 10 % of critical for one ball).
    pocket_clearance : float
        Play of a ball in its pocket along the orbit [m]; 0 as in eq. 4.
    oil_fraction : float
        Volume fraction of lubricant in the oil-air mixture [-] (rho_e = fraction rho);
        0.03 (Harris & Kotzalas: 1-5 % in jet- or grease-lubricated bearings).
    ball_drag_coefficient, cage_drag_coefficient : float
        C_d of eq. 14 (0.5, a sphere at Re 1e3-1e5) and C_b of eq. 15 (5e-3) [-].
    cage_friction : float
        mu_c, friction coefficient of a ball sliding in its cage pocket [-]; default 0.1,
        seed 004 eq. 11 (the Masjedi-Khonsari boundary-friction curve) at the slide-roll
        ratio 2 of a pocket contact, where the curve has reached its boundary value.
        Allowed 0-0.3: boundary-lubricated pairs of the cage materials on bearing steel
        run at about 0.05-0.2 (steel, brass and polyamide against lubricated steel; e.g.
        Bowden & Tabor, *The Friction and Lubrication of Solids*, 1950, boundary films
        0.05-0.15), 0 is a frictionless pocket, and above 0.3 the pocket would be dry,
        which this lubricated model does not describe.
    spin_drag : bool
        Add the drag moment of each ball spinning in the oil-air mixture (density
        oil_fraction x rho, viscosity oil_fraction x eta_0: the linear mixing rule, air
        neglected) by Dennis, Singh & Ingham's rotating-sphere coefficient
        (:func:`._slip_kernels.spin_drag`). Off by default: seed 004's ball equation (24)
        has no such moment.
    cage_mass_ratio : float
        Cage mass over ball-set mass [-]; 0.35 (pressed-steel cage of a 62-series
        bearing, e.g. about 6 g for the 19 g ball set of a 6205); the cage's radius of
        gyration is d_m/2.
    housing_stiffness, housing_damping : float
        k_o [N/m], c_o [N s/m] between outer ring and ground; 1e8 N/m and 2000 N s/m.
    inner_mass, outer_mass : float or None
        Ring masses [kg]; None takes the rings' own masses from the bearing's section.
    unbalance : float
        m_u e [kg m]; seed 004: 0.5 g, at the bore radius of a 6205 (12.5 mm, a choice).
    impact_forces : bool
        Add the ball-defect impact forces of eqs. 16-19 to the contact geometry.
    damping_onset : float
        delta_s [m]: the contact damping grows linearly over the first delta_s of
        approach instead of jumping to C delta' at touch-down, a numerical device like
        ``regularisation_speed``. The jump is a known artefact of spring-dashpot
        contacts (Hunt & Crossley, *J. Appl. Mech.* 42 (1975) 440-445); balls at the edge
        of the load zone cross it tens of thousands of times a second, and the step
        control then rejects half its steps (1000 N case: 10x slower). 1e-8 m is 1/25 of
        the film and about 1/1000 of a loaded ball's approach; the tests show the ball
        speeds do not depend on it below that.
    """

    traction: Traction = "seed004"
    flow_index: float = 1.0
    oil_shear_modulus: float = 0.5e9
    regularisation_speed: float = 1e-3
    cage_stiffness: float = 1e6
    cage_damping: float = 10.0
    pocket_clearance: float = 0.0
    oil_fraction: float = 0.03
    ball_drag_coefficient: float = 0.5
    cage_drag_coefficient: float = 5e-3
    cage_friction: float = sk.CAGE_SLIDING_MU
    spin_drag: bool = False
    cage_mass_ratio: float = 0.35
    housing_stiffness: float = 1e8
    housing_damping: float = 2000.0
    inner_mass: float | None = None
    outer_mass: float | None = None
    unbalance: float = 0.5e-3 * 12.5e-3
    impact_forces: bool = True
    damping_onset: float = 1e-8

    def __post_init__(self) -> None:
        if self.traction not in TRACTIONS:
            raise InputError("traction", self.traction, f"one of {TRACTIONS}")
        for name in ("impact_forces", "spin_drag"):
            if not isinstance(getattr(self, name), bool):
                raise InputError(name, getattr(self, name), "True or False")
        mu_c = self.cage_friction
        if (
            isinstance(mu_c, bool)
            or not isinstance(mu_c, (int, float, np.floating))
            or not 0 <= mu_c <= MAX_CAGE_FRICTION
        ):  # False for NaN too
            raise InputError(
                "cage_friction",
                mu_c,
                f"a friction coefficient in [0, {MAX_CAGE_FRICTION}]",
                "lubricated cage pockets run at about 0.05-0.2",
            )
        for name, value in asdict(self).items():
            if name in ("traction", "impact_forces", "spin_drag") or value is None:
                continue
            positive_number(name, value, "a finite value >= 0 (SI units)", zero=True)
        for name in (
            "flow_index",
            "regularisation_speed",
            "damping_onset",
            "cage_stiffness",
            "cage_mass_ratio",
            "inner_mass",
            "outer_mass",
        ):
            if getattr(self, name) == 0:
                raise InputError(name, 0, "a positive value")
        if self.flow_index > 1:
            raise InputError("flow_index", self.flow_index, "a value in (0, 1]")
        if self.oil_fraction > 1:
            raise InputError("oil_fraction", self.oil_fraction, "a fraction in [0, 1]")
        if self.spin_drag and self.oil_fraction == 0:
            raise InputError(
                "oil_fraction",
                0,
                "a fraction > 0 when `spin_drag` is on",
                "the spin drag acts in the oil-air mixture",
            )

    def to_dict(self) -> dict:
        """JSON-ready values (engineering units of docs/json.md, in the keys where they
        have one)."""
        from ..units import UNITS

        units = {
            "oil_shear_modulus": "gpa",
            "regularisation_speed": "m_s",
            "cage_stiffness": "n_per_um",
            "cage_damping": "n_s_per_m",
            "pocket_clearance": "um",
            "housing_stiffness": "n_per_um",
            "housing_damping": "n_s_per_m",
            "inner_mass": "kg",
            "outer_mass": "kg",
            "unbalance": "g_mm",
            "damping_onset": "um",
        }
        out = {}
        for k, v in asdict(self).items():
            if k in units:
                u = units[k]
                out[f"{k}_{u}"] = None if v is None else UNITS[u].from_si(v)
            else:
                out[k] = v
        return out


def _ring_mass(bearing, which: str, given):
    if given is not None:
        return given
    try:
        return getattr(bearing, f"{which}_ring_mass")
    except InputError as exc:
        raise InputError(
            f"{which}_mass",
            None,
            "a ring mass [kg]",
            f"the bearing has no boundary dimensions to compute it ({exc})",
        ) from None


def pack(
    bearing,
    condition,
    params: SlipParameters,
    table,
    lubricant: Lubricant | None = None,
    defect_width: float = 0.0,
):
    """The kernel's parameter array for ``bearing`` under ``condition``."""
    lub = lubricant or LUBRICANTS["seed004-grease"]
    if lub.limiting_shear_coefficient is None:
        raise InputError(
            "lubricant",
            lub.name,
            "a lubricant with a limiting_shear_coefficient",
            "the traction models need tau_L/p",
        )
    if bearing.contact_angle > math.radians(1.0):
        raise InputError(
            "contact_angle",
            math.degrees(bearing.contact_angle),
            "0 deg (the slip model is planar: deep-groove bearings, radial load)",
        )
    if condition.shaft_speed <= 0:
        raise speed_error(
            condition.shaft_speed, "a speed > 0 rpm", "the slip model needs the inner ring turning"
        )
    z = bearing.ball_count
    dw = bearing.ball_diameter
    e_prime = effective_modulus(bearing.ball_material, bearing.ring_material)
    load = condition.load_vector()
    q_max = max(5.0 * condition.radial_load / z, 1.0)  # Stribeck's estimate
    u = float(entrainment_speed(bearing, condition.shaft_speed))
    eta = lub.dynamic_viscosity
    p = np.zeros(sk.SLIP_PARAMETER_COUNT)
    for race, k_i, h_i, c_i, p1_i in (
        ("inner", sk.K_IN, sk.H_IN, sk.C_IN, sk.P1_IN),
        ("outer", sk.K_OUT, sk.H_OUT, sk.C_OUT, sk.P1_OUT),
    ):
        rx, ry = bearing.contact_radii(race)
        p[k_i] = float(hertz.load_deflection_constant(rx, ry, e_prime))
        h = float(
            hamrock_dowson_film(q_max, u, rx, ry, e_prime, eta, lub.pressure_viscosity_coefficient)
        )
        p[h_i] = h
        contact = hertz.point_contact(q_max, rx, ry, e_prime)
        p[c_i] = 6 * math.pi * eta * rx**1.5 * float(contact.semi_major) / (1.414 * h**1.5)
        p[p1_i] = float(hertz.point_contact(1.0, rx, ry, e_prime).max_pressure)
    m_b = bearing.ball_mass
    r_m = 0.5 * bearing.pitch_diameter
    m_c = params.cage_mass_ratio * z * m_b
    rho_e = params.oil_fraction * lub.density
    r_co, r_ci = r_m + 0.25 * dw, r_m - 0.25 * dw
    p[sk.BALLS] = z
    p[sk.M_I] = _ring_mass(bearing, "inner", params.inner_mass)
    p[sk.M_O] = _ring_mass(bearing, "outer", params.outer_mass)
    p[sk.K_O], p[sk.C_O] = params.housing_stiffness, params.housing_damping
    p[sk.M_B] = m_b
    p[sk.J_B] = 0.4 * m_b * (0.5 * dw) ** 2
    p[sk.J_C] = m_c * r_m**2
    p[sk.R_M], p[sk.R_B] = r_m, 0.5 * dw
    p[sk.R_IN] = 0.5 * bearing.inner_raceway_diameter
    p[sk.R_OUT] = 0.5 * bearing.outer_raceway_diameter
    p[sk.QUARTER_CLEARANCE] = 0.25 * bearing.diametral_clearance
    p[sk.OMEGA_I] = condition.shaft_speed
    p[sk.F_X], p[sk.F_Y] = load[0], load[1]
    p[sk.UNBALANCE] = params.unbalance
    p[sk.GRAVITY] = GRAVITY
    p[sk.K_CAGE], p[sk.C_CAGE] = params.cage_stiffness, params.cage_damping
    p[sk.POCKET] = params.pocket_clearance
    p[sk.TRACTION] = TRACTIONS.index(params.traction)
    p[sk.ETA0] = eta
    p[sk.ALPHA] = lub.pressure_viscosity_coefficient
    p[sk.MU_LIMIT] = lub.limiting_shear_coefficient
    p[sk.FLOW_INDEX] = params.flow_index
    p[sk.G_OIL] = params.oil_shear_modulus
    p[sk.V_REG] = params.regularisation_speed
    p[sk.ONSET] = params.damping_onset
    p[sk.DRAG] = math.pi * rho_e * params.ball_drag_coefficient * (0.5 * dw) ** 2 / 8.0
    p[sk.CAGE_DRAG] = (
        0.5 * rho_e * params.cage_drag_coefficient * r_co**3 * (r_co**2 - r_ci**2)
        + 0.125 * sk.CAGE_D * rho_e * (2 * math.pi * r_co * 0.5 * dw) * r_ci**3
    )
    p[sk.IMPACTS] = 1.0 if params.impact_forces else 0.0
    p[sk.CAGE_MU] = params.cage_friction
    # spin drag: mixture density and viscosity by the linear rule (air neglected)
    p[sk.SPIN_RHO] = rho_e if params.spin_drag else 0.0
    p[sk.SPIN_MU] = params.oil_fraction * eta
    # seed 004 eq. 17: the defect subtends theta_d at the ball centre, sin theta_d = w / D_w
    p[sk.DEFECT_ANGLE] = math.asin(min(defect_width / dw, 1.0))
    return p


def initial_state(p, cage_phase: float = 0.0) -> np.ndarray:
    """Pure-rolling speeds, balls evenly spaced and the inner ring at its static offset."""
    from .rigid import static_offset

    z = int(p[sk.BALLS])
    y = np.zeros(sk.NG + sk.NB * z)
    w_i = p[sk.OMEGA_I]
    r_in, r_out, r_b = p[sk.R_IN], p[sk.R_OUT], p[sk.R_B]
    w_c = w_i * r_in / (r_in + r_out)  # eq. 13 with zero slip
    w_r = w_c * r_out / r_b
    psi = cage_phase + 2 * np.pi * np.arange(z) / z
    force = math.hypot(p[sk.F_X], p[sk.F_Y])
    k = float(hertz.series_constant(p[sk.K_IN], p[sk.K_OUT]))
    offset = static_offset(
        k,
        psi,
        force,
        2 * p[sk.QUARTER_CLEARANCE] - p[sk.H_IN] - p[sk.H_OUT],
        math.atan2(p[sk.F_Y], p[sk.F_X]),
    )
    y[0:2] = offset
    y[8], y[9] = cage_phase, w_c
    balls = y[sk.NG :].reshape(z, sk.NB)
    balls[:, 0] = 0.5 * (offset[0] * np.cos(psi) + offset[1] * np.sin(psi))
    balls[:, 2] = psi
    balls[:, 3] = w_c
    balls[:, 5] = w_r
    return y


def atol(z: int) -> np.ndarray:
    """Absolute tolerances: positions 1e-9 m (1/10000 of a contact deflection),
    velocities 1e-5 m/s, angles 1e-5 rad, angular speeds 0.1 rad/s (1/1000 of the cage
    speed of the seed-004 case: the slip ratios come out to 1e-3). Tighter values
    multiply the step count by ten without changing the ball speeds beyond 1e-4
    (tests/unit/test_dynamics_slip.py)."""
    g = np.array([1e-9] * 4 + [1e-5] * 4 + [1e-5, 1e-1])
    ball = np.array([1e-9, 1e-5, 1e-5, 1e-1, 1e-5, 1e-1])
    return np.concatenate([g, np.tile(ball, z)])


# ------------------------------------------------- settling and what a record measures

#: Settling rule (:func:`settle`): whole cage revolutions of pure rolling, at least
#: MIN_SETTLE_TURNS, until the cage speed and spin ratios averaged over the last two
#: revolutions differ from those of the two before by at most SETTLE_TOLERANCE; at most
#: MAX_SETTLE_TURNS.
MIN_SETTLE_TURNS = 4
MAX_SETTLE_TURNS = 30
SETTLE_TOLERANCE = 1e-3
#: Two halves of a record whose spin or cage speed ratios differ by more than this are
#: reported (``Simulation.warnings``): half the 0.4 % by which seed 004's simulated and
#: measured ball-defect lines differ at 500 N (its table 3).
HALVES_TOLERANCE = 2e-3
_MAX_STEPS_PER_TURN = 2_000_000


def pure_rolling_speeds(p) -> tuple[float, float]:
    """Cage and ball spin speeds of pure rolling (eq. 13 with zero slip) [rad/s]."""
    w_i, r_in, r_out, r_b = p[sk.OMEGA_I], p[sk.R_IN], p[sk.R_OUT], p[sk.R_B]
    w_c = w_i * r_in / (r_in + r_out)
    return w_c, w_c * r_out / r_b


def phase_ratios(t, cage_angle, spin_phase, p) -> tuple[float, float]:
    """Cage speed ratio and ball spin ratio of a record, from the angles (not from
    sampled speeds): the advance of the cage angle and the mean advance of the balls'
    unwrapped spin phases over the record's span, over their pure-rolling values.

    The advance is the time integral of the speed however the speed varies
    between samples; the Z balls, evenly spread round the orbit, together sample every
    orbital position at every instant, so that the mean needs no whole number of cage
    turns. Mean sampled speeds are biased when the spin varies round the orbit faster
    than the sampling resolves it.

    Parameters
    ----------
    t : array (n,)
        Sample times [s].
    cage_angle : array (n,)
        theta_c [rad].
    spin_phase : array (Z, n)
        phi_j, continuous (unwrapped: the integrator never wraps it, and np.unwrap
        would fail on coarse samples, where the spin turns by more than pi between
        them) [rad].
    p : array
        The kernel's parameters (:func:`pack`).
    """
    span = float(t[-1] - t[0])
    w_c, w_r = pure_rolling_speeds(p)
    phase = np.asarray(spin_phase)
    return (
        float((cage_angle[-1] - cage_angle[0]) / span / w_c),
        float(np.mean(phase[:, -1] - phase[:, 0]) / span / w_r),
    )


def halves_check(t, cage_angle, spin_phase, p, tolerance: float = HALVES_TOLERANCE) -> dict:
    """Cage and spin ratios of each half of a record and whether they agree within
    ``tolerance`` [-] (a record still settling, or not long enough to be stationary,
    shows it here). Returns a dict with ``cage_speed_ratio``, ``spin_speed_ratio`` (pairs
    first/second half), ``difference`` (largest |second - first|), ``tolerance``,
    ``agree``."""
    mid = len(t) // 2
    first = phase_ratios(t[: mid + 1], cage_angle[: mid + 1], spin_phase[:, : mid + 1], p)
    second = phase_ratios(t[mid:], cage_angle[mid:], spin_phase[:, mid:], p)
    diff = float(max(abs(second[0] - first[0]), abs(second[1] - first[1])))
    return {
        "cage_speed_ratio": (first[0], second[0]),
        "spin_speed_ratio": (first[1], second[1]),
        "difference": diff,
        "tolerance": tolerance,
        "agree": diff <= tolerance,
    }


def settle(
    p,
    table,
    y0,
    rtol,
    atol,
    h_max,
    tolerance: float | None = None,
    min_turns: int | None = None,
    max_turns: int | None = None,
):
    """Integrate from ``y0`` until the motion has settled.

    How long that takes depends on how firmly the races grip the balls and on the
    cage: the ball spins recover within a revolution, but the cage's position against
    the balls, and with it the pocket forces that brake the unloaded balls, creeps
    towards its steady state through the small slip of the loaded balls, with a time
    constant of about 0.4 s at the seed's 6205 with 20 um clearance and
    ``cage_friction`` 0.3 (2400 rpm, 500 N; an amplitude of 2.5e-3 in the spin ratio);
    weak traction slows the cage too. So the settling time is detected, not fixed:
    the cage speed ratio and the spin ratio (:func:`phase_ratios`) are measured over
    each cage revolution of pure rolling, and the motion has settled when their means over the
    last two revolutions differ from those over the two before by at most
    ``tolerance`` (default SETTLE_TOLERANCE), after at least ``min_turns`` (default
    MIN_SETTLE_TURNS, 4: 0.25 s at 2400 rpm) and at most ``max_turns`` revolutions
    (MAX_SETTLE_TURNS). Averaging two revolutions keeps the turn-to-turn scatter
    (a few 1e-4) from deciding. A creep slower than the rule can see (the one above
    stops it after five turns, 1.7e-3 short of its end) or a transient that pauses and
    then moves on can still pass: give a longer ``settle`` where that matters; the
    record's halves check reports what is left when it exceeds HALVES_TOLERANCE.

    Returns (t, y, h, info): the integrator's time [s], state and step [s] to continue
    from, and ``info`` with ``turns``, ``settled`` (False if ``max_turns`` passed first),
    ``change`` (the last two-revolution change), the per-revolution
    ``cage_speed_ratios`` and ``spin_speed_ratios``, and the integrator's ``steps`` and
    ``rejected_steps``.
    """
    from ..errors import ConvergenceError
    from ._integrate import OK, STATUS_TEXT
    from ._rosenbrock import rosenbrock_chunk

    tolerance = SETTLE_TOLERANCE if tolerance is None else tolerance
    min_turns = MIN_SETTLE_TURNS if min_turns is None else max(int(min_turns), 4)
    max_turns = MAX_SETTLE_TURNS if max_turns is None else int(max_turns)
    w_c, _ = pure_rolling_speeds(p)
    period = 2 * math.pi / w_c
    t, y, h = 0.0, np.array(y0, dtype=float), 1e-6
    spin_cols = sk.NG + 4 + sk.NB * np.arange(int(p[sk.BALLS]))
    mark = y.copy()
    ratios = []  # (cage, spin) per revolution
    change = math.inf
    turn = steps = rejected = 0
    while turn < max(max_turns, min_turns):
        turn += 1
        out, t, y, h, s, r, status = rosenbrock_chunk(
            p, table, t, y, h, np.array([turn * period]), rtol, atol, h_max, _MAX_STEPS_PER_TURN
        )
        if status != OK:
            raise ConvergenceError(
                f"slip model: settling stopped at t = {t:.6g} s: "
                f"{STATUS_TEXT[status]}; try a looser rtol or check "
                "the inputs"
            )
        steps, rejected = steps + s, rejected + r
        ratios.append(
            phase_ratios(
                np.array([0.0, period]),
                np.array([mark[8], out[0, 8]]),
                np.stack([mark[spin_cols], out[0, spin_cols]], axis=1),
                p,
            )
        )
        mark = out[0]
        if turn >= 4:
            recent = np.mean(ratios[-2:], axis=0)
            before = np.mean(ratios[-4:-2], axis=0)
            change = float(np.max(np.abs(recent - before)))
        if turn >= min_turns and change <= tolerance:
            break
    cage, spin = (list(map(float, col)) for col in zip(*ratios, strict=True))
    return (
        t,
        y,
        h,
        {
            "turns": turn,
            "settled": change <= tolerance,
            "change": change,
            "cage_speed_ratios": cage,
            "spin_speed_ratios": spin,
            "steps": int(steps),
            "rejected_steps": int(rejected),
        },
    )
