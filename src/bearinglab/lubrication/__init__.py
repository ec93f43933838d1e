"""Lubrication: lubricant properties and elastohydrodynamic film thickness.

- :mod:`.lubricant` — :class:`Lubricant` (viscosity, its temperature dependence,
  pressure-viscosity coefficient, Roelands' Z) and the built-in lubricants.
- :mod:`.ehl` — Hamrock-Dowson (1977) isothermal film thickness of point contacts,
  the film formula of seed 004 (eq. 6, as printed), entrainment speeds, and
  :func:`film_thickness` for a ball bearing.

Documentation: docs/capabilities/lubrication.md.
"""

from .ehl import (
    contact_ellipticity,
    dimensionless_groups,
    ellipticity_hamrock_dowson,
    entrainment_speed,
    film_thickness,
    hamrock_dowson_central,
    hamrock_dowson_film,
    hamrock_dowson_minimum,
    rolling_entrainment_speed,
    seed004_film_thickness,
)
from .lubricant import (
    ISO_VG68,
    LUBRICANTS,
    OPERATING_TEMPERATURE_RANGE,
    SEED004_GREASE,
    ZERO_CELSIUS,
    Lubricant,
    operating_viscosity,
    reynolds_viscosity,
    roelands_index,
    roelands_pressure_viscosity_coefficient,
)

__all__ = [
    "ISO_VG68",
    "LUBRICANTS",
    "OPERATING_TEMPERATURE_RANGE",
    "SEED004_GREASE",
    "ZERO_CELSIUS",
    "Lubricant",
    "operating_viscosity",
    "contact_ellipticity",
    "dimensionless_groups",
    "ellipticity_hamrock_dowson",
    "entrainment_speed",
    "film_thickness",
    "hamrock_dowson_central",
    "hamrock_dowson_film",
    "hamrock_dowson_minimum",
    "reynolds_viscosity",
    "roelands_index",
    "roelands_pressure_viscosity_coefficient",
    "rolling_entrainment_speed",
    "seed004_film_thickness",
]
