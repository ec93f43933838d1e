"""The registry of every command: each command's request, declared once beside its
analysis (the inputs it takes, what ``run`` gives), and nothing else.

The command line generates each command's options from its entry and prints what the
entry's run gives; a study sweeps the entries that name their outputs; the report calls
them. ``tests/unit/test_request.py`` holds that every command has an entry here and that
its options are the entry's.
"""

from __future__ import annotations

from functools import cache


@cache
def registry() -> dict:
    """command name -> :class:`~bearinglab.analyses.base.Analysis` (imported on first
    use: the command line's start-up imports none of them)."""
    from .analyses import ANALYSES
    from .analyses.diagnosis import ANALYZE, BENCHMARK
    from .analyses.foundation import CONTACT, INFO
    from .analyses.stiffness import STIFFNESS_MAP
    from .dataset.request import DATASET
    from .report.request import REPORT
    from .study.request import STUDY
    from .trend.request import TREND
    from .validation.run import _entry

    entries = [
        INFO,
        ANALYSES["frequencies"],
        CONTACT,
        ANALYSES["static"],
        STIFFNESS_MAP,
        ANALYSES["ring-modes"],
        ANALYSES["simulate"],
        ANALYZE,
        BENCHMARK,
        TREND,
        ANALYSES["noise"],
        ANALYSES["friction"],
        ANALYSES["life"],
        _entry(),
        REPORT,
        STUDY,
        DATASET,
    ]
    return {entry.name: entry for entry in entries}


def entry(command: str):
    """The registry's entry of ``command`` (KeyError when there is none)."""
    return registry()[command]
