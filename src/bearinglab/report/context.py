"""What every section of a report reads: the inputs and the results shared between
sections (the load distribution, the simulation)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..geometry import BallBearing
from ..operating import OperatingCondition


@dataclass
class Context:
    """Inputs of a report and the results its sections share.

    ``defects`` are the ones to simulate (an example outer-race defect when the user gave
    none, ``defects_given`` False); ``viscosity`` [m^2/s] is the operating kinematic
    viscosity and ``viscosity_source`` says where it came from (``lubricant``: the
    lubricant it was read from, None when the viscosity was given); ``duration``,
    ``sample_rate`` and ``slip_duration`` [s, Hz, s] set the simulations; ``results`` holds
    what one section computes for another ("load", "simulation", "slip").
    """

    bearing: BallBearing
    condition: OperatingCondition
    designation: object = None
    defects: tuple = ()
    defects_given: bool = False
    viscosity: float | None = None
    viscosity_source: str = ""
    lubricant: object = None
    duration: float = 1.0
    sample_rate: float = 25.6e3
    slip_duration: float = 0.1
    results: dict = field(default_factory=dict)

    @property
    def speed_rpm(self) -> float:
        """Shaft speed [rpm]."""
        return self.condition.shaft_speed * 30.0 / math.pi

    def need(self, key: str, what: str):
        """A shared result, or an error naming the section it comes from."""
        if key not in self.results:
            raise RuntimeError(f"this section needs the {what}, which failed (see its section)")
        return self.results[key]
