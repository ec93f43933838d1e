"""Sound radiated by a running ball bearing (seed 003 part 4, eqs. 19-27; seed 002).

* :mod:`.sources` (layer 1): the transfer functions of the sources -- a transversely
  vibrating cylinder for the inner ring (eq. 19), a pulsating sphere for each ball
  (eq. 23), a translating sphere as an alternative -- and SPL = 20 lg(p_e / 2e-5 Pa)
  (eq. 27);
* :mod:`.radiation` (layer 3): :func:`sound_pressure` sums them at a field point (eqs. 24,
  26) from velocity records and returns a :class:`SoundPressure` (levels, SPL against
  time, spectrum, directivity round the bearing);
* :mod:`.bearing` (layer 3): :func:`bearing_noise` runs the quasi-static orbit of a bearing
  with waviness and ball-size errors and radiates it (seed 003's whole chain, fig. 8);
* :mod:`.bands` (layer 3): :func:`bearing_velocity_bands`, the ISO 15242 vibration velocity
  bands of a bearing at an operating point (the orbit or the rigid dynamic model);
* :mod:`.analysis` (layer 3): :func:`noise_analysis`, all of it for one operating point
  (the ``noise`` command and the report): levels, spectrum lines, bands, plot.

See docs/capabilities/noise.md for the equations as read from the seeds, the choices and
the parameters the paper leaves out.
"""

from .analysis import LEVEL_ROWS, NoiseAnalysis, noise_analysis
from .bands import BAND_SOURCES, BearingVelocityBands, bearing_velocity_bands
from .bearing import BALL_MODELS, BearingNoise, bearing_noise
from .model import (
    FIELD_POINT_GAP,
    SEED003_POINT_A,
    Air,
    FieldPoint,
    check_field_point,
    default_field_point,
    least_field_distance,
)
from .radiation import BALL_SOURCES, sound_pressure, velocity_from_positions
from .result import LEVELS, Directivity, SoundPressure
from .sources import (
    REFERENCE_PRESSURE,
    cylinder_transfer,
    effective_pressure,
    oscillating_sphere_transfer,
    pulsating_sphere_transfer,
    sound_pressure_level,
)

__all__ = [
    "BALL_MODELS",
    "BALL_SOURCES",
    "BAND_SOURCES",
    "FIELD_POINT_GAP",
    "LEVELS",
    "LEVEL_ROWS",
    "REFERENCE_PRESSURE",
    "SEED003_POINT_A",
    "Air",
    "BearingNoise",
    "BearingVelocityBands",
    "Directivity",
    "FieldPoint",
    "NoiseAnalysis",
    "SoundPressure",
    "bearing_noise",
    "bearing_velocity_bands",
    "check_field_point",
    "cylinder_transfer",
    "default_field_point",
    "effective_pressure",
    "least_field_distance",
    "noise_analysis",
    "oscillating_sphere_transfer",
    "pulsating_sphere_transfer",
    "sound_pressure",
    "sound_pressure_level",
    "velocity_from_positions",
]
