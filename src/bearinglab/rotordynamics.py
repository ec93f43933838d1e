"""One line from a bearing designation to a rotor-dynamics bearing element.

>>> # element = ross_bearing("6205", n=0, radial_load=500.0, speed_rpm=3000.0)
"""

from __future__ import annotations

import math

from .catalog import bearing_from_designation
from .operating import OperatingCondition
from .quasistatic import solve_load_distribution


def ross_bearing(designation: str, n: int, *, radial_load: float = 0.0,
                 axial_load: float = 0.0, speed_rpm: float = 0.0, damping: float = 0.0,
                 system: str | None = None, **overrides):
    """A ``ross.BearingElement`` for ``designation`` at its operating point.

    Builds the bearing from the catalogue (``overrides`` as for
    :func:`bearinglab.catalog.bearing_from_designation`, SI), solves the quasi-static load
    distribution and returns :meth:`LoadDistribution.to_ross`.

    Parameters
    ----------
    designation : str
        Bearing designation or catalogue name [-].
    n : int
        Shaft node of the bearing in the ROSS rotor [-].
    radial_load, axial_load : float
        Loads on the inner ring [N].
    speed_rpm : float
        Shaft speed [rpm].
    damping : float
        Direct damping [N s/m].
    system : str, optional
        "gost" or "iso" to force how the designation is read [-].
    """
    bearing, _ = bearing_from_designation(designation, system=system, overrides=overrides)
    condition = OperatingCondition(radial_load=radial_load, axial_load=axial_load,
                                   shaft_speed=speed_rpm * math.pi / 30)
    return solve_load_distribution(bearing, condition).to_ross(n, damping=damping)
