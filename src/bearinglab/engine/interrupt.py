"""Ctrl-C: one behaviour for every command and every run of the engine.

A Ctrl-C (SIGINT) raises KeyboardInterrupt in the main thread. Four things lost it on the
way before this module:

- numba: a KeyboardInterrupt raised while a compiled function is first called and loads
  its cached code (numba's ``_numba_unpickle``, called back from C) comes out of numba's
  dispatcher as ``SystemError("CPUDispatcher(...) returned a result with an exception
  set")``, whose ``__cause__`` is the KeyboardInterrupt, or crashes the process (SIGSEGV,
  numba 0.68: 2 runs in 8 of ``simulate`` interrupted then); one raised in llvmlite's
  ctypes callbacks as a kernel compiles is printed as "Exception ignored" and lost;
- code that keeps going after a failure (a failed case, record, report section or
  validation case) with ``except Exception``, which then recorded the interrupt, so
  wrapped, as that item's failure and went on (a data set lost the record for good);
- dask: the worker processes of a LocalCluster share the terminal's process group, got
  the same SIGINT and died printing walls of tracebacks;
- typer: it turns a KeyboardInterrupt into a silent exit code 130 (the command line
  carries it past typer, :mod:`bearinglab.cli._app`).

So: :func:`catch_interrupts` (the command line's handler) holds a Ctrl-C back while numba
or llvmlite is in such a callback and raises it as soon as the callback returns (loading
a kernel takes a few seconds on a busy machine; a crash is worse); :func:`interrupted` tells an
interruption from a failure (the exception or any of its causes is a KeyboardInterrupt,
or a SIGINT arrived since :func:`catch_interrupts` began);
:func:`reraise_interrupt` is the first line of every ``except Exception`` that keeps going;
the engine starts its worker processes under :func:`deferred_interrupts` (SIGINT blocked
for them for good, so only this process sees a Ctrl-C and stops them in order) and closes
a cluster it is leaving under :func:`quiet` (its logs silenced); an interrupted run raises
:class:`Interrupted` with how far it got. What was written is whole
(:func:`bearinglab.files.write_atomically`), and a resumable run (a study, a data set)
computes only what is missing when it is run again. The command line prints one line;
``main(argv)`` returns 130, and the program then ends by SIGINT as Python's own does on
Ctrl-C (a shell reports exit status 130 = 128 + SIGINT, and stops a loop that runs it).
"""

from __future__ import annotations

import logging
import signal
import threading
from contextlib import contextmanager

#: The exit code of a command stopped by Ctrl-C.
EXIT_CODE = 130

_seen = [False]


class Interrupted(KeyboardInterrupt):
    """A run stopped by Ctrl-C: ``done`` of ``total`` units (cases, records) were finished
    (and, for a resumable run, kept); ``resume`` says how to go on, or is None."""

    def __init__(
        self,
        done: int | None = None,
        total: int | None = None,
        resume: str | None = None,
    ) -> None:
        super().__init__(done, total)
        self.done = done
        self.total = total
        self.resume = resume


def interrupted(exc: BaseException | None = None) -> bool:
    """True when ``exc`` stands for a Ctrl-C rather than a failure.

    Parameters
    ----------
    exc : BaseException, optional
        An exception caught. It stands for a Ctrl-C when it, its ``__cause__`` or its
        ``__context__`` (followed down the chain) is a KeyboardInterrupt, or when a SIGINT
        arrived since :func:`catch_interrupts` began (with or without ``exc``).
    """
    if _seen[0]:
        return True
    followed: set[int] = set()
    while exc is not None and id(exc) not in followed:
        if isinstance(exc, KeyboardInterrupt):
            return True
        followed.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return False


def reraise_interrupt(exc: BaseException) -> None:
    """Raise KeyboardInterrupt when ``exc`` stands for a Ctrl-C (:func:`interrupted`).

    The first line of every ``except Exception`` that keeps going after a failure, so that
    an interrupt is never recorded as a failed case or record.

    Parameters
    ----------
    exc : BaseException
        The exception caught.
    """
    if interrupted(exc):
        raise KeyboardInterrupt from None


