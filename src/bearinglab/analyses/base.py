"""What an analysis is: the one statement of what it takes and gives.

An :class:`Analysis` names its inputs (entries of :data:`bearinglab.inputs.INPUTS`, with
its own defaults), the function that runs one request of them (``run(values) ->``
result with ``to_dict()``) and the columns a study keeps of the result. The command line
generates a command's options from it and prints the result; a study evaluates it per
case; the report calls ``run``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ..inputs import BEARING, INPUTS, Input, check


def inputs(*names: str, **own: Input) -> dict[str, Input]:
    """name -> Input: the table's entries ``names`` and an analysis' ``own`` readings."""
    return {**{name: INPUTS[name] for name in names}, **own}


#: The bearing's inputs (a designation and/or its geometry).
BEARING_INPUTS = inputs(*BEARING)


@dataclass(frozen=True)
class Analysis:
    """One analysis: ``options`` (name -> Input, what a request holds), ``outputs``
    (study column -> "f" float, "i" integer, "s" text), ``run(values) -> result``,
    ``columns(result) -> dict`` (the study's columns of a result; default its
    ``to_dict()``), and for studies: ``largest`` cases per partition, an optional
    ``batch(cases, seed) -> list`` of (outputs or exception) for a whole partition, the
    modules a worker imports first (``warm``), ``probe``: inputs that make the warm-up
    case short, and ``extra``: the inputs only a study takes."""

    name: str
    help: str
    options: dict
    outputs: dict
    run: Callable
    largest: int
    columns: Callable | None = None
    batch: Callable | None = None
    warm: tuple = field(default_factory=tuple)
    probe: dict = field(default_factory=dict)
    #: inputs a study may give that the command does not take (sweepable numbers that a
    #: command gives as one specification, e.g. a fault's width)
    extra: tuple = ()

    @property
    def command_options(self) -> dict:
        """The inputs of the analysis' command: every option less the study's extras."""
        return {k: v for k, v in self.options.items() if k not in self.extra}

    def evaluate(self, case: dict, seed: int) -> dict:
        """A study ``case``'s output columns; ``seed`` (the case's) draws its random inputs
        unless the case gives a ``seed``."""
        values = {**case}
        if "seed" in self.options and values.get("seed") is None:
            values["seed"] = seed
        check(values, self.options)  # the ranges the command checks, too
        result = self.run(values)
        d = self.columns(result) if self.columns is not None else result.to_dict()
        return pick(d, self.outputs)


@dataclass(frozen=True)
class Outcome:
    """A library result in a request's terms: the result, the request's designation and
    every warning (the bearing's, the result's, the inputs without effect)."""

    result: object
    designation: str | None = None
    warnings: tuple = field(default_factory=tuple)
    bearing: object = None

    def to_dict(self) -> dict:
        d = self.result.to_dict()
        return {"designation": self.designation, **d, "warnings": list(self.warnings)}

    def to_pandas(self):
        return self.result.to_pandas()

    def plot(self, *args, **kwargs):
        return self.result.plot(*args, **kwargs)


def pick(d: dict, outputs: dict) -> dict:
    """The ``outputs`` columns of a result's dict ``d`` (lists joined for text columns)."""
    out = {}
    for k, kind in outputs.items():
        v = d.get(k)
        if isinstance(v, (list, tuple)):
            v = "; ".join(map(str, v)) if kind == "s" else None
        out[k] = v
    return out


#: model parameter -> the input that holds it, where the two are not the same quantity name
_PARAMETERS = {"shaft_speed": "speed_rpm", "noise": "noise_ms2"}


def in_request_terms(exc, values: dict, names: dict | None = None):
    """A library error ``exc`` about a model parameter as the input of the request
    ``values`` that holds it: the input named in
    ``names`` (parameter -> input), else the input whose name less its unit suffix is the
    parameter (``duration`` -> ``duration_s``), with the value as given (or the error's SI
    value in the input's unit) and lengths in the message in the input's unit. Errors
    of other parameters are returned as they are."""
    from ..errors import InputError
    from ..inputs.bearing import _in_units
    from ..units import unit_of

    parameter = (names or {}).get(exc.parameter) or _PARAMETERS.get(exc.parameter, exc.parameter)
    for name in values:
        unit = unit_of(name)
        base = name[: -len(unit.suffix) - 1] if unit is not None else name
        if parameter not in (name, base):
            continue
        value = values.get(name)
        if value is None and isinstance(exc.value, (int, float)) and unit is not None:
            value = unit.from_si(exc.value)
        allowed, hint = exc.allowed, exc.hint
        if name.endswith("_mm"):
            allowed, hint = _in_units(allowed, name), _in_units(hint, name)
        words = {**(names or {}), exc.parameter: name}
        return InputError(name, value, _as_inputs(allowed, words), _as_inputs(hint, words))
    return exc


def _as_inputs(text: str, names: dict) -> str:
    """``text`` with the model parameters it names (``names``: parameter -> input) as the
    request's inputs, in backquotes: "give P (equivalent_load)" -> "give P
    (`equivalent_load_n`)", "use model='constant'" -> "use `model` constant"."""
    import re

    for parameter, name in names.items():
        text = re.sub(rf"(?<![`\w]){parameter}='([^']*)'", rf"`{name}` \1", text)
        if "_" in parameter:  # a plain word ("model", "seals") is prose as often as a name
            text = re.sub(rf"(?<![`\w=]){parameter}(?![\w`=])", f"`{name}`", text)
    return text


def specs(value) -> list[str]:
    """A repeatable input's values: a list as given, or one text with ``;`` between
    them (a study column)."""
    if value is None:
        return []
    if isinstance(value, str):
        return [part.strip() for part in value.split(";") if part.strip()]
    return list(value)
