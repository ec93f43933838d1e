"""Model objects of the noise model: the medium and the field point (layer 2).

Seed 003 part 4 (noise model assumptions (b)-(d), seed file line 769: air is an ideal,
still, uniform medium of constant properties; point A is 10 mm from the bearing centre,
line 771).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .sources import AIR_DENSITY, AIR_SOUND_SPEED


@dataclass(frozen=True)
class Air:
    """The medium: density rho_0 [kg/m^3] and speed of sound c_0 [m/s] (defaults: dry air
    at 20 deg C, 101.325 kPa). Seed 003's assumptions (b)-(d): an ideal, still, uniform
    medium of constant properties."""

    density: float = AIR_DENSITY
    sound_speed: float = AIR_SOUND_SPEED

    def __post_init__(self) -> None:
        for name, unit in (("density", "[kg/m^3]"), ("sound_speed", "[m/s]")):
            v = getattr(self, name)
            if (isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating))
                    or not math.isfinite(v) or v <= 0):
                raise InputError(name, v, f"a finite number > 0 {unit}")
            object.__setattr__(self, name, float(v))


@dataclass(frozen=True)
class FieldPoint:
    """Where the pressure is computed, in the bearing's radial plane: ``distance`` from the
    bearing centre [m] (seed 003: point A, 10 mm) and ``angle`` from +x towards +y [rad]
    (docs/conventions.md; default +y, above the bearing, on the line of a downward load:
    the seed's figure 6 is not in the text, so the direction is a choice)."""

    distance: float = 0.010
    angle: float = 0.5 * math.pi

    def __post_init__(self) -> None:
        for name, positive in (("distance", True), ("angle", False)):
            v = getattr(self, name)
            if (isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating))
                    or not math.isfinite(v) or (positive and v <= 0)):
                raise InputError(name, v, "a finite distance > 0 [m]" if positive
                                 else "a finite angle [rad]")
            object.__setattr__(self, name, float(v))

    @property
    def position(self) -> np.ndarray:
        """(x, y) of the point [m]."""
        return self.distance * np.array([math.cos(self.angle), math.sin(self.angle)])
