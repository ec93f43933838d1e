"""The ``bearinglab`` command line (typer + rich): parse, call the analyses, print.

Every command accepts a designation and/or explicit geometry (the options below, or a
TOML file), prints readable tables, and with ``--json`` one JSON object whose keys carry
their units. Bad input exits with code 2 and one line on stderr; Ctrl-C exits with code
130 and one line. Commands are imported only when run
(:data:`bearinglab.cli._app.COMMANDS`).
"""

import os
import signal
import sys

__all__ = ["app", "main"]


def main(argv: list[str] | None = None) -> int:
    """Entry point (:func:`bearinglab.cli._app.main`); a Ctrl-C while the command line
    itself is still being imported is one line and exit code 130 too.

    Run as the program (``argv`` None: the ``bearinglab`` script, ``python -m
    bearinglab.cli``), a Ctrl-C ends the process the way Python's own does, by SIGINT
    once the line is written, which a shell reports as exit status 130 and which stops a
    shell loop that runs the command (a plain exit(130) would let the loop go on). Called
    with ``argv`` (tests, other programs), it returns 130."""
    try:
        from ._app import main as run

        code = run(argv)
    except KeyboardInterrupt:
        sys.stderr.write("interrupted\n")
        code = 130
    if code == 130 and argv is None:
        _die_by_sigint()
    return code


def _die_by_sigint() -> None:
    """End this process by SIGINT (what was written is flushed; nothing else runs)."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    os.kill(os.getpid(), signal.SIGINT)


def __getattr__(name: str):
    if name == "app":
        from ._app import app

        return app
    raise AttributeError(name)
