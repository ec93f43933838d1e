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

from ..inputs import BEARING, INPUTS, Input, closed


def inputs(*names: str, **own: Input) -> dict[str, Input]:
    """name -> Input: the table's entries ``names`` and an analysis' ``own`` readings."""
    return {**{name: INPUTS[name] for name in names}, **own}


#: The bearing's inputs (a designation and/or its geometry).
BEARING_INPUTS = inputs(*BEARING)
#: The loads of a quasi-static request.
LOADS = inputs("radial_load_n", "axial_load_n")
#: The inner-ring speed, at rest unless given.
SPEED_AT_REST = {
    "speed_rpm": INPUTS["speed_rpm"].with_(default=0.0, help="Inner-ring speed [rpm].")
}


@dataclass(frozen=True)
class Analysis:
    """One entry of the registry: a command's request and what it gives.

    ``options`` (name -> Input, what a request holds; an input whose default is ``...``
    must be given), ``run(values) -> result`` (with ``to_dict()``) and, for an analysis a
    study sweeps, ``outputs`` (study column -> "f" float, "i" integer, "s" text),
    ``columns(result) -> dict`` (the study's columns of a result; default its
    ``to_dict()``), ``largest`` cases per partition, an optional ``batch(cases, seed) ->
    list`` of (outputs or exception) for a whole partition, the modules a worker imports
    first (``warm``), ``probe``: inputs that make the warm-up case short, and ``extra``:
    the inputs only a study takes. Calling the entry with a request runs it closed:
    :meth:`__call__`."""

    name: str
    help: str
    options: dict
    run: Callable
    outputs: dict = field(default_factory=dict)
    largest: int = 0
    columns: Callable | None = None
    batch: Callable | None = None
    warm: tuple = field(default_factory=tuple)
    probe: dict = field(default_factory=dict)
    #: inputs a study may give that the command does not take (sweepable numbers that a
    #: command gives as one specification, e.g. a fault's width)
    extra: tuple = ()
    #: the files the command writes besides printing the result: name -> Input (a path)
    files: dict = field(default_factory=dict)

    @property
    def command_options(self) -> dict:
        """The inputs of the analysis' command: every option less the study's extras."""
        return {k: v for k, v in self.options.items() if k not in self.extra}

    @property
    def sweepable(self) -> bool:
        """Whether a study can sweep it (it names the columns it gives)."""
        return bool(self.outputs)

    def __call__(self, values: dict, **keywords):
        """Run one request ``values`` (name -> value in its unit; None: not given), closed:
        a key that is not one of the options is refused, naming the closest option; an
        option that must be given and is not, and a value out of its range, are refused;
        ``keywords`` go to ``run`` (a progress callback)."""
        from ..errors import InputError
        from ..inputs import restate

        closed(values, self.options, self.name)
        try:
            return self.run(values, **keywords)
        except InputError as exc:  # a model's parameter, as the input that sets it
            raise restate(exc, values, self.options) from None

    def evaluate(self, case: dict, seed: int) -> dict:
        """A study ``case``'s output columns; ``seed`` (the case's) draws its random inputs
        unless the case gives a ``seed``.

        Parameters
        ----------
        case : dict
            One study case: input name -> value in its unit (a ``case`` key, the case's number,
            is left out).
        seed : int
            The case's seed (>= 0), given to the analysis as its ``seed`` when it takes one and
            the case does not set it.

        Returns
        -------
        dict
            Output column -> value (see :func:`pick`).
        """
        values = {k: v for k, v in case.items() if k != "case"}
        if "seed" in self.options and values.get("seed") is None:
            values["seed"] = seed
        result = self(values)  # the ranges the command checks, too
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


#: The files a command may write besides printing its result, declared once; a command's
#: reading of one says what it holds.
FILES = {
    "plot": Input("path", None, "Also draw the result to this .png, .svg or .pdf file."),
    "html": Input("path", None, "Also write the result as one self-contained HTML page."),
    "output": Input("path", None, "Write the result to this file.", aliases=("o",)),
}


def plot_file(what: str = "the result") -> dict:
    """The ``plot`` file of a command that draws ``what``."""
    return {"plot": FILES["plot"].with_(help=f"Also draw {what} to this .png, .svg or .pdf file.")}


#: The ``html`` page a command writes.
HTML_FILE = {"html": FILES["html"]}


def pick(d: dict, outputs: dict) -> dict:
    """The ``outputs`` columns of a result's dict ``d`` (lists joined for text columns).

    Parameters
    ----------
    d : dict
        A result's ``to_dict()`` (or the analysis' own columns).
    outputs : dict
        Study column -> kind: "f" float, "i" integer, "s" text. A list value becomes its
        items joined by "; " in a text column and None in any other.

    Returns
    -------
    dict
        Column -> value, None for a key that ``d`` lacks.
    """
    out = {}
    for k, kind in outputs.items():
        v = d.get(k)
        if isinstance(v, (list, tuple)):
            v = "; ".join(map(str, v)) if kind == "s" else None
        out[k] = v
    return out


def specs(value) -> list[str]:
    """A repeatable input's values: a list as given, or one text with ``;`` between
    them (a study column)."""
    if value is None:
        return []
    if isinstance(value, str):
        return [part.strip() for part in value.split(";") if part.strip()]
    return list(value)
