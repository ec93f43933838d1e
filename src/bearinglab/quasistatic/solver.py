"""Quasi-static load distribution of a single-row ball bearing (layer 3).

Model (seed 001, Balyakin et al. 2010, generalised to five ring degrees of freedom):
each ball has two unknowns, its centre (rho, z) in its own plane, and touches up to four
groove halves (two-, three- or four-point contact, seed 001 figs. 1-3), with the Hertz law
Q = K(alpha) delta^1.5 (K from the exact Hertz solution at the current contact angle),
the EHL film taking up part of the play (seed 001 eq. 2: the centre distance is
R_e + R_n - D_w + delta_e + delta_n - h_e - h_n) and the ball pressed outward by its
centrifugal force F_c = pi rho_b D_w^3 d_m omega_m^2 / 12 (seed 001, after eq. 3), with
omega_m Jones's orbital speed at the ball's own inner and outer contact angles under the
chosen raceway control, the same speed that sets the gyroscopic moment when it is
included (gyroscopic.py; Harris & Kotzalas, *Advanced Concepts of Bearing Technology*,
5th ed., 2007, ch. 3). A ball that does not touch both races orbits at the mean orbital
speed of those that do (the cage carries it). The outer ring is fixed (it may be tilted); the
inner ring moves by u = (x, y, z, tilt_x, tilt_y) (small rotations). Ball equilibrium
(seed 001 eqs. 5, 9, 11) is solved by Newton's method for all balls at once; ring
equilibrium (seed 001 eqs. 8, 12) by Newton's method on u with the analytic Jacobian
condensed over the balls,

    K = sum_j [ sum_i T^T S T - (sum_i T^T S) (sum_all S)^-1 (sum_i S T) ],

which is also the 5x5 tangent stiffness matrix of the bearing (i: inner contacts of ball
j, S = -dG/dv the contact's tangent matrix, T the ring kinematics; see _kernels.py).

Per-ball diameter errors (seed 003 noise section eq. 7) change each ball's free distance
to the groove centres. Not modelled: friction other than what holds the gyroscopic moment
(no traction calculation), ring deformation, thermal expansion.

The ring iteration runs compiled (_ring.ring_newton); :func:`_newton` below is its
Python reference, kept for the tests and the benchmark (``COMPILED_RING = False``).

A ball that touches nothing has no defined position; it is held on the outer race by a
floor of 1e-9 N on its centrifugal force, negligible against any carried load (this is
what seed 001's unloaded zone does at speed, fig. 5b).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import numpy as np

from ..errors import ConvergenceError, InputError
from ..geometry import BallBearing
from ..operating import OperatingCondition
from . import _kernels
from .grooves import ContactSet, contact_set

#: Floor of the outward force on every ball [N] (see the module docstring).
CENTRIFUGAL_FLOOR = 1e-9
#: Run the ring iteration compiled (False: the Python reference :func:`_newton`).
COMPILED_RING = True
#: Raceway controls: the race at which balls roll without spinning, and the share
#: lambda_i of the gyroscopic friction held at the inner contact (gyroscopic.py).
RACE_CONTROLS = ("outer", "inner", "hybrid")
DOF_NAMES = ("x", "y", "z", "tilt_x", "tilt_y")


def centrifugal_force(bearing: BallBearing, shaft_speed: float) -> float:
    """F_c = pi rho D_w^3 d_m omega_c^2 / 12 of one ball at pure-rolling cage speed [N].

    Seed 001 (after eq. 3); omega_c = omega (1 - D_w cos(alpha)/d_m)/2 with the inner ring
    turning at omega and the nominal contact angle.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and ball material.
    shaft_speed : float
        Inner-ring speed omega [rad/s].
    """
    omega_c = 0.5 * shaft_speed * (1.0 - bearing.gamma)
    return (
        math.pi
        * bearing.ball_material.density
        * bearing.ball_diameter**3
        * bearing.pitch_diameter
        * omega_c**2
        / 12.0
    )


def inner_ring_expansion(bearing: BallBearing, shaft_speed: float) -> float:
    """Radial growth of the inner raceway by the ring's own centrifugal force [m].

    The inner ring as a rotating annular disc with free edges, plane stress (Timoshenko S.,
    Goodier J. N., *Theory of Elasticity*, 3rd ed., 1970, sec. 32, rotating disc with a
    central hole): u(b) = rho omega^2 b / (4 E) ((3 + nu) a^2 + (1 - nu) b^2), a the bore
    radius, b the raceway (groove-bottom) radius. The fit on the shaft, which expands too,
    is ignored; the outer ring is fixed. The diametral clearance shrinks by 2 u(b).

    Parameters
    ----------
    bearing : BallBearing
        Geometry (needs the bore) and ring material.
    shaft_speed : float
        Inner-ring speed [rad/s].
    """
    if bearing.bore is None:
        raise InputError("bore", None, "a bore [m]", "needed for the inner ring's expansion")
    m = bearing.ring_material
    a, b = 0.5 * bearing.bore, 0.5 * bearing.inner_raceway_diameter
    return (
        m.density
        * shaft_speed**2
        * b
        / (4.0 * m.elastic_modulus)
        * ((3.0 + m.poisson_ratio) * a * a + (1.0 - m.poisson_ratio) * b * b)
    )


class _Problem:
    """Everything fixed during one solve: geometry arrays, loads, which DOFs are free,
    the speed-force parameters."""

    def __init__(
        self,
        bearing: BallBearing,
        condition: OperatingCondition,
        ball_phase: float,
        ball_diameter_errors,
        film,
        *,
        gyroscopic: bool = False,
        race_control: str = "outer",
    ) -> None:
        self.bearing, self.condition = bearing, condition
        z = bearing.ball_count
        self.contacts: ContactSet = contact_set(bearing)
        cs = self.contacts
        errors = (
            np.zeros(z)
            if ball_diameter_errors is None
            else np.asarray(ball_diameter_errors, dtype=float)
        )
        if (
            errors.shape != (z,)
            or not np.all(np.isfinite(errors))
            or np.any(np.abs(errors) > 0.05 * bearing.ball_diameter)
        ):
            raise InputError(
                "ball_diameter_errors",
                ball_diameter_errors,
                f"{z} finite values within +-5 % of D_w [m]",
            )
        self.free = cs.free_distance[None, :] - 0.5 * errors[:, None]  # (Z, C)
        self.film = (
            np.zeros((z, cs.count))
            if film is None
            else np.ascontiguousarray(np.broadcast_to(film, (z, cs.count)), dtype=float)
        )
        self.psi, self.t, self.c0_rho, self.c0_z = _placement(
            bearing, float(ball_phase), tuple(condition.outer_misalignment)
        )
        self.inner = cs.ring == 0
        self._side, self._ring = cs.side.astype(float), cs.ring.astype(np.int64)
        self.load = condition.load_vector()
        self.free_dofs = np.array([True, True, True, condition.tilt_free, condition.tilt_free])
        self.u_fixed = np.array([0, 0, 0, *condition.misalignment], dtype=float)
        self.scale = np.array([1, 1, 1, 2 / bearing.pitch_diameter, 2 / bearing.pitch_diameter])
        if race_control not in RACE_CONTROLS:
            raise InputError("race_control", race_control, " or ".join(RACE_CONTROLS))
        self.race_control = race_control
        omega = condition.shaft_speed
        dw, dm = bearing.ball_diameter, bearing.pitch_diameter
        rho_b = bearing.ball_material.density
        # cage speed of balls that do not touch both races: pure rolling at the nominal
        # angle until the solve gives the mean of the driven balls (solve updates spd[6])
        wm0 = 0.5 * omega * (1.0 - bearing.gamma)
        self.spd = np.array(
            [
                omega,
                dw / dm,
                0.5 * rho_b * math.pi * dw**3 / 6.0 * dm,
                rho_b * math.pi * dw**5 / 60.0,
                dw,
                float(gyroscopic),
                wm0,
                CENTRIFUGAL_FLOOR,
            ]
        )
        self.control = np.full(z, 1 if race_control == "inner" else 0, dtype=np.int64)
        self.lam_i = np.full(z, 2.0 if race_control == "inner" else 0.0)
        self.k_seat = float(np.max(cs.k_radial[~self.inner]))

    @property
    def fc(self) -> float:
        """Outward force on a ball orbiting at the cage speed of undriven balls [N]."""
        return max(self.spd[2] * self.spd[6] ** 2, CENTRIFUGAL_FLOOR)

    def set_control(self, outer_controlled) -> None:
        """Raceway control per ball (``hybrid``): outer where True, else inner with the
        gyroscopic friction shared lambda_i = lambda_o = 1 (Harris)."""
        outer_controlled = np.asarray(outer_controlled, bool)
        self.control = np.where(outer_controlled, 0, 1).astype(np.int64)
        self.lam_i = np.where(outer_controlled, 0.0, 1.0)

    def centres(self, u):
        shift = self.t @ u  # (Z, C, 2)
        c_rho = self.c0_rho + np.where(self.inner, shift[..., 0], 0.0)
        c_z = self.c0_z + np.where(self.inner, shift[..., 1], 0.0)
        return c_rho, c_z

    def ball_set(self) -> _kernels.BallSet:
        """The constants of the ball and ring kernels as they stand (the film, the raceway
        controls and the speed parameters change between solves)."""
        cs = self.contacts
        return _kernels.BallSet(
            t=self.t,
            c0_rho=self.c0_rho,
            c0_z=self.c0_z,
            inner=self.inner,
            free=self.free,
            radius=cs.groove_radius,
            side=self._side,
            z0=cs.z0,
            k_poly=cs.k_poly,
            film=self.film,
            ring=self._ring,
            control=self.control,
            lam_i=self.lam_i,
            spd=self.spd,
            k_seat=self.k_seat,
        )

    def solve_balls(self, b, u, tol, compiled: bool | None = None):
        """Newton's method on every ball's equilibrium for fixed ring displacement u
        (compiled kernel, or its NumPy twin with ``compiled=False``; see _kernels.py).

        A ball whose contact loads are all below 10 tol is loose: its position is arbitrary
        within the play (it may rattle between two barely touching contacts), so its
        residual is not required to vanish; what it adds to the ring is below 1e-8 of the
        load. Every other ball must be in equilibrium within ``tol``. A ball with no outer
        contact is put back on the outer race: its centrifugal force and any inner contact
        both push it outward. Returns (b, state), state = (q, n_rho, n_z, delta, speed
        (Z, 7), force of the balls on the inner ring, condensed stiffness).
        """
        tol = max(tol, 2.0 * CENTRIFUGAL_FLOOR)
        c_rho, c_z = self.centres(u)
        kernel = _kernels.solve_balls_numpy if compiled is False else _solve_balls_compiled()
        try:
            b, q, n_rho, n_z, delta, speed, force, stiffness, worst, ok = kernel(
                np.ascontiguousarray(b, dtype=float), c_rho, c_z, self.ball_set(), tol
            )
        except ZeroDivisionError:  # the compiled kernel's inf (a ball that touches nothing)
            b, worst, ok = b, math.inf, False
        if not ok:
            raise ConvergenceError(
                f"ball equilibrium did not converge: residual {worst:.3e} N "
                f"(tolerance {tol:.1e} N) at ring displacement {u.tolist()}"
            )
        return b, (q, n_rho, n_z, delta, speed, force, stiffness)

    def ring_force(self, state):
        """Generalised force (F_x, F_y, F_z, M_x, M_y) of the balls on the inner ring."""
        return state[5]

    def ring_force_and_stiffness(self, state):
        """Generalised force of the balls on the inner ring and the condensed stiffness."""
        return state[5], state[6]


@functools.lru_cache(maxsize=256)
def _placement(bearing: BallBearing, ball_phase: float, outer_misalignment: tuple):
    """Ball azimuths, ring kinematics T and groove centres with the inner ring centred,
    for one bearing and ball-set angle (cached: a stiffness map repeats them)."""
    cs = contact_set(bearing)
    z = bearing.ball_count
    psi = ball_phase + 2.0 * math.pi * np.arange(z) / z
    t = _kernels.ring_jacobian(psi, cs.rho0, cs.z0)  # (Z, C, 2, 5)
    inner = cs.ring == 0
    shift_o = t @ np.array([0, 0, 0, *outer_misalignment], dtype=float)  # (Z, C, 2)
    c0_rho = cs.rho0[None, :] + np.where(inner, 0.0, shift_o[..., 0])
    c0_z = cs.z0[None, :] + np.where(inner, 0.0, shift_o[..., 1])
    return psi, t, c0_rho, c0_z  # shared between solves: never written to


def _solve_balls_compiled():
    from . import _ball_set

    return _ball_set.solve_balls


def initial_ring_guess(problem: _Problem) -> np.ndarray:
    """A displacement along the load that closes the clearance and compresses the balls."""
    b = problem.bearing
    cs = problem.contacts
    load = problem.load
    k_n = float(np.min(cs.k_radial)) / 2**1.5  # two equal contacts in series
    u = problem.u_fixed.copy()
    fr = math.hypot(load[0], load[1])
    if fr > 0:
        q = 5.0 * fr / b.ball_count
        u[:2] = load[:2] / fr * (0.5 * b.diametral_clearance + (q / k_n) ** (2 / 3))
    if load[2] != 0:
        q = abs(load[2]) / b.ball_count / 0.5
        u[2] = math.copysign(0.5 * b.end_play + (q / k_n) ** (2 / 3), load[2])
    return u


def solve(
    bearing: BallBearing,
    condition: OperatingCondition,
    *,
    ball_phase: float | None = None,
    ball_diameter_errors=None,
    film=None,
    tolerance: float = 1e-9,
    max_iterations: int = 100,
    initial: np.ndarray | None = None,
    gyroscopic: bool = False,
    race_control: str = "outer",
    problem: _Problem | None = None,
):
    """Solve ring and ball equilibrium; returns (u, b, state, problem, stiffness).

    Without an initial guess, a combined load is solved in two stages: first the radial
    displacement with the axial one held at zero (the balls then touch), then all free
    degrees of freedom from there; starting both at once from a guess can leave a
    four-point or clearance bearing with no loaded ball and no useful Jacobian. When that
    fails, the load is reached in steps (:func:`_continuation`) and, at speed, the speed
    is raised in steps from rest (:func:`_speed_continuation`).
    See :func:`bearinglab.quasistatic.solve_load_distribution` for the public interface.
    """
    if ball_phase is None:
        ball_phase = condition.radial_load_angle
    if problem is None:
        problem = _Problem(
            bearing,
            condition,
            float(ball_phase),
            ball_diameter_errors,
            film,
            gyroscopic=gyroscopic,
            race_control=race_control,
        )
    if initial is None and condition.radial_load > 0:
        guess = initial_ring_guess(problem)
        guess[2] = 0.0
        radial_only = problem.free_dofs.copy()
        problem.free_dofs = np.array([True, True, False, False, False])
        try:  # a warm start only: a loose tolerance is enough
            initial = _ring(problem, max(tolerance, 1e-3), 30, guess)[0]
        except ConvergenceError:
            initial = None
        problem.free_dofs = radial_only
    try:
        return _ring(problem, tolerance, max_iterations, initial)
    except ConvergenceError as direct:
        try:
            return _continuation(problem, tolerance, max_iterations, direct)
        except ConvergenceError:
            if problem.spd[0] <= 0:
                raise
            return _speed_continuation(problem, tolerance, max_iterations, direct)


def _speed_continuation(
    problem: _Problem, tolerance: float, max_iterations: int, failure: ConvergenceError
):
    """Fallback at speed: solve at rest, then raise the speed in steps, each starting from
    the previous solution (ring and balls); steps are halved where Newton fails. At light
    thrust and high speed the balls roll far up the inner groove (alpha_i ~ 60 deg against
    alpha_o ~ 5 deg) and Newton's method cannot reach that state from a cold start."""
    target = problem.spd.copy()

    def at(fraction: float) -> None:
        problem.spd[0] = fraction * target[0]
        problem.spd[6] = fraction * target[6]

    problem.spd[0] = 0.0
    problem.spd[6] = 0.0
    try:
        return _march(problem, tolerance, max_iterations, failure, at)
    finally:
        problem.spd[:] = target


