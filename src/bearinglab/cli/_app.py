"""The typer application, its lazily loaded commands and the entry point (one line per
user error, one line and exit code 130 on Ctrl-C).

Start-up matters: ``bearinglab --help`` must not import the analyses. Each command lives
in a module of its own with its own ``app = command_app()``; :data:`COMMANDS` names the
module and the one-line help of every command, so the top-level help and the command
lookup import nothing until a command runs (``tests/unit/test_cli_startup.py`` checks
that the table agrees with the commands' docstrings).
"""

import importlib
import logging
import os
import sys
from collections.abc import Mapping
from enum import Enum

import typer
from typer.core import TyperGroup

from .. import __version__
from ..errors import BearinglabError

#: command name -> (module in bearinglab.cli, one-line help: how its docstring begins)
COMMANDS: dict[str, tuple[str, str]] = {
    "info": (
        "foundation",
        "Decode a designation; show dimensions, internal geometry (with sources) and "
        "frequency factors.",
    ),
    "frequencies": (
        "foundation",
        "Kinematic defect frequencies (pure rolling) in Hz and as orders.",
    ),
    "contact": (
        "foundation",
        "Hertz contact of one ball or roller with the inner and outer raceway.",
    ),
    "static": (
        "quasistatic",
        "Quasi-static load distribution: per-ball (per-roller) loads and contact angles, "
        "ring displacements and the 5x5 stiffness matrix.",
    ),
    "stiffness-map": (
        "quasistatic",
        "Radial and axial stiffness (and displacements) over a grid of loads and speeds.",
    ),
    "ring-modes": (
        "rings",
        "Natural frequencies of the outer ring in the loaded bearing (seed 000).",
    ),
    "simulate": (
        "simulate",
        "Simulate the vibration of a bearing with defects and form errors (seed 003 rigid"
        " model or seed 004 slip model).",
    ),
    "analyze": ("analyze", "Diagnose a vibration record by envelope analysis."),
    "benchmark": ("benchmark", "Run the diagnosis over a folder of labelled recordings."),
    "trend": ("trend", "Trend health indicators over a series of recordings and raise an alarm."),
    "noise": (
        "noise",
        "Noise of a running ball bearing with waviness, ball-size errors and random "
        "surfaces (seed 003 part 4, seed 002).",
    ),
    "friction": (
        "friction",
        "Friction torque and power loss: seed 003's constant coefficient or the SKF model.",
    ),
    "life": ("life", "Load ratings C, C0, Cu, equivalent loads, basic and modified rating life."),
    "validate": ("validate", "Run every published case bearinglab reproduces."),
    "report": (
        "report",
        "Write an engineer's report of a bearing at an operating point to one self-"
        "contained HTML page.",
    ),
    "study": ("study", "Run one analysis over a grid of inputs or a table of cases, on dask."),
    "dataset": (
        "dataset",
        "Make labelled synthetic vibration records in the bearing-datasets layout, on dask.",
    ),
}


#: Options that were removed or whose meaning changed: (command, old flag) -> the line
#: that says what replaces it (renamed options whose meaning stayed are aliases instead).
REPLACED: dict[tuple[str, str], str] = {
    ("trend", "--false-alarm"): "use --false-alarm-per-hour, a rate per hour of monitoring "
    "(--false-alarm was a probability per record; 1e-6 per record at a record every 10 s is "
    "3.6e-4 per hour)",
}


def replaced(args: list[str]) -> str | None:
    """The line refusing a replaced option of ``args``' command, or None."""
    args = [str(a) for a in args]
    command = next((a for a in args if not a.startswith("-")), None)
    for arg in args:
        line = REPLACED.get((command, arg.split("=")[0]))
        if line is not None:
            return f"error: {arg.split('=')[0]} is no longer an option of {command}: {line}"
    return None


def command_app() -> typer.Typer:
    """The typer app a command module registers its command(s) on."""
    return typer.Typer(add_completion=False, pretty_exceptions_enable=False, rich_markup_mode=None)


class _LazyCommands(Mapping):
    """name -> click command, importing a command's module the first time it is asked."""

    def __init__(self) -> None:
        self._loaded: dict = {}

    def __getitem__(self, name: str):
        if name not in COMMANDS:
            raise KeyError(name)
        if name not in self._loaded:
            module = importlib.import_module(f"{__package__}.{COMMANDS[name][0]}")
            self._loaded.update(typer.main.get_group(module.app).commands)
        return self._loaded[name]

    def __iter__(self):
        return iter(COMMANDS)

    def __len__(self) -> int:
        return len(COMMANDS)


