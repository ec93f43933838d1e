"""Running partitions of work in this process or on dask.distributed.

The default is a :class:`distributed.LocalCluster` of one single-threaded worker process
per core; ``scheduler="tcp://HOST:PORT"`` (or the environment variable
``DASK_SCHEDULER_ADDRESS``) uses a running cluster, whose workers must be able to import
bearinglab; ``scheduler="serial"`` runs the partitions one after the other in this process
(tests, debugging, tiny runs). An address that does not answer fails within
``connect_timeout`` seconds (:mod:`.scheduler`). A command that takes a number of
processes (``jobs``) runs on a pool of processes forked from this one (:func:`open_jobs`),
which start at once. Finished partitions come back through
:func:`distributed.as_completed`, are handed to ``on_done`` (which writes or keeps them) and
are released at once, so the client never holds more than a few partitions.

Progress is one protocol: ``progress(done, total)``, in the units the caller counts
(cases, records), called before the first partition (``done`` > 0 when a run resumes) and
after each one. The library never draws a bar; the command line draws this one. The
dashboard's address of a long run is logged (logger ``bearinglab.engine``, level INFO).

A Ctrl-C stops a run in order (:mod:`.interrupt`): the partitions not finished are
cancelled, a LocalCluster started here is closed with its logs silenced, and
:class:`~.interrupt.Interrupted` says how many units were done.
"""

from __future__ import annotations

import logging
import os
import time
from collections.abc import Callable, Sequence
from contextlib import nullcontext
from dataclasses import dataclass

from ..errors import InputError
from . import scheduler as _scheduler
from .interrupt import Interrupted, deferred_interrupts, interrupted, quiet, reraise_interrupt
from .machine import check_workers, cpu_time, peak_rss
from .scheduler import _unreachable, _why, check_scheduler, scheduler_of

#: A run of at least this many partitions logs the dashboard address.
LONG_RUN_PARTITIONS = 20
#: Seconds given to closing a client or a cluster.
CLOSE_TIMEOUT = 10
#: Seconds a worker of our LocalCluster is given to stop when a run is interrupted.
STOP_GRACE = 0.25

log = logging.getLogger("bearinglab.engine")

#: ``progress(done, total)``: units done so far of all the run's units.
Progress = Callable[[int, int], None]


@dataclass
class Runner:
    """Where partitions run: ``client`` (a dask client; None for serial), the LocalCluster
    we started (if any), a description of the ``scheduler``, the number of ``workers``,
    the ``dashboard`` address (or None), and ``pool``: the process pool of
    :func:`open_jobs` (None on dask or serial)."""

    client: object | None
    cluster: object | None
    scheduler: str
    workers: int
    dashboard: str | None
    pool: object | None = None

    def close(self, quietly: bool = False) -> None:
        """Close the client, and the cluster if we started it.

        Parameters
        ----------
        quietly : bool
            We are stopping it (a Ctrl-C, an error): the workers of our cluster are
            stopped at once (a partition they were computing is dropped: only this process
            writes), nothing of the closing is logged and a failure to close is not
            raised.
        """
        if self.pool is not None:
            _close_pool(self.pool, quietly)
            self.pool = None
        if self.client is None and self.cluster is None:
            return
        with deferred_interrupts(), quiet() if quietly else nullcontext():
            if quietly and self.cluster is not None:
                _stop_workers(self.cluster)
            for part in (self.client, self.cluster):
                if part is None:
                    continue
                try:
                    part.close(timeout=CLOSE_TIMEOUT)
                except Exception:  # noqa: BLE001 - closing: what is left dies with us
                    if not quietly:
                        raise
            self.client = self.cluster = None

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, traceback) -> None:
        self.close(quietly=exc is not None)


def _close_pool(pool, quietly: bool) -> None:
    """Shut the process pool down; ``quietly``: at once, its processes terminated (a task
    they were computing is dropped)."""
    with deferred_interrupts():
        if not quietly:
            pool.shutdown(wait=True)
            return
        processes = list(getattr(pool, "_processes", {}).values())
        pool.shutdown(wait=False, cancel_futures=True)
        for process in processes:
            try:
                process.terminate()
            except (OSError, ValueError):  # already gone
                pass
        for process in processes:
            process.join(CLOSE_TIMEOUT)


def _stop_workers(cluster) -> None:
    """Stop the worker processes of our LocalCluster now: each is given ``STOP_GRACE``
    seconds to close, then killed (left alone, a worker finishes the task it runs first;
    a numba compilation takes seconds)."""
    import asyncio

    async def stop(nannies) -> None:
        await asyncio.gather(
            *(n.kill(timeout=STOP_GRACE, reason="interrupted") for n in nannies),
            return_exceptions=True,
        )

    try:
        cluster.sync(stop, list(cluster.workers.values()))
    except Exception:  # noqa: BLE001, S110 - closing the cluster then ends what is left
        pass


