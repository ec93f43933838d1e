"""Load ratings and rating life of ball bearings (ISO 281:2007, ISO 76:2006, ISO/TS 16281).

* :func:`load_ratings` -- basic dynamic rating C, static rating C_0 and fatigue load
  limit C_u from the internal geometry, or as given (:mod:`bearinglab.ratings.basic`).
* :func:`equivalent_dynamic_load`, :func:`equivalent_static_load` -- P (ISO 281 Table 3)
  and P_0 (ISO 76) (:mod:`bearinglab.ratings.equivalent`).
* :func:`rating_life` -- L10 = (C/P)^3, a_1, kappa, a_ISO and the modified life, or the
  ISO/TS 16281 reference life from the internal load distribution (:mod:`.life`,
  :mod:`.iso16281`), as a :class:`LifeResult` (:mod:`.result`). C and C_0 may be given
  (the maker's) instead of computed; the result says which.

Core API in SI units; coefficient tables and where each came from:
:mod:`bearinglab.ratings.tables`. The ratings and equivalent loads (layers 1-2, which the
quasi-static solver uses too) live in :mod:`bearinglab.ratings` and are re-exported here;
assumptions and checks: docs/capabilities/life.md.

>>> from bearinglab.catalog import bearing_from_designation
>>> from bearinglab.operating import OperatingCondition
>>> from bearinglab.units import rpm_to_rad_s
>>> b, _ = bearing_from_designation("6205")
>>> r = rating_life(b, OperatingCondition(radial_load=2000.0, shaft_speed=rpm_to_rad_s(1500)),
...                 viscosity=30e-6, contamination="high-cleanliness")
>>> round(r.ratings.dynamic), round(r.l10), round(r.a_iso, 2)
(14027, 345, 5.03)
"""

from ..ratings.basic import (
    LoadRatings,
    dynamic_load_rating,
    f0_factor,
    fatigue_load_limit,
    fc_factor,
    load_ratings,
    static_load_rating,
)
from ..ratings.equivalent import (
    LoadFactors,
    equivalent_dynamic_load,
    equivalent_static_load,
    load_factors,
    static_load_factors,
)
from .iso16281 import (
    conformity_ratio,
    contact_ratings,
    equivalent_ball_load,
    reference_life,
    reference_rating_life,
)
from .iso16281_roller import roller_contact_ratings, roller_reference_rating_life
from .life import (
    METHODS,
    LifeResult,
    ViscosityTooLow,
    basic_rating_life,
    contamination_factor,
    life_modification_factor,
    rated_viscosity,
    rating_life,
    reliability_factor,
)

__all__ = [
    "METHODS",
    "LifeResult",
    "LoadFactors",
    "LoadRatings",
    "basic_rating_life",
    "conformity_ratio",
    "contact_ratings",
    "contamination_factor",
    "dynamic_load_rating",
    "equivalent_ball_load",
    "equivalent_dynamic_load",
    "equivalent_static_load",
    "f0_factor",
    "fatigue_load_limit",
    "fc_factor",
    "life_modification_factor",
    "load_factors",
    "load_ratings",
    "rated_viscosity",
    "rating_life",
    "reference_life",
    "reference_rating_life",
    "reliability_factor",
    "roller_contact_ratings",
    "roller_reference_rating_life",
    "static_load_factors",
    "static_load_rating",
    "ViscosityTooLow",
]
