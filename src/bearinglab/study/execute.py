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


#: Largest first message a dask scheduler sends (its handshake: a few hundred bytes).
_HANDSHAKE_BYTES = 1 << 20


def _unreachable(address: str, why: str) -> InputError:
    return InputError("scheduler", address, "the address of a running dask scheduler", why)


def _why(exc: BaseException, timeout: float) -> str:
    """Why connecting failed, in a few words."""
    if isinstance(exc, TimeoutError) or "Timed out" in str(exc):
        return f"no answer within {timeout:g} s"
    if isinstance(exc, ConnectionRefusedError):
        return "connection refused: nothing listens there"
    text = " ".join(str(exc).split())[:120]
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def _receive(sock, n: int, deadline: float) -> bytes:
    """``n`` bytes from ``sock`` before ``deadline`` (time.monotonic()); fewer when the
    peer closes the connection; TimeoutError when the time runs out."""
    data = b""
    while len(data) < n:
        left = deadline - time.monotonic()
        if left <= 0:
            raise TimeoutError
        sock.settimeout(left)
        chunk = sock.recv(min(n - len(data), 65536))
        if not chunk:
            break
        data += chunk
    return data


def _handshake() -> bytes:
    """The first message dask's client sends (``Comm.handshake_info``), framed as on TCP."""
    import pickle
    import struct
    import sys

    from distributed.protocol.core import dumps
    from distributed.protocol.utils import pack_frames

    info = {
        "compression": None,
        "python": tuple(sys.version_info)[:3],
        "pickle-protocol": pickle.HIGHEST_PROTOCOL,
    }
    body = pack_frames(dumps(info))
    return struct.pack("<Q", len(body)) + body


def _probe_tcp(address: str, timeout: float) -> None:
    """Connect to a tcp:// address, send dask's handshake and read the scheduler's, all
    within ``timeout`` seconds. A port where nothing listens, a server that never answers
    and one that answers in another protocol (HTTP, ...) are refused here; dask's own
    client would wait for ever on the second, and read the third's first bytes as a
    message length (and ask for exbibytes of memory)."""
    import socket
    import struct

    host, _, port = address.partition("://")[2].rpartition(":")
    host = host.strip("[]")
    message = _handshake()  # imports distributed's protocol first: not on the clock
    deadline = time.monotonic() + timeout
    try:
        sock = socket.create_connection((host, int(port)), timeout=timeout)
    except socket.gaierror:
        raise _unreachable(address, f"unknown host {host!r}") from None
    except OSError as exc:
        raise _unreachable(address, _why(exc, timeout)) from None
    with sock:
        try:
            sock.sendall(message)
            head = _receive(sock, 8, deadline)
            (size,) = struct.unpack("<Q", head) if len(head) == 8 else (0,)
            body = _receive(sock, size, deadline) if 8 <= size <= _HANDSHAKE_BYTES else b""
        except TimeoutError:
            raise _unreachable(
                address,
                f"it accepted the connection but sent no dask handshake within {timeout:g} s",
            ) from None
        except OSError as exc:
            raise _unreachable(address, _why(exc, timeout)) from None
    if not head:
        raise _unreachable(address, "it closed the connection without a dask handshake")
    try:
        from distributed.protocol.core import loads
        from distributed.protocol.utils import unpack_frames

        if len(body) != size:
            raise ValueError(size)
        handshake = loads(unpack_frames(body, partial=True)[0], deserialize=False)
        if not isinstance(handshake, dict):
            raise ValueError(handshake)
    except Exception:  # noqa: BLE001 - anything that is not dask's handshake
        shown = "".join(c if c.isprintable() else "." for c in head.decode("latin-1"))
        raise _unreachable(
            address, f"it answers in another protocol (its first bytes: {shown!r})"
        ) from None


def check_scheduler(address: str, timeout: float | None = None) -> str:
    """``address`` if a dask scheduler answers there within ``timeout`` seconds, else an
    InputError saying what answered (a malformed address, nothing, something else);
    tcp:// addresses are probed with a plain socket first (:func:`_probe_tcp`)."""
    address = _check_address(address)
    timeout = CONNECT_TIMEOUT if timeout is None else timeout
    if address.startswith("tcp://"):
        _probe_tcp(address, timeout)
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
    connect_timeout: float | None = None,
) -> Runner:
    """Connect to (or start) the cluster that runs a study's partitions.

    Parameters
    ----------
    scheduler : str, optional
        None: $DASK_SCHEDULER_ADDRESS if set, else a LocalCluster; "local": a LocalCluster;
        "serial": this process; "tcp://HOST:PORT": a running scheduler.
    workers : int, optional
        Worker processes of the LocalCluster (default: the machine's cores).
    connect_timeout : float, optional
        Seconds to wait for a scheduler [s] (default :data:`CONNECT_TIMEOUT`).
    """
    if connect_timeout is None:
        connect_timeout = CONNECT_TIMEOUT
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
    address = check_scheduler(str(scheduler), connect_timeout)
    try:
        client = Client(address, timeout=f"{connect_timeout}s")
    except Exception as exc:  # noqa: BLE001 - whatever answered, it is no scheduler we can use
        raise _unreachable(address, _why(exc, connect_timeout)) from None
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
            f"confirm with `yes` (or raise max_{name}) to {verb} them all",
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

    console = Console(stderr=True)
    return Progress(
        TextColumn("[progress.description]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        TextColumn("left"),
        TimeRemainingColumn(),
        console=console,
        transient=False,
        # off a terminal (a pipe, a log file, a test) nothing of the bar is printed
        disable=not console.is_terminal,
    )
