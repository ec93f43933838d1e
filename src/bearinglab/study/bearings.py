"""A case's bearing for the study machinery and the data sets: the bearing inputs of
:data:`bearinglab.inputs.BEARING`, built once per process (a study asks for the same few
bearings again and again) by :func:`bearinglab.inputs.bearing_from`."""

from __future__ import annotations

import functools

from ..errors import InputError
from ..inputs import BEARING, GEOMETRY_NEEDED, INPUTS, bearing_from

#: The bearing inputs a case may give: name -> Input.
BEARING_OPTIONS = {name: INPUTS[name] for name in BEARING if name != "geometry"}


def check_bearing_given(given: set) -> None:
    """A study needs a designation or the explicit geometry (checked before it runs)."""
    if "designation" not in given and not set(GEOMETRY_NEEDED) <= given:
        raise InputError(
            "designation", None, "a designation, or balls, ball_diameter_mm and pitch_diameter_mm"
        )


@functools.lru_cache(maxsize=256)
def _bearing(values: tuple):
    return bearing_from(dict(values))[0]


def bearing_of(case: dict):
    """The BallBearing of a case (designation and/or geometry inputs)."""
    return _bearing(tuple((n, case.get(n)) for n in BEARING_OPTIONS if case.get(n) is not None))
