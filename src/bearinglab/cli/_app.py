"""The typer application, the shared enums and the entry point (one line per user error)."""

import os
import sys
from enum import Enum
from typing import Annotated

import typer
from rich.console import Console

from .. import __version__
from ..errors import BearinglabError

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  rich_markup_mode=None,
                  help="Rolling-bearing mechanics, vibration and diagnostics from published "
                       "methods. Run 'bearinglab COMMAND --help' for a command's options.")
console = Console()


class System(str, Enum):
    gost = "gost"
    iso = "iso"


class HertzMethod(str, Enum):
    exact = "exact"
    hamrock_brewe = "hamrock-brewe"


def _version(value: bool):
    if value:
        print(f"bearinglab {__version__}")
        raise typer.Exit()


@app.callback()
def _main(version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                                help="Show the version and exit.")] = False):
    """Rolling-bearing mechanics, vibration and diagnostics from published methods."""


def main(argv: list[str] | None = None) -> int:
    """Entry point: run the app; user errors become one line on stderr and exit code 2.

    With no arguments it prints the help (stdout, exit code 0).  An unexpected failure is
    one line on stderr and exit code 1 (``BEARINGLAB_DEBUG=1`` shows the traceback)."""
    args = list(sys.argv[1:] if argv is None else argv)
    if not args:
        args = ["--help"]
    try:
        result = app(args=args, standalone_mode=False)
    except typer.Exit as exc:
        return exc.exit_code
    except typer.Abort:
        sys.stderr.write("aborted\n")
        return 1
    except BearinglabError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 2
    except typer.TyperException as exc:  # usage errors: unknown option, bad type, missing
        text = exc.format_message() if hasattr(exc, "format_message") else str(exc)
        sys.stderr.write("error: " + " ".join(text.split()) + "\n")
        return 2
    except Exception as exc:  # a bug: say so in one line rather than a traceback
        if os.environ.get("BEARINGLAB_DEBUG"):
            raise
        text = " ".join(str(exc).split())
        sys.stderr.write(f"error: internal error ({type(exc).__name__}: {text}); please report "
                         "it with the command line (BEARINGLAB_DEBUG=1 shows the traceback)\n")
        return 1
    return result if isinstance(result, int) else 0
