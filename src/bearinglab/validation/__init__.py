"""Published cases bearinglab reproduces: one list, used by ``tests/literature`` and by
the ``validate`` command.

Each source has its own module with a ``CASES`` list of :class:`Case`; a case names its
source, the published value as printed, the tolerance and why that tolerance is fair.
A published number the project cannot reproduce stays in the list with
``known_failure`` saying why (the test then expects the failure, strictly).
"""

from __future__ import annotations

from .case import Case, CaseResult

__all__ = ["Case", "CaseResult", "all_cases"]


def all_cases() -> list[Case]:
    """Every published case, in source order."""
    from . import (
        datasets,
        dynamics,
        friction,
        harris218,
        nasa_slip,
        ratings,
        rollers,
        seed000,
        seed001,
        seed003,
        seed003_noise,
        seed004,
    )

    return [
        *seed000.CASES,
        *seed001.CASES,
        *seed003.CASES,
        *seed004.CASES,
        *dynamics.CASES,
        *seed003_noise.CASES,
        *datasets.CASES,
        *friction.CASES,
        *ratings.CASES,
        *harris218.CASES,
        *nasa_slip.CASES,
        *rollers.CASES,
    ]