class LazyGroup(TyperGroup):
    """A typer group whose commands are imported only when one is run or asked for help."""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.commands = _LazyCommands()

    def list_commands(self, ctx) -> list[str]:
        return list(COMMANDS)

    def format_commands(self, ctx, formatter) -> None:
        with formatter.section("Commands"):
            formatter.write_dl([(name, help_) for name, (_, help_) in COMMANDS.items()])

    def invoke(self, ctx):
        # typer turns a KeyboardInterrupt into a silent exit code 130 and drops it: carry it
        # past typer, with what the command says about resuming
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt as exc:
            raise _Interruption(exc) from None


class _Interruption(Exception):
    """A Ctrl-C on its way through typer (``interrupt``: the KeyboardInterrupt)."""

    def __init__(self, interrupt: BaseException) -> None:
        super().__init__()
        self.interrupt = interrupt


app = typer.Typer(
    cls=LazyGroup,
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    help="Rolling-bearing mechanics, vibration and diagnostics from published "
    "methods. Run 'bearinglab COMMAND --help' for a command's options.",
)


class _LazyConsole:
    """The rich console of stdout, made on first use (rich's import is not free)."""

    _console = None

    def __getattr__(self, name):
        if _LazyConsole._console is None:
            from rich.console import Console

            _LazyConsole._console = Console()
        return getattr(_LazyConsole._console, name)


console = _LazyConsole()


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
def _main(
    version: bool = typer.Option(
        False, "--version", callback=_version, is_eager=True, help="Show the version and exit."
    ),
):
    """Rolling-bearing mechanics, vibration and diagnostics from published methods."""


def main(argv: list[str] | None = None) -> int:
    """Entry point: run the app; user errors become one line on stderr and exit code 2.

    With no arguments it prints the help (stdout, exit code 0).  An unexpected failure is
    one line on stderr and exit code 1 (``BEARINGLAB_DEBUG=1`` shows the traceback). A
    Ctrl-C is one line (``interrupted``, and how to resume a run that can) and exit code
    130, whatever it interrupted (:mod:`bearinglab.engine.interrupt`)."""
    from ..engine.interrupt import EXIT_CODE, catch_interrupts, interrupted

    args = list(sys.argv[1:] if argv is None else argv)
    if not args:
        args = ["--help"]
    _told[0] = False
    level = logging.root.manager.disable
    with catch_interrupts():
        try:
            code = _run(args)
        except KeyboardInterrupt as exc:
            code = _interrupted(exc)
        # typer's own exit code 130 (a Ctrl-C while parsing), or a Ctrl-C that a library
        # swallowed and went on
        if (code == EXIT_CODE or interrupted()) and not _told[0]:
            code = _interrupted(None)
    logging.disable(level)
    return code


_told = [False]


def _interrupted(exc: BaseException | None) -> int:
    """One line for a Ctrl-C; nothing is logged after it (a cluster being torn down)."""
    from ..engine.interrupt import EXIT_CODE

    if not _told[0]:
        resume = getattr(exc, "resume", None)
        sys.stderr.write("interrupted" + (f": {resume}" if resume else "") + "\n")
        sys.stderr.flush()
        _told[0] = True
    logging.disable(logging.CRITICAL)
    return EXIT_CODE


def _run(args: list[str]) -> int:
    from ..engine.interrupt import interrupted

    refused = replaced(args)
    if refused is not None:
        sys.stderr.write(refused + "\n")
        return 2
    try:
        result = app(args=args, standalone_mode=False)
    except _Interruption as exc:
        return _interrupted(exc.interrupt)
    except typer.Exit as exc:
        return exc.exit_code
    except typer.Abort as exc:
        if interrupted(exc):
            return _interrupted(exc)
        sys.stderr.write("aborted\n")
        return 1
    except BearinglabError as exc:
        if interrupted(exc):
            return _interrupted(exc)
        from ._words import in_flags  # an input the library names in `backquotes`: a flag

        text = in_flags(str(exc), {})
        if "--json" in args:  # machines get the error's fields on stdout as well
            import json

            fields = exc.to_dict() if hasattr(exc, "to_dict") else {}
            kind = next(k for k in type(exc).__mro__ if k.__module__ == "bearinglab.errors")
            fields = {**fields, "message": text, "kind": kind.__name__}
            print(json.dumps({"error": fields}))
        sys.stderr.write(f"error: {text}\n")
        return 2
    except typer.TyperException as exc:  # usage errors: unknown option, bad type, missing
        text = exc.format_message() if hasattr(exc, "format_message") else str(exc)
        sys.stderr.write("error: " + " ".join(text.split()) + "\n")
        return 2
    except Exception as exc:  # a bug: say so in one line rather than a traceback
        if interrupted(exc):  # numba's SystemError around a KeyboardInterrupt, ...
            return _interrupted(exc)
        if os.environ.get("BEARINGLAB_DEBUG"):
            raise
        text = " ".join(str(exc).split())
        sys.stderr.write(
            f"error: internal error ({type(exc).__name__}: {text}); please report "
            "it with the command line (BEARINGLAB_DEBUG=1 shows the traceback)\n"
        )
        return 1
    return result if isinstance(result, int) else 0
