"""The analyses a study can sweep: the registry of :mod:`bearinglab.analyses` (each
analysis' inputs - its command's, in engineering units - and its output columns), and
running a partition's cases through it (:func:`run_cases`): one ``evaluate`` per case,
or one ``batch`` for the whole partition (``stiffness``: stiffness_map lines).
"""

from __future__ import annotations

import math

import numpy as np

from ..analyses import ALIASES, ANALYSES, Analysis, analysis
from ..engine import reraise_interrupt
from ..errors import InputError

__all__ = ["ALIASES", "ANALYSES", "Analysis", "analysis", "error_text", "run_cases", "warm_up"]


def error_text(exc: BaseException) -> str:
    """One line saying why a case failed (the InputError message names the input)."""
    text = " ".join(str(exc).split())
    if isinstance(exc, (InputError,)) or type(exc).__module__.startswith("bearinglab"):
        return text or type(exc).__name__
    return f"{type(exc).__name__}: {text}"


def warm_up(args) -> None:
    """Run a few cases (outputs discarded): loads the analysis' compiled kernels."""
    name, cases = args
    a = analysis(name)
    run_cases(a, [{**case, **a.probe} for case in cases], 0)


def run_cases(a: Analysis, cases: list[dict], seed: int) -> list[dict]:
    """Outputs (and ``error``) of every case; a failing case gets its error text and the
    others go on. Options a case does not give take their defaults."""
    from .cases import case_seed

    full = [
        {
            **{k: o.default for k, o in a.options.items() if o.default is not None},
            **{k: v for k, v in c.items() if v is not None},
        }
        for c in cases
    ]
    seeds = [case_seed(seed, c["case"]) for c in cases]
    if a.batch is not None:
        results = a.batch(full, seed)
    else:
        results = []
        for c, s in zip(full, seeds, strict=True):
            try:
                results.append(a.evaluate(c, s))
            except Exception as exc:  # noqa: BLE001 - a failed case never stops a study
                reraise_interrupt(exc)  # a Ctrl-C is no failed case
                results.append(exc)
    rows = []
    for r in results:
        if isinstance(r, BaseException):
            reraise_interrupt(r)
            rows.append({**dict.fromkeys(a.outputs), "error": error_text(r)})
        else:
            rows.append({**{k: _clean(r.get(k)) for k in a.outputs}, "error": None})
    return rows


def _clean(v):
    if isinstance(v, (np.floating, np.integer, np.bool_)):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v
