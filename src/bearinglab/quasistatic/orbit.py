"""Inner-ring centre orbit and ball-centre trajectories as the bearing turns (layer 3).

Two sweeps, both a sequence of quasi-static equilibria (the inner ring is in equilibrium
at every instant: low speed, no inertia):

- **Ball-set angle** (no imperfections): seed 001 (after eq. 5): "varying phi_0 from 0 to
  2 pi / z one can study the trajectory of the ring centre during rotation"; seed 002 eqs.
  1-5 and seed 003 (section 4, eqs. 1-8) do the same with per-ball diameter errors.
  Uniform balls repeat the orbit every ball spacing; with ball-size errors it repeats once
  per cage revolution (a ball carries its error round), so by default the sweep then
  covers a whole revolution of the ball set.
- **Time** (``imperfections``, ``revolutions`` or ``duration`` given): seed 003, section 4,
  eqs. 14-18 and figs. 9-11; seed 002 eq. 10. The inner ring turns at the shaft speed,
  the outer ring is fixed, the cage and the balls' spin follow the pure-rolling kinematics
  (:func:`bearinglab.kinematics.defect_frequencies`): at time t the shaft angle is
  theta_s = omega_i t, ball j is at psi_j = omega_c t + 2 pi j / Z (ball 0 at psi = 0 at
  time 0, docs/conventions.md) and has spun by phi_j = omega_b t (omega_b the ball spin
  speed relative to the cage, every ball from phi = 0). At each instant
  the imperfections are evaluated at the current contacts
  (:meth:`bearinglab.imperfections.Imperfections.approach_change`: a_i at the inner, a_o
  at the outer contact) and their sum a_i + a_o is passed to the solver as ball j's
  effective diameter error (seed 003 eq. 17: delta_k = [delta_r cos(theta_k) - (D_w -
  D_wk) + P_k]_+). The solver shares that error equally between the two contacts; the
  ball centre it returns is then moved by (a_i - a_o)/2 along the contact line, which
  puts it where the unequal split a_i, a_o holds it with the same loads (exact for
  collinear contacts, i.e. without centrifugal force). Random surfaces are evaluated at
  the axial positions of the contacts of the previous instant (``surface_contact =
  "solved"``) or where seed 002 eqs. 7-9 put them (``"axial_shift"``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, positive_number
from ..geometry import BallBearing
from ..operating import OperatingCondition, speed_error


@dataclass(frozen=True)
class Orbit:
    """Inner-ring centre and ball centres over the ball-set angle or over time.

    Attributes
    ----------
    bearing, condition : the inputs.
    ball_phase : array (N,)
        Azimuth of ball 0 [rad] (ball-set sweeps start with it under the radial load,
        seed 001's phi_0 = 0; time sweeps at psi = 0).
    x, y, z : arrays (N,)
        Inner-ring centre displacement [m].
    max_ball_load : array (N,)
        Largest contact load [N].
    time : array (N,) or None
        Time of each point [s] (time sweeps only).
    ball_angle : array (N, Z)
        Ball azimuths psi_j [rad].
    ball_centre : array (N, Z, 2)
        Ball centres (rho, z) in each ball's plane [m] (rho from the bearing axis).
    ball_load : array (N, Z)
        Largest contact load of each ball [N].
    effective_diameter_error : array (N, Z) or None
        a_i + a_o passed to the solver as D_wj - D_w [m].
    frequencies : dict or None
        ``shaft_hz``, ``cage_hz``, ``ball_spin_hz`` and the ``contact_angle_deg`` they
        were computed at (time sweeps).
    imperfections : Imperfections or None
        The form errors of a time sweep.
    max_pressure : array (N,) or None
        Largest maximum Hertz pressure of any contact [Pa] (the ISO 76 check of
        :func:`bearinglab.plausibility.contact_warnings`).
    """

    bearing: BallBearing
    condition: OperatingCondition
    ball_phase: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    max_ball_load: np.ndarray
    time: np.ndarray | None = None
    ball_angle: np.ndarray | None = None
    ball_centre: np.ndarray | None = None
    ball_load: np.ndarray | None = None
    effective_diameter_error: np.ndarray | None = None
    frequencies: dict | None = None
    imperfections: object = None
    max_pressure: np.ndarray | None = None

    @property
    def peak_to_peak(self) -> float:
        """Largest distance between two orbit points [m]."""
        pts = np.stack([self.x, self.y], axis=1)
        best = 0.0
        for start in range(0, len(pts), 512):
            chunk = pts[start : start + 512]
            best = max(best, float(np.max(np.linalg.norm(chunk[:, None] - pts[None, :], axis=-1))))
        return best

    @property
    def radial_peak_to_peak(self) -> float:
        """Peak-to-peak of the displacement along the radial load [m]."""
        a = self.condition.radial_load_angle
        along = self.x * math.cos(a) + self.y * math.sin(a)
        return float(np.ptp(along))

    @property
    def ball_x(self) -> np.ndarray:
        """Ball-centre x in the fixed frame, (N, Z) [m]."""
        return self.ball_centre[..., 0] * np.cos(self.ball_angle)

    @property
    def ball_y(self) -> np.ndarray:
        """Ball-centre y in the fixed frame, (N, Z) [m]."""
        return self.ball_centre[..., 0] * np.sin(self.ball_angle)

    @property
    def ball_radial_displacement(self) -> np.ndarray:
        """Ball-centre radius minus the pitch radius d_m/2, (N, Z) [m]."""
        return self.ball_centre[..., 0] - 0.5 * self.bearing.pitch_diameter

    def _needs_time(self) -> np.ndarray:
        if self.time is None or len(self.time) < 2:
            raise InputError(
                "time",
                None,
                "an orbit swept in time (imperfections, revolutions or duration given)",
            )
        return self.time

    @property
    def ring_velocity(self) -> np.ndarray:
        """Inner-ring centre velocity (dx/dt, dy/dt), (N, 2), central differences [m/s]
        (seed 003 fig. 9e-f)."""
        t = self._needs_time()
        return np.gradient(np.stack([self.x, self.y], axis=1), t, axis=0, edge_order=2)

    @property
    def ball_radial_velocity(self) -> np.ndarray:
        """d/dt of each ball centre's radius, (N, Z), central differences [m/s] (the
        pulsating-sphere source velocity; seed 003 fig. 11)."""
        return np.gradient(self.ball_centre[..., 0], self._needs_time(), axis=0, edge_order=2)

    def to_dict(self) -> dict:
        """JSON-ready orbit in um, degrees, seconds."""
        out = {
            "ball_phase_deg": np.degrees(self.ball_phase).tolist(),
            "x_um": (self.x * 1e6).tolist(),
            "y_um": (self.y * 1e6).tolist(),
            "z_um": (self.z * 1e6).tolist(),
            "max_ball_load_n": self.max_ball_load.tolist(),
            "orbit_peak_to_peak_um": self.peak_to_peak * 1e6,
            "radial_peak_to_peak_um": self.radial_peak_to_peak * 1e6,
        }
        if self.time is not None:
            out["time_s"] = self.time.tolist()
            out.update(self.frequencies or {})
        if self.ball_centre is not None:
            out["ball_angle_deg"] = np.degrees(self.ball_angle).tolist()
            out["ball_radial_displacement_um"] = (self.ball_radial_displacement * 1e6).tolist()
            out["ball_axial_um"] = (self.ball_centre[..., 1] * 1e6).tolist()
            out["ball_load_n"] = self.ball_load.tolist()
        if self.effective_diameter_error is not None:
            out["effective_diameter_error_um"] = (self.effective_diameter_error * 1e6).tolist()
        if self.imperfections is not None:
            out["imperfections"] = self.imperfections.to_dict()
        return out

    def plot(self, ax=None):
        """The orbit in the radial plane (um); returns (fig, ax)."""
        from ..plotting import _pyplot

        plt = _pyplot()
        fig, ax = plt.subplots(figsize=(5, 5)) if ax is None else (ax.figure, ax)
        ax.plot(self.x * 1e6, self.y * 1e6, ".-")
        ax.set_xlabel("x [um]")
        ax.set_ylabel("y [um]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(f"inner-ring centre orbit, peak to peak {self.peak_to_peak * 1e6:.3g} um")
        return fig, ax

    def plot_both(self):
        """The orbit (left) beside the inner ring's displacements and the balls' radial
        displacements against time or the ball-set angle (right); returns (fig, axes)."""
        from ..plotting import _pyplot

        fig = _pyplot().figure(figsize=(12, 5.5))
        grid = fig.add_gridspec(2, 2, width_ratios=(1, 1.4))
        left = fig.add_subplot(grid[:, 0])
        right = fig.add_subplot(grid[0, 1])
        below = fig.add_subplot(grid[1, 1], sharex=right)
        self.plot(ax=left)
        self.plot_history(axes=[right, below])
        fig.tight_layout()
        return fig, [left, right, below]

    def describe(self) -> str:
        """How many points the orbit has, over what time or ball-set angle."""
        if self.time is None:
            turn = np.degrees(self.ball_phase[-1] - self.ball_phase[0])
            return f"{self.x.size} positions over {turn:.4g} deg of the ball set"
        return (
            f"{self.time.size} instants over {self.time.size * (self.time[1] - self.time[0]):.4g} s"
        )

    def plot_history(self, axes=None):
        """Inner-ring x, y, z and the balls' radial displacements against time (or the
        ball-set angle), seed 003 figs. 9c-d and 10; returns (fig, axes)."""
        from ..plotting import _pyplot

        plt = _pyplot()
        fig, axes = (
            plt.subplots(2, 1, sharex=True, figsize=(7, 6))
            if axes is None
            else (axes[0].figure, axes)
        )
        abscissa = self.time if self.time is not None else np.degrees(self.ball_phase)
        for name, values in (("x", self.x), ("y", self.y), ("z", self.z)):
            axes[0].plot(abscissa, values * 1e6, label=name)
        axes[0].set_ylabel("inner ring [um]")
        axes[0].legend()
        if self.ball_centre is not None:
            axes[1].plot(abscissa, self.ball_radial_displacement * 1e6, lw=0.8)
        axes[1].set_ylabel("ball centre radius - d_m/2 [um]")
        axes[1].set_xlabel("time [s]" if self.time is not None else "ball 0 azimuth [deg]")
        return fig, axes


def _ball_state(result, bearing):
    """Per-ball centres (Z, 2), largest loads (Z,) and outer / inner contact angles of the
    most loaded contact of each race (Z,) from a LoadDistribution."""
    load = result.load
    angles = {}
    for race in (0, 1):
        cols = np.flatnonzero(result.ring == race)
        k = cols[np.argmax(load[:, cols], axis=1)]
        angles[race] = result.contact_angle[np.arange(bearing.ball_count), k]
    return np.array(result.ball_centre, float), load.max(axis=1), angles[1], angles[0]


def inner_ring_orbit(
    bearing: BallBearing,
    condition: OperatingCondition,
    *,
    imperfections=None,
    ball_diameter_errors=None,
    points: int | None = None,
    span: str | None = None,
    revolutions: float | None = None,
    duration: float | None = None,
    contact_angle: float | None = None,
    surface_contact: str = "solved",
    **options,
) -> Orbit:
    """Sweep the ball-set angle, or time, and solve the equilibrium at each position.

    Without ``imperfections``, ``revolutions`` and ``duration`` the ball set is turned with
    the rings still (the original sweep); with any of them the bearing runs in time (module
    docstring; seed 003 section 4 eqs. 14-18).

    Parameters
    ----------
    bearing : BallBearing
        Geometry.
    condition : OperatingCondition
        Loads; the speed sets the centrifugal force and, in a time sweep, the kinematics
        (must then be > 0).
    imperfections : bearinglab.imperfections.Imperfections, optional
        Waviness, ball-size errors and random surfaces (time sweep).
    ball_diameter_errors : array (Z,), optional
        D_wj - D_w of each ball [m] (added to the imperfections' in a time sweep).
    points : int, optional
        Ball-set sweep: positions per ball spacing, >= 2 (default 24). Time sweep: number
        of instants, >= 2, equally spaced over the duration without its end point (default
        64 per shaft revolution, at least 64).
    span : {"ball_spacing", "revolution"}, optional
        Ball-set sweep only: how far to turn the ball set; by default one ball spacing for
        uniform balls and a whole revolution with ball-size errors.
    revolutions : float, optional
        Time sweep over this many shaft revolutions [-].
    duration : float, optional
        Time sweep over this duration [s] (default: one cage revolution).
    contact_angle : float, optional
        Contact angle of the kinematics (cage and spin speeds) [rad]; nominal by default.
    surface_contact : {"solved", "axial_shift"}
        Where random surfaces are read across the groove: at the contacts of the previous
        instant's solution, or where seed 002 eqs. 7-9 put the ball
        (:func:`bearinglab.imperfections.ball_axial_shift`).
    **options
        Passed to :func:`bearinglab.quasistatic.solve_load_distribution` (``lubricant``,
        ``gyroscopic``, ``ring_expansion``, ...).

    Examples
    --------
    >>> from bearinglab.imperfections import Imperfections, Waviness
    >>> b = BallBearing(ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3,
    ...                 diametral_clearance=10e-6)
    >>> c = OperatingCondition(axial_load=20.0, shaft_speed=720 * math.pi / 30)
    >>> o = inner_ring_orbit(b, c, imperfections=Imperfections([Waviness("outer", 7, 0.1e-6)]),
    ...                      revolutions=1, points=16)
    >>> bool(np.ptp(o.z) > 0.05e-6), bool(o.peak_to_peak < 1e-12)  # q = Z: axial, not radial
    (True, True)
    """
    taken = sorted({"ball_phase", "ball_diameter_errors", "initial"} & set(options))
    if taken:
        raise InputError(taken[0], options[taken[0]], "not given: the sweep sets it")
    timed = imperfections is not None or revolutions is not None or duration is not None
    if not timed:
        points = 24 if points is None else points
        if isinstance(points, bool) or not isinstance(points, int) or points < 2:
            raise InputError("points", points, "an integer >= 2")
        return _ball_set_sweep(bearing, condition, ball_diameter_errors, points, span, options)
    if span is not None:
        raise InputError("span", span, "None in a time sweep (give revolutions or duration)")
    from ..imperfections import Imperfections

    if imperfections is None:
        imperfections = Imperfections()
    if not isinstance(imperfections, Imperfections):
        raise InputError("imperfections", imperfections, "an Imperfections object")
    if surface_contact not in ("solved", "axial_shift"):
        raise InputError("surface_contact", surface_contact, "'solved' or 'axial_shift'")
    if condition.shaft_speed <= 0:
        raise speed_error(condition.shaft_speed, "a speed > 0 rpm for a time sweep")
    imperfections.check(bearing)
    extra = None
    if ball_diameter_errors is not None:
        extra = np.asarray(ball_diameter_errors, float)
        if extra.shape != (bearing.ball_count,) or not np.all(np.isfinite(extra)):
            raise InputError(
                "ball_diameter_errors",
                ball_diameter_errors,
                f"{bearing.ball_count} finite values [m]",
            )
    return _time_sweep(
        bearing,
        condition,
        imperfections,
        extra,
        points,
        revolutions,
        duration,
        contact_angle,
        surface_contact,
        options,
    )


def _ball_set_sweep(bearing, condition, ball_diameter_errors, points, span, options) -> Orbit:
    errors = None if ball_diameter_errors is None else np.asarray(ball_diameter_errors, float)
    if span is None:
        span = "ball_spacing" if errors is None or not np.any(errors) else "revolution"
    if span not in ("ball_spacing", "revolution"):
        raise InputError("span", span, "'ball_spacing' or 'revolution'")
    spacing = 2.0 * math.pi / bearing.ball_count
    count = points if span == "ball_spacing" else points * bearing.ball_count
    phases = condition.radial_load_angle + spacing * np.arange(count + 1) / points
    from . import solve_load_distribution

    u, disp, balls, pressure = None, [], [], []
    for phase in phases:
        r = solve_load_distribution(
            bearing,
            condition,
            ball_phase=float(phase),
            ball_diameter_errors=errors,
            initial=u,
            **options,
        )
        u = r.displacement
        pressure.append(r.max_pressure)
        disp.append(u[:3].copy())
        balls.append(_ball_state(r, bearing)[:2] + (r.ball_angle,))
    disp = np.array(disp)
    centre, load, angle = (np.array(v) for v in zip(*balls, strict=True))
    eff = None if errors is None else np.broadcast_to(errors, angle.shape).copy()
    return Orbit(
        bearing,
        condition,
        phases,
        disp[:, 0],
        disp[:, 1],
        disp[:, 2],
        load.max(axis=1),
        ball_angle=angle,
        ball_centre=centre,
        ball_load=load,
        effective_diameter_error=eff,
        max_pressure=np.array(pressure),
    )


def record_length(bearing, condition, revolutions=None, duration=None, contact_angle=None) -> float:
    """Length of a time sweep [s]: ``revolutions`` of the shaft, or ``duration``, or by
    default one cage revolution (each ball carries its size error round once)."""
    from ..kinematics import defect_frequencies

    if revolutions is not None and duration is not None:
        raise InputError("duration", duration, "None when revolutions is given")
    freq = defect_frequencies(bearing, condition.shaft_speed, contact_angle=contact_angle)
    if revolutions is not None:
        return positive_number("revolutions", revolutions, "a number > 0") / freq.shaft_hz
    if duration is not None:
        return positive_number("duration", duration, "a duration > 0 [s]")
    return 1.0 / freq.hz("ftf")


def _time_sweep(
    bearing,
    condition,
    imperfections,
    extra,
    points,
    revolutions,
    duration,
    contact_angle,
    surface_contact,
    options,
) -> Orbit:
    from ..imperfections import ball_axial_shift
    from ..kinematics import defect_frequencies
    from . import solve_load_distribution

    freq = defect_frequencies(bearing, condition.shaft_speed, contact_angle=contact_angle)
    f_shaft, f_cage, f_spin = freq.shaft_hz, freq.hz("ftf"), freq.hz("bsf")
    length = record_length(bearing, condition, revolutions, duration, contact_angle)
    if points is None:
        points = max(64, math.ceil(64 * length * f_shaft))
    if isinstance(points, bool) or not isinstance(points, int) or points < 2:
        raise InputError("points", points, "an integer >= 2")
    z_count = bearing.ball_count
    t = length * np.arange(points) / points
    slots = 2.0 * math.pi * np.arange(z_count) / z_count
    cage = 2.0 * math.pi * f_cage * t
    psi = cage[:, None] + slots
    theta_s = (condition.shaft_speed * t)[:, None]
    phi = np.broadcast_to((2.0 * math.pi * f_spin * t)[:, None], psi.shape)
    radius = 0.5 * bearing.ball_diameter

    u, state = None, None
    if imperfections.surfaces:  # where the contacts sit across the groove at the start
        r0 = solve_load_distribution(bearing, condition, ball_phase=float(cage[0]), **options)
        u, state = r0.displacement, _ball_state(r0, bearing)
    disp = np.empty((points, 3))
    centres = np.empty((points, z_count, 2))
    loads = np.empty((points, z_count))
    errors = np.empty((points, z_count))
    pressure = np.empty(points)
    for k in range(points):
        z_i = z_o = 0.0
        if imperfections.surfaces and surface_contact == "solved":
            centre, _, beta_o, beta_i = state
            z_o = centre[:, 1] + radius * np.sin(beta_o)
            z_i = centre[:, 1] - radius * np.sin(beta_i) - u[2]
        elif imperfections.surfaces:
            shift = ball_axial_shift(
                bearing,
                inner_height=lambda z, k=k: imperfections.surface_profile(
                    "inner", psi[k] - theta_s[k], z
                ),
                outer_height=lambda z, k=k: imperfections.surface_profile("outer", psi[k], z),
                inner_offset=float(u[2]),
            )
            z_o, z_i = shift.outer_contact_z, shift.inner_contact_z - u[2]
        dev = imperfections.approach_change(
            bearing, psi[k], theta_s[k], phi[k], z_inner=z_i, z_outer=z_o
        )
        e = dev.total if extra is None else dev.total + extra
        r = solve_load_distribution(
            bearing,
            condition,
            ball_phase=float(cage[k]),
            ball_diameter_errors=e,
            initial=u,
            **options,
        )
        u = r.displacement
        state = _ball_state(r, bearing)
        centre, load, beta_o, _ = state
        move = 0.5 * (dev.inner - dev.outer)  # unequal split of the approach change
        centres[k, :, 0] = centre[:, 0] + move * np.cos(beta_o)
        centres[k, :, 1] = centre[:, 1] + move * np.sin(beta_o)
        disp[k], loads[k], errors[k], pressure[k] = u[:3], load, e, r.max_pressure
    frequencies = {
        "shaft_hz": f_shaft,
        "cage_hz": f_cage,
        "ball_spin_hz": f_spin,
        "contact_angle_deg": math.degrees(freq.contact_angle),
    }
    return Orbit(
        bearing,
        condition,
        cage,
        disp[:, 0],
        disp[:, 1],
        disp[:, 2],
        loads.max(axis=1),
        time=t,
        ball_angle=psi,
        ball_centre=centres,
        ball_load=loads,
        effective_diameter_error=errors,
        frequencies=frequencies,
        imperfections=imperfections,
        max_pressure=pressure,
    )
