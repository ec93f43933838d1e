"""Quasi-static load distribution of a roller bearing (layer 3): cylindrical, needle and
tapered, one row or two (a back-to-back or face-to-face pair, a double-row bearing).

Model: the slice method of ISO/TS 16281:2008 with the rollers' own equilibrium. Each line
contact is cut into n_s slices ("laminae") along the roller; a slice of a contact carries
q = (c_1 / n_s) delta^(10/9), c_1 = 2^(10/9) c_l, so that a roller between both raceways
with equal inner and outer approaches obeys ISO/TS 16281's Q = c_l delta^(10/9),
c_l = 35 948 L_we^(8/9) N/mm^(10/9) (:mod:`bearinglab.contact.line`). The approach of a
slice is the rings' and the roller's rigid displacement along the contact normal less the
clearance, the roller's profile drop P(x) (once per contact, so 2 P(x) for the roller,
ISO/TS 16281 eq. 39) and the outer ring's imposed tilt. A tapered roller's large end
bears on the cone's rib, a Hertz point contact of its spherical end (radius
``roller_end_radius``) with the rib face, Q_f = K_f delta^1.5
(:func:`bearinglab.contact.hertz.load_deflection_constant` with R_x = R_y = the end
radius). Each roller is in equilibrium under its contacts and its centrifugal force
F_c = m (d_m/2) omega_c^2 at the pure-rolling cage speed omega_c = omega (1 - gamma)/2
(the centrifugal force of a roller of mass m on the pitch circle; Harris T. A., Kotzalas
M. N., *Advanced Concepts of Bearing Technology*, 5th ed., 2007, ch. 1, cylindrical and
tapered roller bearings at speed). The inner ring moves by u = (x, y, z, tilt_x, tilt_y)
(small rotations, docs/conventions.md), the outer ring is fixed (it may be tilted);
Newton's method on u with the analytic tangent stiffness condensed over the rollers
(:mod:`._roller_kernels`), which is also the 5x5 stiffness matrix of the bearing.

Without centrifugal force the rollers' equilibrium gives equal inner and outer slice
loads, and the model is exactly ISO/TS 16281's (the roller as one spring c_l per slice);
with it, the outer contacts carry the centrifugal force as well.

Kinds: cylindrical and needle rollers have no axial stiffness (their ribs are not
modelled): the axial load must be 0 and the axial displacement is not solved. A single
tapered row is in equilibrium only with an axial load above F_r tan(alpha) (its induced
axial force; 1.26 F_r tan(alpha) with half the raceway loaded), or with the axial
displacement imposed (``axial_displacement``), which gives the induced axial force as
the reaction. Two mirrored rows (back-to-back, face-to-face) take loads in both
directions; the axial clearance of the pair (negative: preload) sets them against each
other.

Not modelled: roller skew, friction at the rib and raceways, ring deformation, the edge
stress of an unprofiled roller beyond what the slices give (ISO/TS 16281's factors f_k
enter the life, :mod:`bearinglab.life.iso16281_roller`), the barrel rollers of spherical
roller bearings (refused).
"""

from __future__ import annotations

import math

import numpy as np

from ..contact.hertz import load_deflection_constant
from ..contact.line import iso16281_roller_constant, slice_positions
from ..errors import ConvergenceError, InputError
from ..materials import BEARING_STEEL, effective_modulus
from ..operating import OperatingCondition
from ..roller_geometry import RollerBearing
from . import _roller_kernels as kern
from .roller_result import RollerLoadDistribution

