"""Load ratings and equivalent loads of ball and roller bearings (ISO 281:2007, ISO
76:2006): layers 1 and 2, from the internal geometry alone (roller bearings:
:mod:`.roller`, which :func:`load_ratings` and the equivalent loads dispatch to).

* :func:`load_ratings` -- basic dynamic rating C, static rating C_0 and fatigue load
  limit C_u (:mod:`.basic`), as a :class:`LoadRatings`;
* :func:`equivalent_dynamic_load`, :func:`equivalent_static_load` -- P (ISO 281 Table 3)
  and P_0 (ISO 76) (:mod:`.equivalent`);
* :mod:`.tables` -- the coefficient tables of ISO 281, ISO 76 and ISO/TS 16281 and where
  each came from.

The quasi-static solver (the load against C_0) and the friction model use these; the rating
life (:func:`bearinglab.life.rating_life`, which solves load distributions for ISO/TS 16281)
sits above them and re-exports them. docs/capabilities/life.md.

>>> from bearinglab.catalog import bearing_from_designation
>>> b, _ = bearing_from_designation("6205")
>>> round(load_ratings(b).static)
7886
"""

from .basic import (
    LoadRatings,
    dynamic_load_rating,
    f0_factor,
    fatigue_load_limit,
    fc_factor,
    load_ratings,
    static_load_rating,
)
from .equivalent import (
    LoadFactors,
    equivalent_dynamic_load,
    equivalent_static_load,
    load_factors,
    static_load_factors,
)
from .roller import (
    roller_dynamic_load_rating,
    roller_equivalent_dynamic_load,
    roller_equivalent_static_load,
    roller_fatigue_load_limit,
    roller_fc_factor,
    roller_static_load_rating,
    tapered_factors,
)

__all__ = [
    "LoadFactors",
    "LoadRatings",
    "dynamic_load_rating",
    "equivalent_dynamic_load",
    "equivalent_static_load",
    "f0_factor",
    "fatigue_load_limit",
    "fc_factor",
    "load_factors",
    "load_ratings",
    "roller_dynamic_load_rating",
    "roller_equivalent_dynamic_load",
    "roller_equivalent_static_load",
    "roller_fatigue_load_limit",
    "roller_fc_factor",
    "roller_static_load_rating",
    "static_load_factors",
    "static_load_rating",
    "tapered_factors",
]
