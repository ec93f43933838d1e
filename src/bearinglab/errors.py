"""Exceptions raised by bearinglab.

Every error a user can provoke with bad input is an :class:`InputError` that
names the parameter, the value given and what is allowed, so that the command
line can print it as one line.
"""

from __future__ import annotations

import math
from numbers import Real


class BearinglabError(Exception):
    """Base class of all bearinglab errors."""


class InputError(BearinglabError, ValueError):
    """A parameter is outside what the model allows.

    A missing value (None) reads "is not given" rather than "= None".

    >>> str(InputError("ball_count", 2, "an integer >= 3"))
    'ball_count = 2 is not allowed: expected an integer >= 3'
    >>> str(InputError("viscosity", None, "the operating viscosity [m^2/s]"))
    'viscosity is not given: expected the operating viscosity [m^2/s]'
    """

    def __init__(self, parameter: str, value: object, allowed: str, hint: str = "") -> None:
        self.parameter = parameter
        self.value = value
        self.allowed = allowed
        self.hint = hint
        message = (
            f"{parameter} is not given: expected {allowed}"
            if value is None
            else f"{parameter} = {value!r} is not allowed: expected {allowed}"
        )
        if hint:
            message += f" ({hint})"
        super().__init__(message)


class DesignationError(BearinglabError, ValueError):
    """A bearing designation could not be read.

    The message names the designation and the part that was not understood.
    """

    def __init__(self, designation: str, part: str, reason: str) -> None:
        self.designation = designation
        self.part = part
        self.reason = reason
        super().__init__(f"designation {designation!r}: cannot read {part!r}: {reason}")


class CatalogError(BearinglabError, LookupError):
    """A bearing (or one of its values) is not in the catalogue."""


class ConvergenceError(BearinglabError, RuntimeError):
    """An iterative solver did not converge; the message names the case and residual."""


def positive_number(name: str, value, allowed: str, *, zero: bool = False) -> float:
    """``value`` as a float if it is a finite real number > 0 (>= 0 with ``zero``), not a
    bool; otherwise an :class:`InputError` naming ``name``, the value and ``allowed``.

    >>> positive_number("duration", 2, "a duration > 0 [s]")
    2.0
    >>> positive_number("load", -1.0, "a load >= 0 [N]", zero=True)
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: load = -1.0 is not allowed: expected a load >= 0 [N]
    """
    if (
        isinstance(value, bool)
        or not isinstance(value, Real)
        or not math.isfinite(value)
        or not (value >= 0 if zero else value > 0)
    ):
        raise InputError(name, value, allowed)
    return float(value)