#: Default number of slices per line contact (ISO/TS 16281 uses n_s = 30 in its example).
DEFAULT_SLICES = 30
#: Outward force on every roller besides its centrifugal force [N]. 0: a roller the rings
#: do not load is free (its position is left where Newton puts it and it carries
#: nothing); a seating force as for balls would have to exceed what the contact law gives
#: at the approach floor (RollerSet.delta_floor), and would then load the rib.
SEATING_FLOOR = 0.0
#: Run the ring iteration compiled (False: the Python twin, for tests and benchmarks).
COMPILED = True
#: Cylindrical rollers at rest as two springs in series per slice pair, without the
#: rollers' equilibrium iteration (exact there, see RollerSet.series; False: iterate, for
#: the test that they agree).
SERIES_SHORTCUT = True
#: Approaches up to this fraction of D_we count as no contact (RollerSet.delta_floor): far
#: above the ring iteration's convergence noise (1e-9 of the approach) and round-off,
#: far below any load that matters (1e-6 N a slice at D_we = 10 mm).
DELTA_FLOOR = 1e-10


def roller_centrifugal_force(bearing: RollerBearing, shaft_speed: float) -> float:
    """F_c = m (d_m/2) omega_c^2 of one roller at the pure-rolling cage speed [N].

    omega_c = omega (1 - gamma)/2 with the inner ring turning at omega.

    Parameters
    ----------
    bearing : RollerBearing
        Geometry and roller material.
    shaft_speed : float
        Inner-ring speed omega [rad/s].

    Examples
    --------
    >>> from bearinglab.roller_geometry import RollerBearing
    >>> b = RollerBearing(roller_count=14, roller_diameter=10e-3, roller_length=9.6e-3,
    ...                   pitch_diameter=65.01e-3)
    >>> round(roller_centrifugal_force(b, 10000 * math.pi / 30), 2)
    37.67
    """
    omega_c = 0.5 * shaft_speed * (1.0 - bearing.gamma)
    return bearing.roller_mass * 0.5 * bearing.pitch_diameter * omega_c**2


def _check_slices(slices) -> int:
    if isinstance(slices, bool) or not isinstance(slices, (int, np.integer)) or slices < 1:
        raise InputError("slices", slices, "an integer in [1, 200]")
    if slices > 200:
        raise InputError("slices", slices, "an integer in [1, 200]")
    return int(slices)


