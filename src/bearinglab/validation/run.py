"""Running the published cases: each case's verdict, the counts, and one result object
that the ``validate`` command and the report print."""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

from ..engine import reraise_interrupt

#: Verdicts that leave ``validate``'s exit code at 0.
GOOD_VERDICTS = ("pass", "known failure")
VERDICTS = ("pass", "known failure", "fail", "unexpected pass", "error")


def verdict(passed: bool | None, known_failure: str | None) -> str:
    """pass, fail, known failure (documented, fails as expected) or unexpected pass; a
    case whose computation raised is "error" (``passed`` None).

    >>> verdict(True, None), verdict(False, "why"), verdict(True, "why")
    ('pass', 'known failure', 'unexpected pass')
    """
    if passed is None:
        return "error"
    if known_failure:
        return "unexpected pass" if passed else "known failure"
    return "pass" if passed else "fail"


def _finite(value):
    return value if isinstance(value, float) and math.isfinite(value) else None


def run_case(case) -> dict:
    """One case as a JSON-ready dict with its ``verdict`` (an exception is an "error")."""
    out = {
        "source": case.source,
        "quantity": case.quantity,
        "published": case.published,
        "computed": None,
        "unit": case.unit,
        "error_percent": None,
        "passed": False,
        "known_failure": case.known_failure,
        "tolerance_percent": case.rel_tol * 100.0,
        "tolerance_reason": case.tolerance_reason,
        "error": None,
    }
    try:
        result = case.run()
    except Exception as exc:  # noqa: BLE001 - a broken case is reported, the others still run
        reraise_interrupt(exc)  # a Ctrl-C is no broken case
        out["error"] = f"{type(exc).__name__}: {exc}"
        out["verdict"] = verdict(None, case.known_failure)
        return out
    out.update(
        computed=_finite(result.computed),
        error_percent=_finite(result.error_percent),
        passed=bool(result.passed),
    )
    out["verdict"] = verdict(result.passed, case.known_failure)
    return out


def summarize(results: list[dict], seconds: float) -> dict:
    """Counts by verdict and ``ok`` (every case passed or failed as documented)."""
    count = {v: sum(r["verdict"] == v for r in results) for v in VERDICTS}
    return {
        "total": len(results),
        "passed": count["pass"],
        "known_failures": count["known failure"],
        "failed": count["fail"],
        "unexpected_passes": count["unexpected pass"],
        "errors": count["error"],
        "ok": all(r["verdict"] in GOOD_VERDICTS for r in results),
        "duration_s": seconds,
    }


@dataclass(frozen=True)
class Validation:
    """The verdict of every published case (``results``: JSON-ready dicts) and the counts
    (``summary``); ``ok`` when every case passed or failed as documented."""

    results: tuple
    summary: dict

    @property
    def ok(self) -> bool:
        return bool(self.summary["ok"])

    def to_dict(self) -> dict:
        return {"cases": list(self.results), "summary": dict(self.summary)}

    def to_pandas(self):
        """One row per case."""
        import pandas as pd

        return pd.DataFrame(list(self.results))

    def plot(self, ax=None):
        """Each case's error against its tolerance [%], coloured by verdict; (fig, ax)."""
        from ..plotting import _pyplot

        if ax is None:
            fig, ax = _pyplot().subplots(figsize=(8, max(3.0, 0.18 * len(self.results))))
        else:
            fig = ax.figure
        colors = {
            "pass": "tab:green",
            "known failure": "tab:orange",
            "fail": "tab:red",
            "unexpected pass": "tab:red",
            "error": "tab:red",
        }
        for i, r in enumerate(self.results):
            error = abs(r["error_percent"]) if r["error_percent"] is not None else 0.0
            ax.barh(i, max(error, 1e-6), color=colors[r["verdict"]])
            ax.plot(r["tolerance_percent"], i, "k|", ms=8)
        ax.set_xscale("log")
        ax.set_yticks(
            range(len(self.results)),
            [f"{r['source'][:24]}: {r['quantity'][:40]}" for r in self.results],
            fontsize=6,
        )
        ax.set_xlabel("|error| [%] (bar) and tolerance [%] (tick)")
        ax.invert_yaxis()
        fig.tight_layout()
        return fig, ax


def run_validation(
    cases=None,
    progress: Callable[[int, int, str], None] | None = None,
) -> Validation:
    """Run ``cases`` (default: every published case, :func:`bearinglab.validation.all_cases`).

    ``progress(done, total, label)`` is called before each case.

    Parameters
    ----------
    cases : sequence of Case or None
        The cases to run (:class:`~bearinglab.validation.case.Case`); None: every published
        case.
    progress : callable or None
        ``progress(done, total, label)``, called before each case with the number of cases
        done, their total and the case's "source: quantity"; None: no report.

    Returns
    -------
    Validation
        Each case's verdict and the counts.
    """
    if cases is None:
        from .. import validation

        cases = validation.all_cases()
    start = time.perf_counter()
    results = []
    for i, case in enumerate(cases):
        if progress is not None:
            progress(i, len(cases), f"{case.source}: {case.quantity}")
        results.append(run_case(case))
    return Validation(tuple(results), summarize(results, time.perf_counter() - start))


def _validate(values: dict, progress: Callable[[int, int, str], None] | None = None):
    return run_validation(progress=progress)


def _entry():
    from ..analyses.base import HTML_FILE, Analysis

    return Analysis(
        "validate",
        "Every published case bearinglab reproduces, with its verdict (run_validation).",
        {},
        run=_validate,
        files=HTML_FILE,
    )
