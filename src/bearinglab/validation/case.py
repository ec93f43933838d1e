"""One published case: the number as printed, how bearinglab computes it, the tolerance
and why it is fair; and its result. The case modules import these from here (not from the
package, which imports them back)."""

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
        return {
            "source": c.source,
            "quantity": c.quantity,
            "published": c.published,
            "computed": self.computed,
            "unit": c.unit,
            "error_percent": self.error_percent,
            "passed": self.passed,
            "tolerance_percent": c.rel_tol * 100.0,
            "known_failure": c.known_failure,
        }