class RollerProblem:
    """Everything fixed during one solve: the contact geometry of every roller, the loads,
    the free ring DOFs (layer 3 internals; built by :func:`solve_roller_distribution`)."""

    def __init__(
        self,
        bearing: RollerBearing,
        condition: OperatingCondition,
        slices: int,
        roller_phase: float,
        tolerance: float,
        axial_displacement: float | None = None,
    ) -> None:
        b = bearing
        self.bearing, self.condition, self.slices = b, condition, slices
        z = b.roller_count
        offsets, signs = b.row_layout()
        rows = len(offsets)
        self.row_offsets, self.row_signs = offsets, signs
        self.psi = np.tile(roller_phase + 2.0 * math.pi * np.arange(z) / z, rows)
        self.row = np.repeat(np.arange(rows), z)
        self.x = slice_positions(b.roller_length, slices)
        tapered = b.is_tapered
        ncon = 2 * slices + (1 if tapered else 0)
        self.n_contacts = ncon
        alpha_o, alpha_i = b.contact_angle, b.inner_angle
        alpha_m = 0.5 * (alpha_o + alpha_i)
        half_d, dm = 0.5 * b.roller_diameter, b.pitch_diameter
        length_scale = b.roller_length
        self.length_scale = length_scale

        def unit(angle):
            return np.array([math.cos(angle), math.sin(angle)])

        def tangent(angle):
            return np.array([-math.sin(angle), math.cos(angle)])

        e_o, e_i = unit(alpha_o), unit(alpha_i)
        t_o, t_i, t_r, n_r = tangent(alpha_o), tangent(alpha_i), tangent(alpha_m), unit(alpha_m)
        centre = np.array([0.5 * dm, 0.0])
        # contact points and normals in a row's own frame (sign +1), relative to its centre
        pts = np.zeros((ncon, 2))
        nrm = np.zeros((ncon, 2))
        pts[:slices] = centre - half_d * e_i + self.x[:, None] * t_i
        nrm[:slices] = e_i
        pts[slices : 2 * slices] = centre + half_d * e_o + self.x[:, None] * t_o
        nrm[slices : 2 * slices] = e_o
        if tapered:
            beta = b.flange_angle
            pts[-1] = centre - 0.5 * b.roller_length * t_r - 0.5 * half_d * n_r
            nrm[-1] = math.cos(beta) * t_r + math.sin(beta) * n_r
        sign = np.where(np.arange(ncon) < slices, 1.0, -1.0)
        inner = np.ones(ncon, bool)
        inner[slices : 2 * slices] = False
        if tapered:
            sign[-1] = 1.0
        power = np.full(ncon, kern_line_power())
        e_prime = effective_modulus(b.roller_material, b.ring_material)
        steel = effective_modulus(BEARING_STEEL, BEARING_STEEL)
        c_l = iso16281_roller_constant(b.roller_length, e_prime, steel)
        k_slice = 2.0 ** (10.0 / 9.0) * c_l / slices
        k = np.full(ncon, k_slice)
        if tapered:
            power[-1] = 1.5
            k[-1] = float(load_deflection_constant(b.end_radius, b.end_radius, e_prime))
        self.e_prime = e_prime
        self.slice_constant = k_slice
        drop = b.profile_drop(self.x)
        gap0 = np.zeros(ncon)
        gap0[:slices] += drop
        gap0[slices : 2 * slices] += drop
        # the clearance at the outer contacts, along their normal: radial play P_d and, for
        # two mirrored rows, axial play P_a shared by both rows
        gap0[slices : 2 * slices] += 0.5 * b.diametral_clearance * math.cos(alpha_o)
        if b.rows == 2 and b.arrangement in ("back_to_back", "face_to_face"):
            gap0[slices : 2 * slices] += 0.5 * b.axial_clearance * math.sin(alpha_o)
        nz = len(self.psi)
        sg = signs[self.row][:, None]
        z0 = offsets[self.row][:, None]
        p_rho = np.broadcast_to(pts[:, 0], (nz, ncon))
        p_z = z0 + sg * pts[:, 1]
        e_rho = np.ascontiguousarray(np.broadcast_to(nrm[:, 0], (nz, ncon)))
        e_z = np.ascontiguousarray(sg * nrm[:, 1])
        ring_arm = -p_z * e_rho + p_rho * e_z
        roller_arm = (-(p_z - z0) * e_rho + (p_rho - centre[0]) * e_z) / length_scale
        tox, toy = condition.outer_misalignment
        theta_o = tox * np.sin(self.psi) - toy * np.cos(self.psi)
        gap = gap0 + np.where(inner, 0.0, theta_o[:, None] * ring_arm)
        self.contact_rho, self.contact_z = np.ascontiguousarray(p_rho), p_z
        w = condition.shaft_speed
        self.centrifugal_force = roller_centrifugal_force(b, w) if w > 0 else 0.0
        fext = np.full(nz, self.centrifugal_force + SEATING_FLOOR)
        dof = np.array([True, tapered, True])
        load = condition.load_vector()
        self.load = load
        self.scale = np.array([1.0, 1.0, 1.0, 2.0 / dm, 2.0 / dm])
        load_norm = float(np.linalg.norm(load * self.scale))
        self.target = tolerance * max(load_norm, 1.0)
        roller_tol = max(0.05 * self.target / nz, 1e-12)
        self.rs = kern.RollerSet(
            psi=self.psi,
            e_rho=e_rho,
            e_z=e_z,
            ring_arm=ring_arm,
            roller_arm=roller_arm,
            sign=sign,
            inner=inner,
            k=np.ascontiguousarray(np.broadcast_to(k, (nz, ncon))),
            power=power,
            gap=gap,
            fext=fext,
            dof=dof,
            max_step=0.01 * b.roller_diameter,
            tol=roller_tol,
            delta_floor=DELTA_FLOOR * b.roller_diameter,
            series=bool(SERIES_SHORTCUT and not tapered and self.centrifugal_force == 0.0),
        )
        free = np.array([True, True, tapered, condition.tilt_free, condition.tilt_free])
        fixed = np.array([0.0, 0.0, 0.0, *condition.misalignment])
        if axial_displacement is not None:
            free[2] = False
            fixed[2] = axial_displacement
        self.free, self.fixed = free, fixed
        self.max_step = np.array([1, 1, 1, 2.0 / dm, 2.0 / dm]) * 0.02 * b.roller_diameter

    def initial_guess(self) -> np.ndarray:
        """A ring displacement near the solution: Stribeck's Q_max = 4.08 F_r / (Z cos a)
        for the radial part, the axial load shared by all rollers of the loaded row for
        the axial part (tapered), the clearance added [m, rad]."""
        b, c = self.bearing, self.condition
        u = self.fixed.copy()
        z = b.roller_count
        c_l = self.slice_constant * self.slices / 2.0 ** (10.0 / 9.0)
        alpha = b.contact_angle
        if c.radial_load > 0:
            q = 4.08 * c.radial_load / (z * b.rows * math.cos(alpha))
            radial = (q / c_l) ** 0.9 / math.cos(alpha) + 0.5 * b.diametral_clearance
            u[0] = radial * math.cos(c.radial_load_angle)
            u[1] = radial * math.sin(c.radial_load_angle)
        if b.is_tapered and self.free[2] and c.axial_load != 0.0:
            q = abs(c.axial_load) / (z * math.sin(alpha))
            axial = (q / c_l) ** 0.9 / math.sin(alpha)
            if b.rows == 2 and b.arrangement in ("back_to_back", "face_to_face"):
                axial += 0.5 * max(b.axial_clearance, 0.0)
            u[2] = math.copysign(axial, c.axial_load)
        return u

    def initial_rollers(self, u) -> np.ndarray:
        """Roller states from the ring displacement: each roller where its inner and outer
        slice approaches are equal (the solution without centrifugal force and rib, fitted
        by least squares over the slices), a start for Newton [m]."""
        rs, s = self.rs, self.slices
        proj, _ = kern._projection_numpy(u, rs)
        # inner slice k and outer slice k: B_i.v - B_o.v ... equal approaches give, along
        # each normal, B.v = (proj_i - g_i + g_o) / 2 for the inner contact of the pair
        target = 0.5 * (proj[:, :s] - rs.gap[:, :s] + rs.gap[:, s : 2 * s])
        b = np.stack([rs.e_rho[:, :s], rs.e_z[:, :s], rs.roller_arm[:, :s]], axis=-1)
        b = b * rs.dof
        normal = np.einsum("jki,jkl->jil", b, b) + np.diag(1.0 - rs.dof)
        return np.linalg.solve(normal, np.einsum("jki,jk->ji", b, target)[..., None])[..., 0]