def _continuation(
    problem: _Problem, tolerance: float, max_iterations: int, failure: ConvergenceError
):
    """Fallback: reach the load in steps from its radial part alone (or a tenth of it),
    each step starting from the previous solution; steps are halved where Newton fails.
    Contacts that switch on and off (a ball crossing the cusp of a gothic arch, balls
    entering the load zone) can stall Newton's method from a distant start."""
    target = problem.load.copy()
    start = target.copy()
    start[2:] = 0.0
    if not np.any(start):
        start = 0.1 * target

    def at(fraction: float) -> None:
        problem.load = start + fraction * (target - start)

    problem.load = start
    try:
        return _march(problem, tolerance, max_iterations, failure, at)
    finally:
        problem.load = target


def _march(
    problem: _Problem,
    tolerance: float,
    max_iterations: int,
    failure: ConvergenceError,
    at: Callable[[float], None],
):
    """Solve ``problem`` as it stands, then move it by ``at(fraction)`` to fraction 1 in
    steps (a quarter at first, doubled up to a half after a success, halved after a
    failure), each solve starting from the last solution; ``failure`` is raised when the
    step falls below 1e-3 or the last solve fails."""
    try:
        u = _ring(problem, tolerance, max_iterations, None)[0]
        t, step = 0.0, 0.25
        while t < 1.0:
            trial = min(1.0, t + step)
            at(trial)
            try:
                u = _ring(problem, tolerance, max_iterations, u)[0]
                t, step = trial, min(0.5, 2 * step)
            except ConvergenceError:
                step *= 0.5
                if step < 1e-3:
                    raise failure from None
        return _ring(problem, tolerance, max_iterations, u)
    except ConvergenceError:
        raise failure from None


