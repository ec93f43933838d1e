"""What this machine offers to work run in parallel, and how much one run may ask of it."""

from __future__ import annotations

import operator
import os

from ..errors import InputError

#: Worker processes per core beyond which more only queue for the cores and take memory
#: (each process holds its own NumPy, SciPy and numba: 100-300 MB).
PROCESSES_PER_CORE = 4


def most_processes() -> int:
    """The most worker processes a command starts on this machine [-]."""
    return PROCESSES_PER_CORE * (os.cpu_count() or 1)


def check_workers(name: str, value) -> int:
    """``value`` as a number of worker processes, or an InputError naming ``name``.

    Parameters
    ----------
    name : str
        The input that holds it (``workers``, ``jobs``).
    value : int
        Worker processes asked for, in [1, :func:`most_processes`] [-].
    """
    most = most_processes()
    if isinstance(value, bool) or not hasattr(value, "__index__") or not 1 <= value <= most:
        raise InputError(name, value, f"a number of worker processes in [1, {most}] (4 per core)")
    return operator.index(value)


def check_count(name: str, count: int, most: int, confirm: int | None, verb: str) -> None:
    """Refuse more than ``most`` units of work at all, and more than ``confirm`` without
    confirmation.

    Parameters
    ----------
    name : str
        What is counted, the input that holds the count (``cases``, ``records``).
    count : int
        How many are asked for [-].
    most : int
        The hard ceiling [-].
    confirm : int, optional
        More than this needs confirmation (``max_<name>`` raised, or `yes`) [-].
    verb : str
        What is done to them ("run", "make"), for the message.
    """
    if count > most:
        raise InputError(name, count, f"at most {most:g} {name} in one run")
    if confirm is not None and count > confirm:
        raise InputError(
            name,
            count,
            f"at most {confirm} {name} without confirmation",
            f"confirm with `yes` (or raise max_{name}) to {verb} them all",
        )


def peak_rss() -> int:
    """Peak resident memory of this process [bytes]."""
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # Linux: kB


def cpu_time() -> float:
    """CPU time this process has used, user and system [s]."""
    import resource

    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime
