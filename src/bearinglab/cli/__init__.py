"""The ``bearinglab`` command line (typer + rich): parse, call the analyses, print.

Every command accepts a designation and/or explicit geometry (the options below, or a
TOML file), prints readable tables, and with ``--json`` one JSON object whose keys carry
their units. Bad input exits with code 2 and one line on stderr. Commands are imported
only when run (:data:`bearinglab.cli._app.COMMANDS`).
"""

from ._app import app, main

__all__ = ["app", "main"]