def _setup(problem: _Problem, tolerance: float, initial):
    bearing = problem.bearing
    load_norm = float(np.linalg.norm(problem.load * problem.scale))
    ball_tol = max(tolerance * max(load_norm, 1.0) / bearing.ball_count, 2 * CENTRIFUGAL_FLOOR)
    u = initial_ring_guess(problem) if initial is None else np.asarray(initial, float).copy()
    b = np.stack(
        [np.full(bearing.ball_count, 0.5 * bearing.pitch_diameter), np.zeros(bearing.ball_count)],
        axis=1,
    )
    # steps of the order of the play plus Hertz approaches; tilts a few mrad
    play = max(bearing.diametral_clearance, 0.0) + 0.005 * bearing.ball_diameter
    max_step = np.array([play, play, 4 * play, 0.005, 0.005])
    return u, b, ball_tol, tolerance * max(load_norm, 1.0), max_step


def _not_converged(problem: _Problem, residual: float, target: float, max_iterations: int):
    return ConvergenceError(
        f"ring equilibrium did not converge for F = {problem.load.round(6).tolist()} (N, N m): "
        f"residual {residual:.3e} (tolerance {target:.1e}) after "
        f"{max_iterations} iterations; the bearing may not carry this load"
    )


def _ring(problem: _Problem, tolerance: float, max_iterations: int, initial):
    """The ring iteration: compiled (COMPILED_RING) or the Python reference."""
    if not COMPILED_RING:
        return _newton(problem, tolerance, max_iterations, initial)
    from . import _ring as compiled

    u, b, ball_tol, target, max_step = _setup(problem, tolerance, initial)
    try:
        out = compiled.ring_newton(
            u,
            b,
            problem.free_dofs,
            problem.load,
            problem.scale,
            max_step,
            problem.ball_set(),
            ball_tol,
            target,
            max_iterations,
        )
    except ZeroDivisionError:  # numba's error where the NumPy twin has inf: no equilibrium
        raise _not_converged(problem, math.inf, target, max_iterations) from None
    u, b, q, n_rho, n_z, delta, speed, force, stiff, status, residual = out
    if status == 3:
        raise ConvergenceError(
            f"ball equilibrium did not converge at ring displacement {u.tolist()}"
        )
    if status == 2:
        raise ConvergenceError(
            f"ring equilibrium: no admissible step from {u.tolist()} for "
            f"F = {problem.load.round(6).tolist()}"
        )
    if status == 1:
        raise _not_converged(problem, residual, target, max_iterations)
    return u, b, (q, n_rho, n_z, delta, speed, force, stiff), problem, stiff


