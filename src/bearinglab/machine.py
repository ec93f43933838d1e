"""What this machine offers to work run in parallel (benchmark records, study workers)."""

from __future__ import annotations

import os

#: Worker processes per core beyond which more only queue for the cores and take memory
#: (each process holds its own NumPy, SciPy and numba: 100-300 MB).
PROCESSES_PER_CORE = 4


def most_processes() -> int:
    """The most worker processes a command starts on this machine [-]."""
    return PROCESSES_PER_CORE * (os.cpu_count() or 1)
