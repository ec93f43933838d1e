"""All form errors of one bearing, evaluated at the balls' contacts (layer 2).

The approach of ball j's contacts changes (seed 003, section 4, eqs. 7 and 16-17; seed 002
eq. 10) by

    inner contact:  a_i = r_i(theta_s-frame angle) + r_b(phi + pi) + (D_wj - D_w)/2
    outer contact:  a_o = -r_o(psi) + r_b(phi) + (D_wj - D_w)/2

r_i, r_o the radius deviations of the raceways (outward positive; waviness and random
surfaces) at the contact, in each ring's own frame: the outer ring is fixed, so its angle
is the ball's azimuth psi_j; the inner ring turns with the shaft, so its angle is
psi_j - theta_s (seed 003 eq. 14 writes it 2 pi (j-1)/N_b + (omega_c - omega_i) t).
r_b is the ball's radius deviation at the point facing each race: phi_j (the spin angle)
faces the outer race, phi_j + pi the inner race. The sum a_i + a_o is seed 003's
-(D_w - D_wk) + P_k with P_k = P_i - P_o (eq. 16) extended by the ball's own waviness: it
acts on the load distribution exactly like a ball diameter error (eq. 17), which is how
:func:`bearinglab.quasistatic.orbit.inner_ring_orbit` passes it to the solver.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from .surface import RandomSurface
from .waviness import BallSizeErrors, Waviness


class ContactDeviation(NamedTuple):
    """Approach changes at the inner and outer contacts of each ball [m] (positive: the
    contact is pressed harder; the opposite sign of the dynamic models'
    ``surface_deviation``, which is extra clearance)."""

    inner: np.ndarray
    outer: np.ndarray

    @property
    def total(self) -> np.ndarray:
        """a_i + a_o: the effective ball diameter error (seed 003 eq. 17) [m]."""
        return self.inner + self.outer


def _as_tuple(name: str, value, kind) -> tuple:
    items = () if value is None else (value,) if isinstance(value, kind) else tuple(value)
    for item in items:
        if not isinstance(item, kind):
            raise InputError(name, item, f"{kind.__name__} objects")
    return items


@dataclass(frozen=True)
class Imperfections:
    """Waviness, ball-size errors and random raceway surfaces of one bearing.

    Parameters
    ----------
    waviness : Waviness or sequence of Waviness
        Sinusoidal form errors (any number of orders, races and balls).
    ball_size_errors : BallSizeErrors or array (Z,), optional
        D_wj - D_w [m].
    surfaces : RandomSurface or sequence of RandomSurface
        3-D random raceway surfaces (seed 002 eq. 6); several on one race add up.

    Examples
    --------
    >>> import math
    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3)
    >>> imp = Imperfections([Waviness("outer", 7, 0.1e-6)], ball_size_errors=[1e-6] + [0.0] * 6)
    >>> d = imp.approach_change(b, 2 * math.pi * np.arange(7) / 7)
    >>> (d.outer * 1e6).round(3).tolist()
    [0.4, -0.1, -0.1, -0.1, -0.1, -0.1, -0.1]
    """

    waviness: tuple = ()
    ball_size_errors: BallSizeErrors | None = None
    surfaces: tuple = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "waviness", _as_tuple("waviness", self.waviness, Waviness))
        object.__setattr__(self, "surfaces", _as_tuple("surfaces", self.surfaces, RandomSurface))
        e = self.ball_size_errors
        if e is not None and not isinstance(e, BallSizeErrors):
            object.__setattr__(self, "ball_size_errors", BallSizeErrors(e))

    @property
    def is_empty(self) -> bool:
        """True when nothing deviates."""
        return not (
            self.waviness
            or self.surfaces
            or (self.ball_size_errors is not None and np.any(self.ball_size_errors.errors))
        )

    def check(self, bearing) -> None:
        """Refuse ball indices or ball-size error counts that do not fit ``bearing``.

        Parameters
        ----------
        bearing : BallBearing
            The bearing the form errors are on.

        Raises
        ------
        InputError
            If a ball index is not less than its ball count, or the ball-size errors are not
            one per ball or exceed +-5 % of D_w.
        """
        for item in self.waviness + self.surfaces:
            item.check(bearing)
        if self.ball_size_errors is not None:
            self.ball_size_errors.check(bearing)

    def raceway_deviation(self, race: str, angle, z=0.0):
        """Radius deviation of one raceway (waviness plus surfaces), outward positive [m].

        Parameters
        ----------
        race : {"inner", "outer"}
            Which raceway [-].
        angle : float or array
            Angle in that ring's own frame [rad].
        z : float or array
            Axial coordinate from the groove's mid-plane, for random surfaces [m].
        """
        if race not in ("inner", "outer"):
            raise InputError("race", race, "'inner' or 'outer'")
        angle = np.asarray(angle, float)
        out = np.zeros(np.broadcast_shapes(angle.shape, np.shape(z)))
        for w in self.waviness:
            if w.race == race:
                out = out + w.radius_deviation(angle)
        for s in self.surfaces:
            if s.race == race:
                out = out + s.height(angle, z)
        return out

    def surface_profile(self, race: str, angle, z):
        """Random-surface heights [m] of one raceway (``race``: "inner" or "outer") along
        ``z`` [m] at each ``angle`` [rad]: (..., n) for angle (...) and z (n,) (what
        :func:`ball_axial_shift` samples; waviness, constant across the groove, does not
        move the contacts axially).

        Parameters
        ----------
        race : {"inner", "outer"}
            The raceway.
        angle : array_like
            Angle in the ring's own frame [rad], any shape (...).
        z : array_like
            Axial positions across the raceway [m], shape (n,).

        Returns
        -------
        numpy.ndarray
            Height [m], shape (..., n); zero without a random surface on that race.
        """
        angle = np.asarray(angle, float)[..., None]
        out = np.zeros(angle.shape[:-1] + np.shape(z))
        for s in self.surfaces:
            if s.race == race:
                out = out + s.height(angle, np.asarray(z, float))
        return out

    def ball_deviation(self, spin_angle, ball_count: int):
        """Radius deviation of each ball at spin angle phi (the point facing the outer
        race) [m]; the last axis of ``spin_angle`` (broadcast to ``ball_count``) is the ball.

        Parameters
        ----------
        spin_angle : array_like
            Spin angle phi of each ball [rad] (0: the mark faces the outer race at time 0); its
            last axis, broadcast to ``ball_count``, is the ball.
        ball_count : int
            Number of balls Z.

        Returns
        -------
        numpy.ndarray
            Radius deviation r - R [m] of each ball, of the broadcast shape (..., Z).
        """
        phi = np.broadcast_to(
            np.asarray(spin_angle, float), np.broadcast_shapes(np.shape(spin_angle), (ball_count,))
        )
        out = np.zeros(phi.shape)
        for w in self.waviness:
            if w.race != "ball":
                continue
            r = w.radius_deviation(phi)
            if w.ball is None:
                out = out + r
            else:
                out[..., w.ball] += r[..., w.ball]
        return out

    def diameter_errors_at_rest(self, bearing, radial_load_angle: float) -> np.ndarray:
        """The form errors as effective ball-diameter errors for a quasi-static solve: the
        approach changes a_i + a_o of every ball of ``bearing`` at shaft angle 0, ball 0
        under the load, which acts at ``radial_load_angle`` [rad] (:meth:`approach_change`)
        [m], one per ball.

        Parameters
        ----------
        bearing : BallBearing
            The bearing the form errors are on.
        radial_load_angle : float
            Direction of the radial load [rad], from +x towards +y; ball 0 sits there.

        Returns
        -------
        numpy.ndarray
            Effective ball-diameter error [m] of each of the Z balls (positive: more approach).
        """
        z = bearing.ball_count
        psi = radial_load_angle + 2.0 * np.pi * np.arange(z) / z
        return self.approach_change(bearing, psi).total

    def approach_change(
        self, bearing, ball_angle, shaft_angle=0.0, spin_angle=0.0, *, z_inner=0.0, z_outer=0.0
    ) -> ContactDeviation:
        """Approach changes a_i, a_o at every ball's inner and outer contact (module
        docstring; seed 003 section 4 eqs. 7, 14-17), vectorised over balls and time.

        Parameters
        ----------
        bearing : BallBearing
            Geometry (Z).
        ball_angle : array (..., Z)
            Ball azimuths psi_j in the fixed frame, from +x towards +y [rad]; the last axis
            is the ball (ball 0 first).
        shaft_angle : float or array broadcastable to (..., 1)
            Inner-ring (shaft) rotation angle theta_s since time 0 [rad].
        spin_angle : float or array broadcastable to (..., Z)
            Ball spin angles phi_j: the point of the ball facing the outer race [rad].
        z_inner, z_outer : float or arrays broadcastable to (..., Z)
            Axial coordinates of the contacts in each ring's own frame, for random
            surfaces [m].

        Returns
        -------
        ContactDeviation
            ``inner``, ``outer`` (and ``total``), arrays (..., Z) [m].
        """
        self.check(bearing)
        z = bearing.ball_count
        psi = np.asarray(ball_angle, float)
        if psi.shape[-1:] != (z,):
            raise InputError("ball_angle", psi.shape, f"an array whose last axis has {z} balls")
        theta_s = np.asarray(shaft_angle, float)
        inner = self.raceway_deviation("inner", psi - theta_s, z_inner)
        outer = -self.raceway_deviation("outer", psi, z_outer)
        phi = np.asarray(spin_angle, float)
        facing_outer = self.ball_deviation(phi, z)
        facing_inner = self.ball_deviation(phi + math.pi, z)
        size = 0.0 if self.ball_size_errors is None else 0.5 * self.ball_size_errors.errors
        shape = np.broadcast_shapes(psi.shape, inner.shape, outer.shape, facing_outer.shape)
        return ContactDeviation(
            np.broadcast_to(inner + facing_inner + size, shape).copy(),
            np.broadcast_to(outer + facing_outer + size, shape).copy(),
        )

    def to_dict(self) -> dict:
        """JSON-ready description in engineering units."""
        return {
            "waviness": [w.to_dict() for w in self.waviness],
            "ball_size_errors": None
            if self.ball_size_errors is None
            else self.ball_size_errors.to_dict(),
            "surfaces": [s.to_dict() for s in self.surfaces],
        }
