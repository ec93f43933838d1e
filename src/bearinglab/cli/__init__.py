"""The ``bearinglab`` command line (typer + rich): parse, call the analyses, print.

Every command accepts a designation and/or explicit geometry (the options below, or a
TOML file), prints readable tables, and with ``--json`` one JSON object whose keys carry
their units. Bad input exits with code 2 and one line on stderr; Ctrl-C exits with code
130 and one line. Commands are imported only when run
(:data:`bearinglab.cli._app.COMMANDS`).
"""

import sys

__all__ = ["app", "main"]


def main(argv: list[str] | None = None) -> int:
    """Entry point (:func:`bearinglab.cli._app.main`); a Ctrl-C while the command line
    itself is still being imported is one line and exit code 130 too."""
    try:
        from ._app import main as run
    except KeyboardInterrupt:
        sys.stderr.write("interrupted\n")
        return 130
    return run(argv)


def __getattr__(name: str):
    if name == "app":
        from ._app import app

        return app
    raise AttributeError(name)