def open_runner(
    scheduler: str | None = None,
    workers: int | None = None,
    connect_timeout: float | None = None,
) -> Runner:
    """Connect to (or start) the cluster that runs the partitions.

    Parameters
    ----------
    scheduler : str, optional
        None: $DASK_SCHEDULER_ADDRESS if set, else a LocalCluster; "local": a LocalCluster;
        "serial": this process; "tcp://HOST:PORT": a running scheduler.
    workers : int, optional
        Worker processes of the LocalCluster (default: the machine's cores) [-].
    connect_timeout : float, optional
        Seconds to wait for a scheduler [s] (default :data:`.scheduler.CONNECT_TIMEOUT`).

    Returns
    -------
    Runner
        Use it as a context manager: it closes what it opened.
    """
    if connect_timeout is None:
        connect_timeout = _scheduler.CONNECT_TIMEOUT
    if workers is not None:
        workers = check_workers("workers", workers)
    scheduler = scheduler_of(scheduler)
    if scheduler == "serial":
        return Runner(None, None, "serial (this process)", 1, None)
    if scheduler == "local":
        return _local(workers or os.cpu_count() or 1)
    address = check_scheduler(str(scheduler), connect_timeout)
    from distributed import Client

    try:
        client = Client(address, timeout=f"{connect_timeout}s")
    except Exception as exc:  # noqa: BLE001 - whatever answered, it is no scheduler we can use
        reraise_interrupt(exc)
        raise _unreachable(address, _why(exc, connect_timeout)) from None
    runner = Runner(client, None, address, 0, client.dashboard_link)
    try:
        runner.workers = len(client.nthreads())
    except BaseException:
        runner.close(quietly=True)
        raise
    return runner


def _local(n: int) -> Runner:
    """A LocalCluster of ``n`` single-threaded worker processes and its client; started
    with SIGINT held back, so that its threads and workers never see a Ctrl-C (a Ctrl-C
    pressed meanwhile closes it again and is raised)."""
    from multiprocessing import resource_tracker

    from distributed import Client, LocalCluster

    # multiprocessing starts its resource tracker with SIGINT unblocked again in the thread
    # that first needs it (here: dask's IO loop, which then starts the workers): start it
    # now, from this thread, before SIGINT is held back
    resource_tracker.ensure_running()
    runner = Runner(None, None, f"LocalCluster ({n} worker processes)", n, None)
    try:
        with deferred_interrupts():
            runner.cluster = LocalCluster(
                n_workers=n,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",
                silence_logs=logging.ERROR,
            )
            runner.client = Client(runner.cluster)
            runner.dashboard = runner.client.dashboard_link
    except BaseException:
        runner.close(quietly=True)
        raise
    return runner


def open_jobs(jobs: int, scheduler: str | None = None, name: str = "jobs") -> Runner:
    """The runner of a command that takes a number of processes: this process for 1, a
    pool of ``jobs`` worker processes for more, or ``scheduler`` when one is given.

    The pool's processes are forked from this one (they start in a fraction of a second
    with what this process has imported; a LocalCluster's start and imports took 2-10 s
    on this machine, longer than many a benchmark) with SIGINT blocked: a Ctrl-C is this
    process's to handle, and it stops them.

    Parameters
    ----------
    jobs : int
        Worker processes, in [1, :func:`.machine.most_processes`] [-].
    scheduler : str, optional
        A dask scheduler address, "local" or "serial", instead (:func:`open_runner`).
    name : str
        The input that holds ``jobs``, for its error.
    """
    jobs = check_workers(name, jobs)
    if scheduler is not None:
        return open_runner(scheduler, workers=jobs if scheduler == "local" else None)
    if jobs == 1:
        return open_runner("serial")
    from concurrent.futures import ProcessPoolExecutor

    return Runner(
        None, None, f"process pool ({jobs} worker processes)", jobs, None, ProcessPoolExecutor(jobs)
    )


def check_progress(progress) -> Progress | None:
    """``progress`` as the engine calls it: a callable ``progress(done, total)``, or None.

    Parameters
    ----------
    progress : callable, optional
        None or False: no progress is told (the library draws no bar itself).
    """
    if progress is None or progress is False:
        return None
    if not callable(progress):
        raise InputError("progress", progress, "a callable progress(done, total), or None")
    return progress


def _import_modules(modules: Sequence[str], probe=None) -> int:
    import importlib

    for m in modules:
        importlib.import_module(m)
    if probe is not None:
        func, arg = probe
        try:
            func(arg)
        except Exception as exc:  # noqa: BLE001 - a warm-up only: the run reports errors
            reraise_interrupt(exc)
    return os.getpid()


def warm(runner: Runner, modules: Sequence[str], probe=None) -> None:
    """Import ``modules`` and run ``probe`` once on every worker first: numba kernels load
    from their on-disk cache (or compile) at their first call, once per process, and that
    should not be charged to the first partitions.

    Parameters
    ----------
    runner : Runner
        Where the partitions will run.
    modules : sequence of str
        Modules to import.
    probe : tuple, optional
        (function, argument): a small piece of the work; its errors are left to the run.
    """
    if runner.pool is not None:
        return  # each forked process has what this one imported
    if runner.client is None:
        _import_modules(modules, probe)
    else:
        runner.client.run(_import_modules, list(modules), probe)