def solve_line(
    problem: _Problem, loads, initial, balls, tolerance: float = 1e-9, max_iterations: int = 100
):
    """Several loads on one problem in one compiled call, each from the previous solution
    (a stiffness-map line); see _ring.ring_newton_line. ``initial`` (5,) and ``balls``
    (Z, 2) are a converged neighbour's ring displacement and ball centres [m, rad].
    Returns (u (N, 5), stiffness (N, 5, 5), largest contact load (N,), status (N,), ball
    centres of the last case solved)."""
    from . import _ring as compiled

    _, _, _, _, max_step = _setup(problem, tolerance, initial)
    return compiled.ring_newton_line(
        np.ascontiguousarray(loads, dtype=float),
        np.asarray(initial, float),
        np.ascontiguousarray(balls, dtype=float),
        problem.free_dofs,
        problem.scale,
        max_step,
        problem.ball_set(),
        tolerance,
        CENTRIFUGAL_FLOOR,
        max_iterations,
    )


def _newton(problem: _Problem, tolerance: float, max_iterations: int, initial):
    """Newton's method with damping and an exact line search on the free ring DOFs (the
    Python reference of _ring.ring_newton)."""
    load = problem.load
    u, b, ball_tol, target, max_step = _setup(problem, tolerance, initial)
    free = problem.free_dofs
    b, state = problem.solve_balls(b, u, ball_tol)
    force, stiff = problem.ring_force_and_stiffness(state)
    r = (load + force) * problem.scale
    damping = 0.0
    for iteration in range(max_iterations + 1):
        norm = float(np.linalg.norm(r[free]))
        if norm <= target:
            return u, b, state, problem, stiff
        if iteration == max_iterations:
            break
        k_ff = stiff[np.ix_(free, free)]
        # Levenberg-Marquardt damping: grows while steps must be cut back (a ring that
        # touches only one or two balls is nearly singular), shrinks when Newton works
        diag = np.maximum(np.abs(np.diag(k_ff)), 1e-12 * np.max(np.abs(np.diag(k_ff))) + 1.0)
        try:
            du = np.linalg.solve(k_ff + damping * np.diag(diag), (load + force)[free])
        except np.linalg.LinAlgError:
            du = (load + force)[free] / diag
        if (load + force)[free] @ (du * problem.scale[free] ** 2) <= 0:
            du = (load + force)[free] / diag  # not a descent direction: use gradient
        limit = np.max(np.abs(du) / max_step[free])
        if limit > 1:
            du /= limit

        def along(lam, u=u, du=du, b=b):
            trial = u.copy()
            trial[free] += lam * du
            try:
                b_t, state_t = problem.solve_balls(b, trial, ball_tol)
            except ConvergenceError:  # far past contact onset: the step is too long
                return None
            force_t = problem.ring_force(state_t)
            return trial, b_t, state_t, force_t, (load + force_t) * problem.scale

        def slope(lam, du=du):
            at = along(lam)
            return -1e30 if at is None else float(at[4][free] @ (du * problem.scale[free]))

        step = along(1.0)
        newton_worked = step is not None and np.linalg.norm(step[4][free]) < 0.5 * norm
        damping = (
            0.0
            if newton_worked and damping < 1e-3
            else (damping * 0.1 if newton_worked else max(1e-3, 10.0 * damping))
        )
        if step is None or np.linalg.norm(step[4][free]) >= norm:
            # Newton overshoots (typically across the onset of contact): go to where the
            # residual turns against the step, i.e. the energy minimum along it.
            if slope(1.0) < 0 < slope(0.0):
                from scipy import optimize  # rarely needed; costs ~0.4 s to import

                step = along(optimize.brentq(slope, 0.0, 1.0, xtol=1e-12, rtol=1e-10, maxiter=200))
            if step is None:
                raise ConvergenceError(
                    f"ring equilibrium: no admissible step from "
                    f"{u.tolist()} for F = {load.round(6).tolist()}"
                )
        u, b, state, force, r = step
        stiff = problem.ring_force_and_stiffness(state)[1]
    raise _not_converged(problem, float(np.linalg.norm(r[free])), target, max_iterations)
