"""Bearing catalogue: ISO boundary dimensions, published internal geometries, estimates.

* :func:`boundary_dimensions` -- d, D, B (and T, C or height) of a designation from the
  ISO 15 / ISO 355 / ISO 104 dimension plans shipped in ``catalog/data``.
* :func:`published_geometry` -- internal geometry of specific bearings as their sources
  published it (CWRU 6205 and 6203, ER-16K, the Harris 209, ...).
* :func:`estimate_internal_geometry` -- Z, D_w, d_m, f_i, f_o from boundary dimensions by
  the deep-groove design rules cited in :mod:`bearinglab.catalog.estimate`.
* :func:`bearing_from_designation` -- a :class:`~bearinglab.geometry.BallBearing` (or,
  with ``rollers=True``, a :class:`~bearinglab.roller_geometry.RollerBearing` for
  cylindrical and tapered roller bearings) from a designation or catalogue name, every
  value tagged with its source.
* :func:`estimate_roller_geometry` -- Z, D_we, L_we, d_m of a roller bearing by the rules
  of :mod:`bearinglab.catalog.estimate_roller`.
* :func:`radial_clearance` -- the ISO 5753-1 radial internal clearance range (min, max)
  of a deep-groove ball bearing by bore and group (C2, CN, C3, C4, C5).
* :func:`catalog_table` -- the shipped tables as a DataFrame.

Core API in SI units (m, rad); the CSV files hold millimetres as catalogues print them.
"""

from .build import GeometryNeeded, bearing_from_designation, rolling_element_of
from .build_roller import published_roller_geometries
from .estimate import EstimatedGeometry, estimate_internal_geometry
from .estimate_roller import EstimatedRollerGeometry, estimate_roller_geometry
from .families import FAMILIES, Family
from .lookup import (
    BoundaryDimensions,
    PublishedGeometry,
    boundary_dimensions,
    catalog_table,
    published_geometries,
    published_geometry,
    radial_clearance,
)

__all__ = [
    "FAMILIES",
    "BoundaryDimensions",
    "EstimatedGeometry",
    "EstimatedRollerGeometry",
    "Family",
    "GeometryNeeded",
    "PublishedGeometry",
    "bearing_from_designation",
    "rolling_element_of",
    "boundary_dimensions",
    "catalog_table",
    "estimate_internal_geometry",
    "estimate_roller_geometry",
    "published_geometries",
    "published_geometry",
    "published_roller_geometries",
    "radial_clearance",
]