def kern_line_power() -> float:
    """The slices' load-deflection exponent, 10/9 [-]."""
    return 10.0 / 9.0


def _check(bearing: RollerBearing, condition: OperatingCondition, axial_displacement) -> None:
    if not isinstance(bearing, RollerBearing):
        raise InputError("bearing", type(bearing).__name__, "a RollerBearing")
    if not bearing.contact_modelled:
        raise InputError(
            "bearing_type",
            bearing.bearing_type,
            "a cylindrical, needle or tapered roller bearing",
            "the barrel-roller contact of a spherical roller bearing is not modelled "
            "(only its kinematic frequencies are)",
        )
    if not bearing.is_tapered:
        if condition.axial_load != 0.0:
            raise InputError(
                "axial_load",
                condition.axial_load,
                "0 for a cylindrical or needle roller bearing",
                "its rollers take no axial load on their raceways and the rib contacts "
                "(NJ, NUP) are not modelled",
            )
        if axial_displacement is not None:
            raise InputError(
                "axial_displacement",
                axial_displacement,
                "None for a cylindrical or needle roller bearing",
                "its axial position does not load the rollers",
            )
        return
    if axial_displacement is not None:
        if not (isinstance(axial_displacement, (int, float)) and math.isfinite(axial_displacement)):
            raise InputError("axial_displacement", axial_displacement, "a finite length [m]")
        return
    if bearing.rows == 1:
        induced = condition.radial_load * math.tan(bearing.contact_angle)
        if condition.axial_load <= induced:
            raise InputError(
                "axial_load",
                condition.axial_load,
                f"more than F_r tan(alpha) = {induced:.6g} N for a single tapered row",
                "under a radial load a tapered roller bearing pushes its rings apart with an "
                f"induced axial force (about 1.26 F_r tan(alpha) = {1.26 * induced:.4g} N with "
                "half the raceway loaded); give a larger axial load, an axial_displacement, "
                "or a pair (arrangement back_to_back or face_to_face)",
            )


