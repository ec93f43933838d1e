"""Sound radiated by a running ball bearing (seed 003 part 4, eqs. 19-27; seed 002).

* :mod:`.sources` (layer 1): the transfer functions of the sources -- a transversely
  vibrating cylinder for the inner ring (eq. 19), a pulsating sphere for each ball
  (eq. 23), a translating sphere as an alternative -- and SPL = 20 lg(p_e / 2e-5 Pa)
  (eq. 27);
* :mod:`.radiation` (layer 3): :func:`sound_pressure` sums them at a field point (eqs. 24,
  26) from velocity records and returns a :class:`SoundPressure` (levels, SPL against
  time, spectrum, directivity round the bearing);
* :mod:`.bearing` (layer 3): :func:`bearing_noise` runs the quasi-static orbit of a bearing
  with waviness and ball-size errors and radiates it (seed 003's whole chain, fig. 8).

See docs/capabilities/noise.md for the equations as read from the seeds, the choices and
the parameters the paper leaves out.
"""

from .bearing import BALL_MODELS, BearingNoise, bearing_noise
from .model import Air, FieldPoint
from .radiation import BALL_SOURCES, sound_pressure, velocity_from_positions
from .result import Directivity, SoundPressure
from .sources import (
    REFERENCE_PRESSURE,
    cylinder_transfer,
    effective_pressure,
    oscillating_sphere_transfer,
    pulsating_sphere_transfer,
    sound_pressure_level,
)

__all__ = [
    "BALL_MODELS", "BALL_SOURCES", "REFERENCE_PRESSURE", "Air", "BearingNoise", "Directivity",
    "FieldPoint", "SoundPressure", "bearing_noise", "cylinder_transfer", "effective_pressure",
    "oscillating_sphere_transfer", "pulsating_sphere_transfer", "sound_pressure",
    "sound_pressure_level", "velocity_from_positions",
]
