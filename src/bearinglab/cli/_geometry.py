"""The bearing options every command takes, for a command written as
``f(designation, ..., *, geometry)``: :func:`with_geometry` gives it the table's bearing
inputs (:data:`bearinglab.inputs.BEARING`) as one ``geometry`` dict; new commands take
them with :func:`._inputs.takes` instead."""

import functools
import inspect

from ..inputs import BEARING, bearing_from, bearing_warnings
from ._inputs import takes

_GEOMETRY = tuple(n for n in BEARING if n != "designation")


def with_geometry(func):
    """Give a command the shared geometry options; it receives them as ``geometry``."""
    own = [p for p in inspect.signature(func).parameters.values() if p.name != "geometry"]

    @functools.wraps(func)
    def wrapper(values, **kwargs):
        return func(geometry=values, **kwargs)

    wrapper.__signature__ = inspect.Signature([*own, inspect.Parameter("values", 3)])
    del wrapper.__wrapped__
    return takes(*_GEOMETRY)(wrapper)


def resolve_bearing(designation, geometry: dict):
    """(BallBearing, Designation or None) of a designation and the geometry options."""
    return bearing_from({**geometry, "designation": designation})


def _geometry_warnings(bearing) -> list[str]:
    return bearing_warnings(bearing)
