"""Shared command-line inputs: the options most commands share, their checks and limits,
the one-line option errors (:class:`OptionError`, :func:`option_error`) and output paths.
The geometry options and the bearing they describe are in :mod:`._geometry`."""

import functools
import inspect
import os
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import BearinglabError, CatalogError, InputError, markup
from ._app import console
from ._words import _SHOWN, flag, in_flags

JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON object instead of tables.")]
SchedulerOpt = Annotated[
    str | None,
    typer.Option(
        "--scheduler",
        help="tcp://HOST:PORT of a running dask scheduler (default: "
        "$DASK_SCHEDULER_ADDRESS, else a LocalCluster of this machine's cores); 'serial' runs in "
        "this process.",
    ),
]
WorkersOpt = Annotated[
    int | None,
    typer.Option(
        "--workers",
        help="Worker processes of the LocalCluster (default: the cores).",
    ),
]


def plot_option(what: str = "the result"):
    """The --plot option of a command that draws ``what``."""
    return Annotated[
        Path | None,
        typer.Option("--plot", help=f"Also draw {what} to this .png, .svg or .pdf file."),
    ]


PlotOpt = plot_option()

#: Python type of an option of each input kind.
_TYPES = {
    "number": float | None,
    "integer": int | None,
    "text": str | None,
    "texts": list[str] | None,
    "bool": bool,
    "path": Path | None,
}


def _parameter(name: str, spec, *, argument: bool, default, help_: str) -> inspect.Parameter:
    kind = _TYPES[spec.kind]
    if argument:
        info = typer.Argument(help=help_, show_default=False)
    else:
        # a one-letter alias is a short flag (-o); a boolean has its negation (--no-film)
        flags = [flag(n) if len(n) > 1 else f"-{n}" for n in (name, *spec.aliases)]
        if spec.kind == "bool":
            flags = [f"{f}/--no-{f[2:]}" if f.startswith("--") else f for f in flags]
        shown = default is not None and spec.kind != "bool"
        choices = "[" + "|".join(spec.choices) + "]" if spec.choices else None
        info = typer.Option(*flags, help=help_, show_default=shown, metavar=choices)
    if spec.kind == "bool":
        default = bool(default)
    return inspect.Parameter(
        name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=Annotated[kind, info]
    )


def takes(
    *names: str,
    argument: str | None = None,
    defaults=None,
    helps=None,
    files: dict | None = None,
    **specs,
):
    """Give a command the inputs ``names`` of :data:`bearinglab.inputs.INPUTS` (and
    ``specs``: name -> Input, the command's own reading of a name) as options
    (``argument``: the one given as a positional argument; ``defaults`` and ``helps``: this
    command's own), and the ``files`` it writes (name -> Input, a path). The command
    receives the inputs as ``values`` (name -> value as typed) and each file as a keyword;
    a library error naming one of the command's parameters is worded as its flag."""
    from ..inputs import BEARING, INPUTS, check

    defaults, helps, files = defaults or {}, helps or {}, files or {}
    names = tuple(dict.fromkeys((*names, *specs)))
    table = {**INPUTS, **specs}

    def decorate(func):
        sig = inspect.signature(func)
        own = [
            p.replace(kind=inspect.Parameter.KEYWORD_ONLY)
            for p in sig.parameters.values()
            if p.name != "values" and p.name not in files
        ]
        every = [*names, *files, *(p.name for p in own)]
        shown = {n: n.upper() if n == argument else flag(n) for n in every}
        shown["json_output"] = "--json"
        made = {
            name: _parameter(
                name,
                table[name],
                argument=name == argument,
                default=defaults.get(name, table[name].default),
                help_=in_flags(helps.get(name, table[name].help), shown),
            )
            for name in names
        }
        written = [
            _parameter(n, spec, argument=False, default=None, help_=in_flags(spec.help, shown))
            for n, spec in files.items()
        ]
        first = [made[n] for n in names if n not in BEARING or n == argument]
        params = first + written + own + [made[n] for n in names if n in BEARING and n != argument]

        @functools.wraps(func)
        def wrapper(**kwargs):
            _GIVEN.clear()
            _GIVEN.update(typed(kwargs.pop("ctx")))
            values = {name: kwargs.pop(name) for name in names}
            _SHOWN.clear()
            _SHOWN.update(shown)
            try:
                check(values, {name: table[name] for name in names})  # in their units
                return (
                    func(values=values, **kwargs)
                    if "values" in sig.parameters
                    else func(**values, **kwargs)
                )
            except InputError as exc:
                raise worded(exc, shown) from None
            except (CatalogError, BearinglabError) as exc:
                if type(exc) not in (CatalogError, BearinglabError):
                    raise
                raise type(exc)(in_flags(str(exc), shown)) from None

        # typer hands the click context to a parameter annotated typer.Context: which
        # options the user typed (given())
        context = inspect.Parameter("ctx", inspect.Parameter.KEYWORD_ONLY, annotation=typer.Context)
        params = [context, *params]
        wrapper.__signature__ = sig.replace(parameters=params)
        wrapper.__annotations__ = {p.name: p.annotation for p in params}
        del wrapper.__wrapped__
        return wrapper

    return decorate