#: Python functions that numba and llvmlite call back into from C and that must not
#: raise: a KeyboardInterrupt raised in numba's came back as a SystemError or crashed the
#: process (SIGSEGV; numba 0.68, 2 runs in 8 when Ctrl-C came as a cached kernel was
#: loaded); in llvmlite's (ctypes callbacks, as a kernel is compiled) it was printed as
#: "Exception ignored" and lost, and the compilation went on.
_CALLBACKS = (
    ("numba", "serialize.py", "_numba_unpickle"),
    ("llvmlite", "executionengine.py", "_raw_object_cache_notify"),
    ("llvmlite", "executionengine.py", "_raw_object_cache_getbuffer"),
)
#: Seconds before a Ctrl-C held back from such a callback is raised again.
_RETRY = 0.02


def _in_callback(frame) -> bool:
    """Whether ``frame`` or one of its callers is a callback of :data:`_CALLBACKS`, or one
    Python itself calls where an exception cannot propagate: a finalizer (``__del__``) or
    a weak reference's callback (the garbage collector's; a KeyboardInterrupt raised there
    is printed as "Exception ignored" and lost)."""
    while frame is not None:
        code = frame.f_code
        path = code.co_filename
        if code.co_name == "__del__" or path.endswith(("weakref.py", "_weakrefset.py")):
            return True
        for package, file, name in _CALLBACKS:
            if code.co_name == name and path.endswith(file) and package in path:
                return True
        frame = frame.f_back
    return False


def _remember(signum, frame) -> None:
    _seen[0] = True
    if _in_callback(frame):  # sent again until the callback has returned
        main = threading.main_thread().ident
        threading.Timer(_RETRY, signal.pthread_kill, (main, signum)).start()
        return
    raise KeyboardInterrupt


def _main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


@contextmanager
def catch_interrupts():
    """Within, a SIGINT raises KeyboardInterrupt as Python's own handler does and is also
    remembered, so that :func:`interrupted` is True even after a library swallowed the
    exception (until the block ends); one that comes while numba loads a kernel is raised
    as soon as it has. A SIGINT that is ignored (a command started in the background by a
    shell) stays ignored."""
    _seen[0] = False
    if not _main_thread() or signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return
    previous = signal.signal(signal.SIGINT, _remember)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        _seen[0] = False


@contextmanager
def deferred_interrupts():
    """Within, a Ctrl-C is held back and raised as KeyboardInterrupt when the block ends;
    the threads and processes started within inherit SIGINT blocked, for good.

    Used around the start of a LocalCluster (its workers then never see a Ctrl-C: this
    process stops them in order) and around the closing of one (a second Ctrl-C does not
    leave it half closed)."""
    if not _main_thread():
        yield
        return
    pending: list[int] = []
    previous = signal.getsignal(signal.SIGINT)
    deferring = callable(previous)  # a Python handler, not SIG_IGN or SIG_DFL
    if deferring:
        signal.signal(signal.SIGINT, lambda signum, frame: pending.append(signum))
    masking = hasattr(signal, "pthread_sigmask")
    mask = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT}) if masking else None
    try:
        yield
    finally:
        if masking:  # a SIGINT held back is delivered now, to the handler that defers it
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        if deferring:
            signal.signal(signal.SIGINT, previous)
        if pending:
            _seen[0] = _seen[0] or previous is _remember
            raise KeyboardInterrupt


@contextmanager
def quiet():
    """Within, nothing is logged (dask's scheduler, nannies and client report the workers
    they lose and the comms they close as errors, with tracebacks, when we are the ones
    stopping them)."""
    manager = logging.root.manager
    level = manager.disable
    logging.disable(logging.CRITICAL)
    try:
        yield
    finally:
        logging.disable(level)
