"""Published cases bearinglab reproduces: one list, used by ``tests/literature`` and by
the ``validate`` command.

Each source has its own module with a ``CASES`` list of :class:`Case`; a case names its
source, the published value as printed, the tolerance and why that tolerance is fair.
A published number the project cannot reproduce stays in the list with
``known_failure`` saying why (the test then expects the failure, strictly).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class Case:
    """One published number and how bearinglab computes it."""

    source: str
    quantity: str
    published: float
    unit: str
    compute: Callable[[], float]
    rel_tol: float
    tolerance_reason: str
    known_failure: str | None = None

    @property
    def id(self) -> str:
        return f"{self.source} | {self.quantity}"

    def run(self) -> CaseResult:
        computed = float(self.compute())
        error = (computed - self.published) / self.published * 100.0
        passed = math.isfinite(computed) and abs(error) <= self.rel_tol * 100.0
        return CaseResult(self, computed, error, passed)


@dataclass(frozen=True)
class CaseResult:
    """A case with its computed value, error [%] and verdict."""

    case: Case
    computed: float
    error_percent: float
    passed: bool

    def to_dict(self) -> dict:
        c = self.case
        return {"source": c.source, "quantity": c.quantity, "published": c.published,
                "computed": self.computed, "unit": c.unit,
                "error_percent": self.error_percent, "passed": self.passed,
                "tolerance_percent": c.rel_tol * 100.0, "known_failure": c.known_failure}


def all_cases() -> list[Case]:
    """Every published case, in source order."""
    from . import (
        datasets,
        dynamics,
        friction,
        harris218,
        nasa_slip,
        ratings,
        seed000,
        seed001,
        seed003,
        seed003_noise,
        seed004,
    )

    return [*seed000.CASES, *seed001.CASES, *seed003.CASES, *seed004.CASES, *dynamics.CASES,
            *seed003_noise.CASES, *datasets.CASES, *friction.CASES, *ratings.CASES,
            *harris218.CASES, *nasa_slip.CASES]
