"""Noise of a running bearing with form errors: orbit and sound radiation together
(layer 3; seed 003 part 4, the flow chart of its fig. 8).

:func:`bearing_noise` runs the quasi-static time sweep of
:func:`bearinglab.quasistatic.orbit.inner_ring_orbit` with the bearing's imperfections
(waviness, ball-size errors: seed 003 eqs. 9-18) to get the inner-ring centre and the
ball centres over time (seed 003 figs. 9-10), differentiates them (figs. 9E-F, 11) and
radiates the velocities with :func:`.sound_pressure` (eqs. 19-27) at the field point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..operating import speed_error
from ..units import rad_s_to_rpm
from .model import FieldPoint, default_field_point
from .radiation import sound_pressure
from .result import SoundPressure

#: How the balls radiate in :func:`bearing_noise`: name -> description.
BALL_MODELS = {
    "radial": "pulsating sphere (eq. 23) driven by d(rho_j)/dt, the rate of change of the "
    "ball centre's distance from the bearing axis",
    "xy": "the x and y components of that vibration, each driving eq. 23 (the seed's "
    "figs. 11 and 13 A/B, read literally)",
    "oscillating": "a rigid sphere translating with that vibration (a dipole)",
}
#: Default sample rate of the orbit's time sweep [Hz].
SAMPLE_RATE = 8192.0


@dataclass(frozen=True, eq=False)
class BearingNoise:
    """The orbit (:class:`bearinglab.quasistatic.orbit.Orbit`), the sound at the point
    (:class:`.SoundPressure`) and the ball model used."""

    orbit: object
    sound: SoundPressure
    ball_model: str

    def to_dict(self) -> dict:
        """The sound's summary (the levels of :data:`.result.LEVELS` ...) with the
        operating point and the imperfections, in engineering units."""
        o = self.orbit
        out = self.sound.to_dict()
        out.update(
            {
                "speed_rpm": rad_s_to_rpm(o.condition.shaft_speed),
                "radial_load_n": o.condition.radial_load,
                "ball_model": self.ball_model,
                "points": int(o.time.size),
                "orbit_peak_to_peak_um": o.peak_to_peak * 1e6,
            }
        )
        if o.imperfections is not None:
            out["imperfections"] = o.imperfections.to_dict()
        return out

    def plot(self, axes=None):
        """Pressure and SPL against time on ``axes`` (as for
        :meth:`.SoundPressure.plot`).

        Parameters
        ----------
        axes : pair of matplotlib Axes or None
            Where to draw the pressure and the SPL; None: a new figure.
        """
        return self.sound.plot(axes)


def bearing_noise(
    bearing,
    condition,
    imperfections=None,
    *,
    duration: float | None = None,
    revolutions: float | None = None,
    points: int | None = None,
    point: FieldPoint | tuple | None = None,
    medium=None,
    ball_model: str = "radial",
    ring_model: str = "exact",
    **orbit_options,
) -> BearingNoise:
    """Sound pressure at a point of a bearing running with form errors (seed 003 part 4).

    Parameters
    ----------
    bearing : BallBearing
        Geometry (the inner-ring cylinder has radius d_i / 2, the balls D_w / 2).
    condition : OperatingCondition
        Radial load [N] and shaft speed > 0 [rad/s].
    imperfections : bearinglab.imperfections.Imperfections, optional
        Waviness, ball-size errors, random surfaces; None: a perfect bearing.
    duration : float, optional
        Length of the record [s]; default one cage revolution (a ball carries its size
        error round once).
    revolutions : float, optional
        Length in shaft revolutions instead [-].
    points : int, optional
        Instants of the time sweep; default SAMPLE_RATE x length (at least 256).
    point : FieldPoint or (distance, angle), optional
        Field point [m, rad]; default :func:`.model.default_field_point`: 10 mm outside
        the bearing's outside diameter, straight up (seed 003's point A, 10 mm from the
        centre, lies inside most bearings: pass :data:`.model.SEED003_POINT_A` for it).
    medium : Air, optional
        The air [kg/m^3, m/s].
    ball_model : {"radial", "xy", "oscillating"}
        How the balls radiate (:data:`BALL_MODELS`).
    ring_model : {"exact", "seed"}
        Cylinder solution, as in :func:`.sound_pressure`.
    **orbit_options
        Passed to ``inner_ring_orbit`` (``contact_angle``, ``surface_contact``, solver
        options such as ``lubricant``).

    Returns
    -------
    BearingNoise

    Notes
    -----
    The record is generally not a whole period of the motion (the inner-ring waviness
    turns with the shaft, the ball errors with the cage), so the velocities are
    detrended before the transform (``detrend=True`` of :func:`.sound_pressure`). The
    quasi-static orbit has kinks where a ball enters or leaves contact: its velocity
    jumps, the pressure (~ d v/dt at low frequency) spikes there and ``spl_time_max_db``
    grows with ``points``; ``spl_time_mean_db`` (the seed's figure-14 "mean SPL") does not.
    """
    from ..quasistatic.orbit import inner_ring_orbit, record_length

    if ball_model not in BALL_MODELS:
        raise InputError("ball_model", ball_model, f"one of {tuple(BALL_MODELS)}")
    if condition.shaft_speed <= 0:
        raise speed_error(condition.shaft_speed, "a speed > 0 rpm")
    length = record_length(
        bearing, condition, revolutions, duration, orbit_options.get("contact_angle")
    )
    if points is None:
        points = max(256, math.ceil(SAMPLE_RATE * length))
    if point is None:
        point = default_field_point(bearing)[0]
    orbit = inner_ring_orbit(
        bearing,
        condition,
        imperfections=imperfections,
        duration=length,
        points=points,
        **orbit_options,
    )
    t = orbit.time
    ring, radial = orbit.ring_velocity, orbit.ball_radial_velocity
    if ball_model == "radial":
        balls, source = radial, "pulsating"
    else:
        psi = orbit.ball_angle
        balls = radial[..., None] * np.stack([np.cos(psi), np.sin(psi)], axis=-1)
        source = "pulsating" if ball_model == "xy" else "oscillating"
    sound = sound_pressure(
        t,
        ring,
        balls,
        orbit.ball_angle,
        bearing,
        point=point,
        medium=medium,
        ring_model=ring_model,
        ball_source=source,
        detrend=True,
    )
    return BearingNoise(orbit, sound, ball_model)
