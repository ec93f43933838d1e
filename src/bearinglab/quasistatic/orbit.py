"""Inner-ring centre orbit of a bearing as the ball set turns (layer 3).

Seed 001 (after eq. 5): "varying phi_0 from 0 to 2 pi / z one can study the trajectory of
the ring centre during rotation"; seed 002 eqs. 1-5 and seed 003 (noise section, eqs. 1-8
and 17-18) do the same with per-ball diameter errors. At low speed the inner ring is in
quasi-static equilibrium at every ball-set position, so the orbit is a sequence of
solves with the ball set rotated by phi_0. Uniform balls repeat the orbit every ball
spacing; with ball-size errors it repeats once per cage revolution (a ball carries its
error round), so by default the sweep then covers a whole revolution of the ball set.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..geometry import BallBearing
from ..operating import OperatingCondition


@dataclass(frozen=True)
class Orbit:
    """Inner-ring centre positions over the ball-set angle.

    Attributes: ``ball_phase`` (Z-independent angle of ball 1) [rad], ``x``, ``y``, ``z``
    [m] for each phase, ``max_ball_load`` [N] per phase, and the inputs.
    """

    bearing: BallBearing
    condition: OperatingCondition
    ball_phase: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    max_ball_load: np.ndarray

    @property
    def peak_to_peak(self) -> float:
        """Largest distance between two orbit points [m]."""
        pts = np.stack([self.x, self.y], axis=1)
        return float(np.max(np.linalg.norm(pts[:, None] - pts[None, :], axis=-1)))

    @property
    def radial_peak_to_peak(self) -> float:
        """Peak-to-peak of the displacement along the radial load [m]."""
        a = self.condition.radial_load_angle
        along = self.x * math.cos(a) + self.y * math.sin(a)
        return float(np.ptp(along))

    def to_dict(self) -> dict:
        """JSON-ready orbit in um and degrees."""
        return {"ball_phase_deg": np.degrees(self.ball_phase).tolist(),
                "x_um": (self.x * 1e6).tolist(), "y_um": (self.y * 1e6).tolist(),
                "z_um": (self.z * 1e6).tolist(),
                "max_ball_load_n": self.max_ball_load.tolist(),
                "orbit_peak_to_peak_um": self.peak_to_peak * 1e6,
                "radial_peak_to_peak_um": self.radial_peak_to_peak * 1e6}

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


def inner_ring_orbit(bearing: BallBearing, condition: OperatingCondition, *,
                     ball_diameter_errors=None, points: int = 24,
                     span: str | None = None, **options) -> Orbit:
    """Sweep the ball-set angle and solve the equilibrium at each position.

    Parameters
    ----------
    bearing : BallBearing
        Geometry.
    condition : OperatingCondition
        Loads (speed only sets the centrifugal force).
    ball_diameter_errors : array (Z,), optional
        D_wj - D_w of each ball [m].
    points : int
        Positions per ball spacing [-], >= 2.
    span : {"ball_spacing", "revolution"}, optional
        How far to turn the ball set; by default one ball spacing for uniform balls and a
        whole revolution with ball-size errors.
    **options
        Passed to :func:`bearinglab.quasistatic.solve_load_distribution` (``lubricant``,
        ``gyroscopic``, ``ring_expansion``, ...).
    """
    if isinstance(points, bool) or not isinstance(points, int) or points < 2:
        raise InputError("points", points, "an integer >= 2")
    errors = None if ball_diameter_errors is None else np.asarray(ball_diameter_errors, float)
    if span is None:
        span = "ball_spacing" if errors is None or not np.any(errors) else "revolution"
    if span not in ("ball_spacing", "revolution"):
        raise InputError("span", span, "'ball_spacing' or 'revolution'")
    spacing = 2.0 * math.pi / bearing.ball_count
    count = points if span == "ball_spacing" else points * bearing.ball_count
    phases = condition.radial_load_angle + spacing * np.arange(count + 1) / points
    from . import solve_load_distribution

    u, xs, ys, zs, qmax = None, [], [], [], []
    for phase in phases:
        r = solve_load_distribution(bearing, condition, ball_phase=float(phase),
                                    ball_diameter_errors=errors, initial=u, **options)
        u = r.displacement
        xs.append(u[0])
        ys.append(u[1])
        zs.append(u[2])
        qmax.append(float(np.max(r.load)))
    return Orbit(bearing, condition, phases, np.array(xs), np.array(ys), np.array(zs),
                 np.array(qmax))
