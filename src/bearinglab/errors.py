"""Exceptions raised by bearinglab.

Every error a user can provoke with bad input is an :class:`InputError` that
names the parameter, the value given and what is allowed, so that the command
line can print it as one line.
"""

from __future__ import annotations

import math
from numbers import Real


class BearinglabError(Exception):
    """Base class of all bearinglab errors.

    They pickle with their fields (a worker process raises them, the client shows them):
    an exception whose constructor takes other arguments than its message does not
    otherwise survive the trip.

    >>> import pickle
    >>> e = pickle.loads(pickle.dumps(InputError("ball_count", 2, "an integer >= 3")))
    >>> e.parameter, str(e)
    ('ball_count', 'ball_count = 2 is not allowed: expected an integer >= 3')
    """

    def __reduce__(self):
        return _restore, (type(self), self.args, self.__dict__)


def _restore(cls, args, state):
    """An error of class ``cls`` with its ``args`` and attributes ``state`` (unpickling)."""
    error = cls.__new__(cls)
    error.args = args
    error.__dict__.update(state)
    return error


class InputError(BearinglabError, ValueError):
    """A parameter is outside what the model allows: an error as data.

    It carries the ``parameter`` (a model parameter, or the public name of an input once
    the request has restated it), the ``value`` given, what is ``allowed`` and a ``hint``.
    Numbers inside ``allowed`` and ``hint`` may be fields, ``{name}``, whose values
    (``numbers``) are in ``unit``, so that the request can restate the error in the unit of
    the input the user gave (:meth:`restated`) without rewording its text. Names of other
    inputs are written in backquotes (`` `balls` ``): a front end renders them as it names
    inputs (the command line as flags). A missing value (None) reads "is not given"
    rather than "= None".

    >>> str(InputError("ball_count", 2, "an integer >= 3"))
    'ball_count = 2 is not allowed: expected an integer >= 3'
    >>> str(InputError("viscosity", None, "the operating viscosity [m^2/s]"))
    'viscosity is not given: expected the operating viscosity [m^2/s]'
    >>> e = InputError("pitch_diameter", 0.005, "more than {d}", unit="m", numbers={"d": 0.00794})
    >>> e.allowed, e.restated("pitch_diameter_mm", 5.0, 1e-3, "mm").allowed
    ('more than 0.00794 m', 'more than 7.94 mm')
    """

    def __init__(
        self,
        parameter: str,
        value: object,
        allowed: str,
        hint: str = "",
        *,
        unit: str = "",
        numbers: dict | None = None,
    ) -> None:
        self.parameter = parameter
        self.value = value
        self.template = (allowed, hint)
        self.unit = unit
        self.numbers = dict(numbers or {})
        super().__init__(self.message)

    @staticmethod
    def _filled(text: str, numbers: dict, scale: float, unit: str) -> str:
        for key, number in numbers.items():
            shown = f"{number / scale:.6g}" + (f" {unit}" if unit else "")
            text = text.replace("{" + key + "}", shown)
        return text

    @property
    def allowed(self) -> str:
        """What is allowed, its numbers filled in."""
        return self._filled(self.template[0], self.numbers, 1.0, self.unit)

    @property
    def hint(self) -> str:
        """The hint, its numbers filled in ('' for none)."""
        return self._filled(self.template[1], self.numbers, 1.0, self.unit)

    @property
    def message(self) -> str:
        """The error in one line, naming the parameter as it is called here."""
        return self.worded(self.parameter)

    def worded(self, name: str, names=None) -> str:
        """The message with the parameter called ``name`` and each backquoted name of the
        texts replaced by ``names(name)`` (default: kept in backquotes).

        Parameters
        ----------
        name : str
            How to call the parameter (e.g. an input's public name or a flag).
        names : callable or None
            ``names(name) -> str`` rewrites each backquoted name of the allowed range and hint;
            None keeps them in backquotes.

        Returns
        -------
        str
            The message in one line.
        """
        allowed, hint = (markup(t, names) for t in (self.allowed, self.hint))
        text = (
            f"{name} is not given: expected {allowed}"
            if self.value is None
            else f"{name} = {self.value!r} is not allowed: expected {allowed}"
        )
        return text + (f" ({hint})" if hint else "")

    def restated(
        self,
        parameter: str,
        value: object,
        scale: float = 1.0,
        unit: str | None = None,
        names=None,
    ) -> InputError:
        """This error about ``parameter`` with ``value``, its numbers in ``unit`` (one of
        which is ``scale`` in this error's unit; by default this error's), its backquoted
        names renamed by ``names(name)``.

        Parameters
        ----------
        parameter : str
            The name the new error gives (e.g. the public input name ``pitch_diameter_mm``).
        value : object
            The value the new error shows, as given (it is not converted).
        scale : float
            The size of one ``unit`` in this error's unit (e.g. 1e-3 for mm when this error's
            numbers are in m): each of its numbers is divided by it. Default 1.
        unit : str or None
            The unit symbol of the new error's numbers; None: this error's unit.
        names : callable or None
            ``names(name) -> str`` rewrites each backquoted name of the texts (e.g. as a
            command-line flag); None keeps them in backquotes.

        Returns
        -------
        InputError
            A new error; this one is left as it is.
        """
        allowed, hint = (markup(t, names) for t in self.template)
        numbers = {k: v / scale for k, v in self.numbers.items()}
        unit = self.unit if unit is None else unit
        return InputError(parameter, value, allowed, hint, unit=unit, numbers=numbers)

    def to_dict(self) -> dict:
        """The error as JSON-ready fields: input, value (as given; text when it is not a
        number, a text or null), allowed, hint, unit and the message."""
        value = self.value
        if not (value is None or isinstance(value, (bool, int, float, str))):
            value = str(value)
        elif isinstance(value, float) and not math.isfinite(value):
            value = repr(value)
        return {
            "input": self.parameter,
            "value": value,
            "allowed": self.allowed,
            "hint": self.hint or None,
            "unit": self.unit or None,
            "message": self.message,
        }