def worded(exc: InputError, shown: dict) -> InputError:
    """A library error in the command line's terms, in one place: the input it names first
    (``radial_load_n``, ``geometry ball_diameter_mm``) as the command's flag, its value as
    typed, and the inputs its texts name (in backquotes) as flags; the input's public
    name stays in the error's fields (``--json``)."""
    if isinstance(exc, OptionError):
        return exc
    head, space, rest = exc.parameter.partition(" ")
    option = shown[head] + space + rest if head in shown else exc.parameter
    names = lambda name: shown.get(name, flag(name))  # noqa: E731
    error = OptionError(option, exc.value, markup(exc.allowed, names), markup(exc.hint, names))
    error.input, error.unit = exc.parameter, exc.unit
    return error


#: The inputs the user typed on the command line running (not left at their defaults).
_GIVEN: set[str] = set()


def given() -> set[str]:
    """The inputs the user typed for the command running (for "no effect" warnings)."""
    return set(_GIVEN)


def typed(ctx: typer.Context) -> set[str]:
    """The parameters of the command that the user typed (not left at their defaults)."""
    # by name: typer vendors its own copy of click's ParameterSource
    sources = {p.name: ctx.get_parameter_source(p.name) for p in ctx.command.params}
    return {name for name, s in sources.items() if getattr(s, "name", None) == "COMMANDLINE"}


def _show(value) -> str:
    """A value as the user would type it: 90 rather than 90.0, strings quoted."""
    if isinstance(value, bool) or value is None:
        return repr(value)
    if isinstance(value, float):
        return f"{value:.10g}"
    if isinstance(value, (int, str)):
        return repr(value) if isinstance(value, str) else str(value)
    if isinstance(value, Path):
        return repr(str(value))
    if isinstance(value, list) and all(isinstance(v, str) for v in value):
        return " ".join(_show(v) for v in value)  # a repeatable option: its values as typed
    return repr(value)


class OptionError(InputError):
    """An :class:`InputError` worded for the command line: the option as typed, its value
    in the option's units; ``input`` is the input's public name (the option's, if it is
    not an input)."""

    def __init__(self, parameter: str, value, allowed: str, hint: str = "") -> None:
        super().__init__(parameter, value, allowed, hint)
        self.input = parameter.lstrip("-").replace("-", "_").partition(" ")[0]
        message = (
            f"{parameter} is not given: expected {allowed}"
            if value is None
            else f"{parameter} = {_show(value)} is not allowed: expected {allowed}"
        )
        self.args = (message + (f" ({hint})" if hint else ""),)

    @property
    def message(self) -> str:
        return self.args[0] if self.args else super().message

    def to_dict(self) -> dict:
        """The error's fields: the input's public name, the option as typed, and the rest."""
        return {**super().to_dict(), "input": self.input, "option": self.parameter}


def _print_warnings(warnings: list[str]) -> None:
    for text in warnings:
        console.print(f"[yellow]warning:[/yellow] {escape(in_flags(text))}")


@contextmanager
def writing(flag: str, path: Path):
    """Write ``path``, the value of ``flag``, inside the block: an OSError, or the writer's
    InputError refusing the path (its suffix, its directory), is a one-line error naming
    ``flag``."""
    try:
        yield
    except OSError as exc:
        raise OptionError(
            flag, str(path), "a writable file", exc.strerror or type(exc).__name__
        ) from None
    except InputError as exc:
        raise OptionError(flag, str(path), exc.allowed) from None


def save_plot_figure(fig, path: Path, flag: str = "--plot") -> None:
    """Save a composed figure atomically (bearinglab.plotting.save_figure); an unwritable
    path is a one-line error naming ``flag``."""
    from ..plotting import save_figure

    with writing(flag, path):
        save_figure(fig, path)


def check_path(name: str, path: Path | None, suffixes: tuple[str, ...] = ()) -> None:
    """Refuse an output path with an unknown suffix (any with no ``suffixes``) or in a
    missing directory, before any work; ``name`` is the input (or a flag as typed)."""
    if path is None:
        return
    error = OptionError if name.startswith("-") else InputError
    if suffixes and path.suffix.lower() not in suffixes:
        raise error(name, str(path), f"a file name ending in {', '.join(suffixes)}")
    if not path.parent.is_dir():
        raise error(name, str(path), "a path in an existing directory")
    if not os.access(path.parent, os.W_OK) or (path.exists() and not os.access(path, os.W_OK)):
        raise error(name, str(path), "a writable file", "permission denied")
