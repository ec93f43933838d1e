"""Dynamic simulation of ball bearings with localised defects (seeds 003 and 004).

- :mod:`.defects`: defect geometry and the surface table every model reads;
- :mod:`.rigid`: seed 003's rigid-ring 4-DOF model;
- :mod:`.slip`: seed 004's model with ball slip under EHL and a cage;
- :func:`simulate`: run either model, get a :class:`Simulation` with its signal.
"""

from .defects import Defect
from .rigid import RigidParameters
from .simulation import MODELS, Simulation, needs_compiling, simulate
from .slip import SlipParameters

__all__ = [
    "MODELS",
    "Defect",
    "RigidParameters",
    "Simulation",
    "SlipParameters",
    "needs_compiling",
    "simulate",
]
