"""bearinglab: mechanics, vibration, noise and diagnostics of rolling bearings.

The layers (docs/architecture.md): physics functions (``contact.hertz``, ``geometry``
functions, ``kinematics.frequency_orders``), model objects (``Material``,
``BallBearing``, ``Designation``), analyses (``ball_contacts``,
``defect_frequencies``) and interfaces (``bearinglab`` command line).
"""

from .errors import BearinglabError, CatalogError, ConvergenceError, DesignationError, InputError
from .geometry import BallBearing, Source
from .materials import BEARING_STEEL, SILICON_NITRIDE, Material

__version__ = "0.1.0"

__all__ = [
    "BEARING_STEEL", "SILICON_NITRIDE", "BallBearing", "BearinglabError", "CatalogError",
    "ConvergenceError", "DesignationError", "InputError", "Material", "Source",
]
