"""A request read against the input table (:data:`~.table.INPUTS`): its values checked
(:func:`check`, :func:`closed`: every value in its range, no unknown key, the required
ones given), a value in SI by the unit its name carries (:func:`si`), and a model's error
put back in the request's terms (:func:`input_for`, :func:`restate`: the input that sets
the parameter, its value and numbers in that input's unit).
"""

from __future__ import annotations

from ..errors import InputError
from .table import INPUTS


def si(values: dict, name: str, default=None):
    """The value of input ``name`` in the request ``values`` in SI, by the unit its name
    carries (:func:`bearinglab.units.unit_of`); ``default`` (already SI) when not given.

    Parameters
    ----------
    values : dict
        The request: input name -> value in the unit its name carries (None: not given).
    name : str
        The input's public name (``ball_diameter_mm``, ``speed_rpm``, ...).
    default : object
        Returned as it is when the input is not given (already in SI).

    Examples
    --------
    >>> si({"ball_diameter_mm": 7.5}, "ball_diameter_mm"), si({}, "speed_rpm", 0.0)
    (0.0075, 0.0)
    """
    from ..units import unit_of

    value = values.get(name)
    if value is None:
        return default
    unit = unit_of(name)
    return float(value) if unit is None else unit.to_si(float(value))


def input_for(parameter: str, specs: dict) -> str | None:
    """The input of ``specs`` (name -> Input) that ``parameter`` is: the input of that name,
    else the first whose model parameters (:attr:`Input.fields`) include it, else the
    first whose name less its unit suffix is it (``duration`` -> ``duration_s``); None if
    none.

    Parameters
    ----------
    parameter : str
        A model parameter or input name (e.g. ``shaft_speed``, ``ball_count``).
    specs : dict
        Input name -> :class:`Input` to look in (e.g. :data:`INPUTS`).

    Returns
    -------
    str or None
        The input's public name.

    Examples
    --------
    >>> input_for("shaft_speed", INPUTS), input_for("ball_count", INPUTS)
    ('speed_rpm', 'balls')
    >>> input_for("duration", INPUTS)
    'duration_s'
    """
    from ..units import unit_of

    if parameter in specs:
        return parameter
    for name, spec in specs.items():
        if parameter in spec.fields:
            return name
    for name in specs:
        unit = unit_of(name)
        if unit is not None and name[: -len(unit.suffix) - 1] == parameter:
            return name
    return None


def restate(exc: InputError, values: dict, specs: dict) -> InputError:
    """A model's error ``exc`` in the terms of the request ``values`` whose inputs are
    ``specs``: about the input that sets the parameter it names (:func:`input_for`), with
    the value as given (or the model's value in the input's unit), the numbers of its text
    in that unit, and the model parameters it names in backquotes as the inputs that set
    them. An error about no input of the request is returned as it is.

    Parameters
    ----------
    exc : InputError
        The model's error, naming a model parameter in SI.
    values : dict
        The request: input name -> value as given, in the input's unit.
    specs : dict
        Input name -> :class:`Input` of the request's inputs.

    Examples
    --------
    >>> e = InputError("ball_diameter", 0.05, "less than {d}", unit="m", numbers={"d": 0.04})
    >>> str(restate(e, {"ball_diameter_mm": 50.0}, INPUTS))
    'ball_diameter_mm = 50.0 is not allowed: expected less than 40 mm'
    """
    from ..units import unit_of

    name = input_for(exc.parameter, specs)
    rename = lambda p: f"`{input_for(p, specs) or p}`"  # noqa: E731
    if name is None:
        return exc.restated(exc.parameter, exc.value, names=rename)
    unit = unit_of(name)
    value = values.get(name)
    si = unit is not None and exc.unit not in ("", unit.symbol)
    if isinstance(value, str) and isinstance(exc.value, str) and exc.value in value:
        value = exc.value  # the part of the value at fault (one item of a list)
    if value is None:
        value = exc.value
        if si and isinstance(value, (int, float)) and not isinstance(value, bool):
            value = unit.from_si(value)
    if si:
        return exc.restated(name, value, unit.factor, unit.symbol, names=rename)
    return exc.restated(name, value, names=rename)


def closed(values: dict, specs: dict, what: str = "") -> dict:
    """Check a request against its inputs: a key that is not an input is refused naming
    the closest one (a misspelt key must not be ignored silently), an input whose default
    is ``...`` must be given, and every value must lie in its range.

    Parameters
    ----------
    values : dict
        The request: input name -> value in its unit (None: not given).
    specs : dict
        Its inputs: name -> :class:`Input`.
    what : str
        What the request is for (an analysis' name), for the error.

    Returns
    -------
    dict
        ``values``.

    Examples
    --------
    >>> try:
    ...     closed({"reliabilty_percent": 99}, {"reliability_percent": INPUTS["seed"]}, "life")
    ... except InputError as exc:
    ...     print(exc.hint)
    did you mean `reliability_percent`?
    """
    import difflib

    for key in values:
        if key not in specs:
            close = difflib.get_close_matches(str(key), list(specs), n=1, cutoff=0.6)
            hint = (
                f"did you mean `{close[0]}`?"
                if close
                else "its inputs: " + ", ".join(f"`{n}`" for n in specs)
            )
            raise InputError(str(key), values[key], f"an input of {what or 'the request'}", hint)
    for name, spec in specs.items():
        if spec.default is ... and values.get(name) is None:
            raise InputError(name, None, spec.allowed(_symbol(name)))
    return check(values, specs)


def _symbol(name: str) -> str:
    from ..units import unit_of

    unit = unit_of(name)
    return unit.symbol if unit is not None else ""


def check(values: dict, specs: dict | None = None) -> dict:
    """Check each value of ``values`` (name -> value in its unit; None: not given) against
    its input's range: the inputs ``specs`` (name -> Input), by default the table's
    entries of the names given; returns ``values``.

    Parameters
    ----------
    values : dict
        Input name -> value in its unit (None: not given).
    specs : dict or None
        Input name -> :class:`Input` to check against; None: the table's entries of the
        names in ``values`` (names that are not in the table are not checked).
    """
    if specs is None:
        specs = {name: INPUTS[name] for name in values if name in INPUTS}
    for name, spec in specs.items():
        spec.check(name, values.get(name))
    return values