def markup(text: str, names=None) -> str:
    """``text`` with each name written in backquotes replaced by ``names(name)`` (kept as
    it is without ``names``): the one way messages name inputs.

    >>> markup("give `balls` and `ball_diameter_mm`", lambda n: "--" + n.replace("_", "-"))
    'give --balls and --ball-diameter-mm'
    """
    if names is None or "`" not in text:
        return text
    parts = text.split("`")
    if len(parts) % 2 == 0:  # an unpaired backquote: not markup
        return text
    return "".join(
        names(part) if i % 2 and part.isidentifier() else (f"`{part}`" if i % 2 else part)
        for i, part in enumerate(parts)
    )


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


def bore_below_outside(bore: float, outside_diameter: float, blame: str = "outside_diameter"):
    """Check d < D, else an :class:`InputError` on ``blame`` (``"outside_diameter"`` or
    ``"bore"``: the value the user gave rather than the catalogue's).

    Parameters
    ----------
    bore : float
        d [m].
    outside_diameter : float
        D [m].
    blame : str
        The input the error names when d >= D [-].

    Examples
    --------
    >>> bore_below_outside(0.025, 0.052)
    >>> bore_below_outside(0.06, 0.052, "bore")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: bore = 0.06 is not allowed: expected less than the ...
    """
    if blame not in ("outside_diameter", "bore"):
        raise ValueError(f"blame must be 'outside_diameter' or 'bore', not {blame!r}")
    if bore < outside_diameter:
        return
    if blame == "bore":
        allowed, numbers = "less than the outside diameter {D}", {"D": outside_diameter}
        raise InputError("bore", bore, allowed, unit="m", numbers=numbers)
    allowed, numbers = "more than the bore {d}", {"d": bore}
    raise InputError("outside_diameter", outside_diameter, allowed, unit="m", numbers=numbers)


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