def cpu_seconds(runner: Runner) -> dict:
    """CPU time used so far by each worker process (this process when serial) [s]: the
    difference over a run shows how much of a core each worker got.

    Parameters
    ----------
    runner : Runner
        Where the partitions run.
    """
    if runner.pool is not None:
        return {}  # a pool's processes cannot be asked one by one
    if runner.client is None:
        return {"serial": cpu_time()}
    return runner.client.run(cpu_time)


def peak_memory(runner: Runner) -> dict:
    """Peak resident memory of each worker process (this process when serial) [bytes].

    Parameters
    ----------
    runner : Runner
        Where the partitions run.
    """
    if runner.pool is not None:
        return {}
    if runner.client is None:
        return {"serial": peak_rss()}
    return runner.client.run(peak_rss)


def run_partitions(
    runner: Runner,
    func: Callable,
    tasks: list,
    units: list[int],
    on_done: Callable,
    *,
    progress: Progress | None = None,
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
        Units of work (cases, records) in each task, the units ``progress`` counts.
    on_done : callable
        Called in this process with (task, result); the result is then released.
    progress : callable, optional
        ``progress(done, total)``: called before the first partition and after each one.
    total : int, optional
        Units of the whole run (default: those of ``tasks`` and ``done``).
    done : int
        Units already done before these tasks (a run that resumes, a second stage).

    Returns
    -------
    float
        Wall time [s].

    Raises
    ------
    Interrupted
        On Ctrl-C: the partitions not finished are cancelled; ``done`` counts the units
        finished (handed to ``on_done``).
    """
    start = time.perf_counter()
    total = done + sum(units) if total is None else total
    count = [done]

    def advance(n: int) -> None:
        count[0] += n
        if progress is not None:
            progress(min(count[0], total), total)

    if runner.dashboard and len(tasks) >= LONG_RUN_PARTITIONS:
        log.info("dashboard: %s (%s)", runner.dashboard, runner.scheduler)
    try:
        advance(0)
        if runner.pool is not None:
            _on_pool(runner.pool, func, tasks, units, on_done, advance)
        elif runner.client is None:
            for task, n in zip(tasks, units, strict=True):
                on_done(task, func(task))
                advance(n)
        else:
            _on_cluster(runner, func, tasks, units, on_done, advance)
    except BaseException as exc:
        if isinstance(exc, Interrupted) or not interrupted(exc):
            raise
        raise Interrupted(min(count[0], total), total) from None
    return time.perf_counter() - start


def _on_pool(pool, func, tasks, units, on_done, advance) -> None:
    from concurrent.futures import as_completed

    with deferred_interrupts():  # the processes fork here: SIGINT stays blocked in them
        futures = {pool.submit(func, task): i for i, task in enumerate(tasks)}
    for future in as_completed(futures):
        i = futures.pop(future)
        on_done(tasks[i], future.result())
        advance(units[i])


def _on_cluster(runner: Runner, func, tasks, units, on_done, advance) -> None:
    from distributed import as_completed

    futures = runner.client.map(func, tasks, pure=False)
    index = {f.key: i for i, f in enumerate(futures)}
    try:
        for future in as_completed(futures):
            i = index[future.key]
            on_done(tasks[i], future.result())
            future.release()
            advance(units[i])
    except BaseException:
        with deferred_interrupts(), quiet():
            try:
                runner.client.cancel([f for f in futures if not f.done()])
            except Exception:  # noqa: BLE001, S110 - stopping: the cluster is closed next
                pass
        raise
    runner.client.cancel([f for f in futures if not f.done()])


def measured_run(
    runner: Runner, modules: Sequence[str], probe, func: Callable, tasks, units, on_done, **kw
) -> tuple[float, dict, dict]:
    """:func:`warm`, then :func:`run_partitions`: wall time [s], the CPU time each worker
    used in the run [s] and each worker's peak memory [bytes].

    Parameters
    ----------
    runner : Runner
        Where to run.
    modules, probe
        As for :func:`warm`.
    func, tasks, units, on_done
        As for :func:`run_partitions`.
    **kw
        ``progress``, ``total`` and ``done`` of :func:`run_partitions`.
    """
    try:
        warm(runner, modules, probe)
        cpu0 = cpu_seconds(runner)
    except BaseException as exc:
        if not interrupted(exc):
            raise
        done = kw.get("done", 0)
        raise Interrupted(done, kw.get("total") or done + sum(units)) from None
    seconds = run_partitions(runner, func, tasks, units, on_done, **kw)
    cpu = {w: t - cpu0.get(w, 0.0) for w, t in cpu_seconds(runner).items()}
    return seconds, cpu, peak_memory(runner)
