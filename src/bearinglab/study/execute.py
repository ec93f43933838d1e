"""Running partitions on dask.distributed, with a progress bar over cases.

The default is a :class:`distributed.LocalCluster` of one single-threaded worker process
per core; ``scheduler="tcp://HOST:PORT"`` (or the environment variable
``DASK_SCHEDULER_ADDRESS``) uses a running cluster, whose workers must be able to import
bearinglab; ``scheduler="serial"`` runs the partitions one after the other in this process
(tests, debugging, tiny studies). An address that does not answer fails within
``connect_timeout`` seconds. Finished partitions come back through
:func:`distributed.as_completed`, are handed to ``on_done`` (which writes them) and are
released at once, so the client never holds more than a few partitions.
"""

from __future__ import annotations

import logging
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from ..errors import InputError

ENV_ADDRESS = "DASK_SCHEDULER_ADDRESS"
#: Seconds to wait for a scheduler before saying it is unreachable.
CONNECT_TIMEOUT = 5.0
#: A run of at least this many partitions prints the dashboard address.
LONG_RUN_PARTITIONS = 20


@dataclass
class Runner:
    """Where partitions run: ``client`` (None for serial), the LocalCluster we started (if
    any), a description of the scheduler and the number of workers."""

    client: object | None
    cluster: object | None
    scheduler: str
    workers: int
    dashboard: str | None

    def close(self) -> None:
        if self.client is not None:
            self.client.close()
        if self.cluster is not None:
            self.cluster.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _check_address(address: str) -> str:
    scheme, sep, rest = address.partition("://")
    host, colon, port = rest.rpartition(":")
    if (
        not sep
        or scheme not in ("tcp", "tls", "ucx", "inproc", "ws", "wss")
        or not colon
        or not host
        or not port.isdigit()
    ):
        raise InputError(
            "scheduler", address, "a dask scheduler address tcp://HOST:PORT, or 'local' or 'serial'"
        )
    return address


def scheduler_of(scheduler: str | None) -> str:
    """The scheduler :func:`open_runner` uses: ``scheduler``, else $DASK_SCHEDULER_ADDRESS,
    else "local" (only a LocalCluster has a number of workers to choose)."""
    if scheduler is None:
        return os.environ.get(ENV_ADDRESS) or "local"
    return scheduler


def open_runner(
    scheduler: str | None = None,
    workers: int | None = None,
    connect_timeout: float = CONNECT_TIMEOUT,
) -> Runner:
    """Connect to (or start) the cluster that runs a study's partitions.

    Parameters
    ----------
    scheduler : str, optional
        None: $DASK_SCHEDULER_ADDRESS if set, else a LocalCluster; "local": a LocalCluster;
        "serial": this process; "tcp://HOST:PORT": a running scheduler.
    workers : int, optional
        Worker processes of the LocalCluster (default: the machine's cores).
    connect_timeout : float
        Seconds to wait for a scheduler [s].
    """
    from ..machine import most_processes

    most = most_processes()
    if workers is not None and (
        isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= most
    ):
        raise InputError(
            "workers", workers, f"a number of worker processes in [1, {most}] (4 per core)"
        )
    scheduler = scheduler_of(scheduler)
    if scheduler == "serial":
        return Runner(None, None, "serial (this process)", 1, None)
    from distributed import Client

    if scheduler == "local":
        from distributed import LocalCluster

        n = workers or os.cpu_count() or 1
        cluster = LocalCluster(
            n_workers=n,
            threads_per_worker=1,
            processes=True,
            dashboard_address=":0",
            silence_logs=logging.ERROR,
        )
        client = Client(cluster)
        return Runner(
            client, cluster, f"LocalCluster ({n} worker processes)", n, client.dashboard_link
        )
    address = _check_address(str(scheduler))
    try:
        client = Client(address, timeout=f"{connect_timeout}s")
    except (OSError, TimeoutError) as exc:
        why = (
            "no answer"
            if isinstance(exc, TimeoutError) or "Timed out" in str(exc)
            else " ".join(str(exc).split())[:120]
        )
        raise InputError(
            "scheduler",
            address,
            "the address of a running dask scheduler",
            f"{why} within {connect_timeout:g} s",
        ) from None
    n = len(client.nthreads())
    return Runner(client, None, address, n, client.dashboard_link)


def _import_modules(modules: Sequence[str], probe=None) -> int:
    import importlib

    for m in modules:
        importlib.import_module(m)
    if probe is not None:
        func, arg = probe
        try:
            func(arg)
        except Exception:  # noqa: BLE001, S110 - a warm-up only: the run reports errors
            pass
    return os.getpid()


