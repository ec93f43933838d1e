"""Numba compiles a kernel the first time it runs after install (the models' kernels
take 20 s together, minutes on a busy machine); later processes load them from numba's
on-disk cache. :func:`watch` says so once per process, as a warning on the logger
``bearinglab.engine.compiling`` (a command that sat silent that long looked hung); the
command line's progress bars print it above themselves."""

from __future__ import annotations

import logging

log = logging.getLogger(__name__)
_state = {"watching": False, "told": False}


def watch() -> None:
    """Tell the first compilation in this process (idempotent; the modules that define
    numba kernels call it when imported)."""
    if _state["watching"]:
        return
    _state["watching"] = True
    from numba.core import event

    class _FirstCompile(event.Listener):
        def on_start(self, ev) -> None:
            if _state["told"]:
                return
            _state["told"] = True
            log.warning(
                "compiling the numerical kernels (the first run after install only; later "
                "runs load them from the cache): about 20 s, longer on a busy machine"
            )

        def on_end(self, ev) -> None:
            pass

    event.register("numba:compile", _FirstCompile())
