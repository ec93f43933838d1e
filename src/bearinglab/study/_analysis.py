"""What a sweepable analysis is (:class:`Analysis`) and what every analysis shares: the
bearing options, the load and speed options, and picking the output columns from a
result's ``to_dict()``. The analyses themselves are in mechanics.py, operation.py and
vibration.py; the registry in analyses.py.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ._inputs import BEARING_OPTIONS
from .cases import Option

_BEARING = {name: spec[0] for name, spec in BEARING_OPTIONS.items()}
LOADS = {
    "radial_load_n": Option("number", 0.0, "Radial load F_r [N]."),
    "axial_load_n": Option("number", 0.0, "Axial load F_a [N]."),
    "speed_rpm": Option("number", 0.0, "Speed of the rotating (inner) ring [rpm]."),
}


@dataclass(frozen=True)
class Analysis:
    """One sweepable analysis: ``options`` (name -> Option), ``outputs`` (column -> "f"
    float, "i" integer, "s" text), ``evaluate(case, seed) -> dict`` of outputs,
    ``largest`` cases per partition, optional ``batch(cases, seed) -> list`` of (outputs or
    exception) for a whole partition, the modules a worker imports first and ``probe``:
    options that make the warm-up case (the study's first case, run once per worker to
    load the compiled kernels) short."""

    name: str
    help: str
    options: dict
    outputs: dict
    evaluate: Callable
    largest: int
    batch: Callable | None = None
    warm: tuple = field(default_factory=tuple)
    probe: dict = field(default_factory=dict)


def pick(d: dict, outputs: dict) -> dict:
    """The ``outputs`` columns of a result's ``to_dict()`` (lists joined for text columns)."""
    out = {}
    for k, kind in outputs.items():
        v = d.get(k)
        if isinstance(v, (list, tuple)):
            v = "; ".join(map(str, v)) if kind == "s" else None
        out[k] = v
    return out


def with_bearing(**more) -> dict:
    """The bearing options followed by ``more`` (an analysis' own options)."""
    return {**_BEARING, **more}