def solve_roller_distribution(
    bearing: RollerBearing,
    condition: OperatingCondition,
    *,
    slices: int = DEFAULT_SLICES,
    roller_phase: float | None = None,
    tolerance: float = 1e-9,
    initial=None,
    axial_displacement: float | None = None,
    max_iterations: int = 100,
) -> RollerLoadDistribution:
    """Quasi-static equilibrium of a roller bearing under ``condition``.

    Parameters
    ----------
    bearing : RollerBearing
        Cylindrical, needle or tapered roller bearing (one row or two).
    condition : OperatingCondition
        Loads on the inner ring (the axial load 0 for cylindrical bearings), a tilting
        moment or imposed misalignments, the outer ring's misalignment, shaft speed.
    slices : int
        Slices per line contact n_s [-].
    roller_phase : float, optional
        Azimuth of roller 1 [rad]; by default the direction of the radial load (a roller on
        the load line).
    tolerance : float
        Ring equilibrium tolerance relative to the load [-].
    initial : array (5,), optional
        Starting ring displacement [m, rad].
    axial_displacement : float, optional
        Tapered bearings: impose the inner ring's axial displacement instead of solving it
        (the axial load is then the reaction, e.g. the induced axial force at 0) [m].
    max_iterations : int
        Ring Newton iterations [-].

    Returns
    -------
    RollerLoadDistribution

    Raises
    ------
    InputError
        An axial load on a cylindrical bearing, a single tapered row without enough axial
        load, a spherical roller bearing, bad slices.
    ConvergenceError
        When no equilibrium is found (the message names the case and the residual).
    """
    _check(bearing, condition, axial_displacement)
    n_s = _check_slices(slices)
    if not (isinstance(tolerance, (int, float)) and 0 < tolerance < 1e-2):
        raise InputError("tolerance", tolerance, "a value in (0, 0.01)")
    phase = condition.radial_load_angle if roller_phase is None else float(roller_phase)
    problem = RollerProblem(bearing, condition, n_s, phase, tolerance, axial_displacement)
    if initial is None:
        u0 = problem.initial_guess()
    else:
        u0 = np.array(initial, dtype=float)
        if u0.shape != (5,) or not np.all(np.isfinite(u0)):
            raise InputError("initial", initial, "5 finite values [m, rad]")
        u0[~problem.free] = problem.fixed[~problem.free]
    v0 = problem.initial_rollers(u0)
    if COMPILED:
        from . import _roller_compiled

        newton = _roller_compiled.ring_newton
    else:
        newton = kern.ring_newton_numpy
    u, v, q, delta, force, stiff, status, residual = newton(
        u0,
        v0,
        problem.free,
        problem.load,
        problem.scale,
        problem.max_step,
        problem.rs,
        problem.target,
        max_iterations,
    )
    if status != 0:
        raise ConvergenceError(_failure(bearing, condition, status, residual, problem.target))
    return RollerLoadDistribution.from_solution(problem, u, v, q, delta, force, stiff)


def _failure(bearing, condition, status, residual, target) -> str:
    what = {
        1: "did not converge within the iterations",
        2: "found no step that reduces the residual",
        3: "could not place the rollers at the start",
    }[int(status)]
    return (
        f"roller load distribution of {bearing.name or bearing.bearing_type} under "
        f"F_r = {condition.radial_load:.6g} N, F_a = {condition.axial_load:.6g} N "
        f"{what} (residual {residual:.3g} against {target:.3g})"
    )
