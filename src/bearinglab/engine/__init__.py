"""The parallel engine: where work runs, how its progress is told, what a Ctrl-C does.

Every front end that fans out work runs on it: parameter studies (:mod:`bearinglab.study`),
synthetic data sets (:mod:`bearinglab.dataset`), the diagnosis benchmark
(:func:`bearinglab.diagnosis.run_benchmark`) and the trend
(:func:`bearinglab.trend.trend_records`). It is on the ground floor: it imports nothing of
bearinglab but :mod:`bearinglab.errors` (and dask only when a cluster is asked for).

- :mod:`.scheduler`: the scheduler's address, probed before any work;
- :mod:`.runner`: :func:`open_runner` (this process, a LocalCluster, a running cluster),
  :func:`open_jobs` (a number of processes: this one, or a pool of forked ones),
  :func:`run_partitions` (``on_done`` as each partition finishes, ``progress(done, total)``
  in the caller's units), :func:`measured_run` (warm-up, CPU time and memory per worker);
- :mod:`.machine`: how many worker processes this machine takes, how much one run may ask;
- :mod:`.interrupt`: one behaviour on Ctrl-C (:class:`Interrupted`, :func:`interrupted`).

>>> from bearinglab.engine import open_runner, run_partitions
>>> kept = []
>>> with open_runner("serial") as runner:
...     _ = run_partitions(runner, abs, [-1, -2], [1, 1], lambda task, r: kept.append(r))
>>> kept
[1, 2]
"""

from .interrupt import (
    EXIT_CODE,
    Interrupted,
    catch_interrupts,
    deferred_interrupts,
    interrupted,
    quiet,
    reraise_interrupt,
)
from .machine import PROCESSES_PER_CORE, check_count, check_workers, most_processes
from .runner import (
    Progress,
    Runner,
    check_progress,
    cpu_seconds,
    measured_run,
    open_jobs,
    open_runner,
    peak_memory,
    run_partitions,
    warm,
)
from .scheduler import CONNECT_TIMEOUT, ENV_ADDRESS, check_scheduler, scheduler_of

__all__ = [
    "CONNECT_TIMEOUT",
    "ENV_ADDRESS",
    "EXIT_CODE",
    "PROCESSES_PER_CORE",
    "Interrupted",
    "Progress",
    "Runner",
    "catch_interrupts",
    "check_count",
    "check_progress",
    "check_scheduler",
    "check_workers",
    "cpu_seconds",
    "deferred_interrupts",
    "interrupted",
    "measured_run",
    "most_processes",
    "open_jobs",
    "open_runner",
    "peak_memory",
    "quiet",
    "reraise_interrupt",
    "run_partitions",
    "scheduler_of",
    "warm",
]