def warm(runner: Runner, modules: Sequence[str], probe=None) -> None:
    """Import ``modules`` and run ``probe`` = (func, arg) once on every worker first: numba
    kernels load from their on-disk cache (or compile) at their first call, once per
    process, and that should not be charged to the first partitions."""
    if runner.client is None:
        _import_modules(modules, probe)
    else:
        runner.client.run(_import_modules, list(modules), probe)


def _peak_rss() -> int:
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # Linux: kB


def _cpu_seconds() -> float:
    import resource

    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def cpu_seconds(runner: Runner) -> dict:
    """CPU time used so far by each worker process [s] (this process when serial): the
    difference over a run shows how much of a core each worker got."""
    if runner.client is None:
        return {"serial": _cpu_seconds()}
    return runner.client.run(_cpu_seconds)


def peak_memory(runner: Runner) -> dict:
    """Peak resident memory of each worker process [bytes] (this process when serial)."""
    if runner.client is None:
        return {"serial": _peak_rss()}
    return runner.client.run(_peak_rss)


def run_partitions(
    runner: Runner,
    func: Callable,
    tasks: list,
    units: list[int],
    on_done: Callable,
    *,
    progress: bool = False,
    label: str = "cases",
    total: int | None = None,
    done: int = 0,
) -> float:
    """Run ``func(task)`` for every task; ``on_done(task, result)`` as each finishes.

    Parameters
    ----------
    runner : Runner
        Where to run.
    func : callable
        Top-level (picklable) function of one task.
    tasks : list
        Arguments of func, one per partition.
    units : list of int
        Cases (or records) in each task, for the progress bar.
    on_done : callable
        Called in this process with (task, result); the result is then released.
    progress : bool
        Show a rich progress bar (on stderr).
    label : str
        What the units are ("cases", "records").
    total, done : int
        Units of the whole study and those already done before this run.

    Returns
    -------
    float
        Wall time [s].
    """
    from contextlib import nullcontext

    start = time.perf_counter()
    bar = _progress(label) if progress else None
    with bar if bar is not None else nullcontext():
        job = None
        if bar is not None:
            job = bar.add_task(
                label, total=total if total is not None else sum(units), completed=done
            )
            if runner.dashboard and len(tasks) >= LONG_RUN_PARTITIONS:
                bar.console.print(f"dashboard: {runner.dashboard} ({runner.scheduler})")
        if runner.client is None:
            for task, n in zip(tasks, units, strict=True):
                on_done(task, func(task))
                if bar is not None:
                    bar.advance(job, n)
        else:
            from distributed import as_completed

            futures = runner.client.map(func, tasks, pure=False)
            index = {f.key: i for i, f in enumerate(futures)}
            try:
                for future in as_completed(futures):
                    i = index[future.key]
                    on_done(tasks[i], future.result())
                    future.release()
                    if bar is not None:
                        bar.advance(job, units[i])
            finally:
                runner.client.cancel([f for f in futures if not f.done()])
    return time.perf_counter() - start


def measured_run(
    runner: Runner, modules: Sequence[str], probe, func: Callable, tasks, units, on_done, **kw
) -> tuple[float, dict, dict]:
    """:func:`warm`, then :func:`run_partitions` (``kw`` as there): wall time [s], the CPU
    time each worker used in the run [s] and each worker's peak memory [bytes]."""
    warm(runner, modules, probe)
    cpu0 = cpu_seconds(runner)
    seconds = run_partitions(runner, func, tasks, units, on_done, **kw)
    cpu = {w: t - cpu0.get(w, 0.0) for w, t in cpu_seconds(runner).items()}
    return seconds, cpu, peak_memory(runner)


def check_count(name: str, count: int, most: int, confirm: int | None, verb: str) -> None:
    """Refuse more than ``most`` cases or records (``name``) at all, and more than
    ``confirm`` without confirmation (``max_<name>``; ``verb`` is what is done to them)."""
    if count > most:
        raise InputError(name, count, f"at most {most:g} {name} in one run")
    if confirm is not None and count > confirm:
        raise InputError(
            name,
            count,
            f"at most {confirm} {name} without confirmation",
            f"confirm with --yes (or raise max_{name}) to {verb} them all",
        )


def _progress(label: str):
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    return Progress(
        TextColumn("[progress.description]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        TextColumn("left"),
        TimeRemainingColumn(),
        console=Console(stderr=True),
        transient=False,
    )
