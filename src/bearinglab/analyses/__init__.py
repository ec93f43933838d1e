"""The analysis registry: what each analysis takes (inputs of :mod:`bearinglab.inputs`)
and gives (a result with ``to_dict()``), stated once for every front end.

The command line generates each command's options from its entry and prints the result of
``run``; :mod:`bearinglab.study` evaluates the entries per case; the report calls ``run``.

>>> r = ANALYSES["frequencies"].run({"designation": "6205-2RS", "speed_rpm": 1797.0})
>>> round(r.to_dict()["bpfo_hz"], 1)
107.4
"""

from __future__ import annotations

from ..errors import InputError
from . import foundation, mechanics, operation, rings, stiffness, vibration
from .base import Analysis, inputs, pick

__all__ = ["ALIASES", "ANALYSES", "Analysis", "analysis", "inputs", "pick"]

#: The registry, in the order the command line lists the analyses.
ANALYSES: dict[str, Analysis] = {
    a.name: a
    for a in (
        stiffness.STIFFNESS,
        mechanics.STATIC,
        foundation.FREQUENCIES,
        operation.LIFE,
        operation.FRICTION,
        rings.RING_MODES,
        vibration.NOISE,
        vibration.SIMULATE,
    )
}
ALIASES = {"ring_modes": "ring-modes", "load-distribution": "static"}


def analysis(name: str) -> Analysis:
    """The analysis called ``name`` (InputError naming the choices otherwise).

    Parameters
    ----------
    name : str
        The analysis' name as the command line spells it (e.g. "static", "ring-modes"; the
        aliases "ring_modes" and "load-distribution" are accepted).
    """
    name = ALIASES.get(name, name)
    if name not in ANALYSES:
        raise InputError("analysis", name, "one of " + ", ".join(ANALYSES))
    return ANALYSES[name]
