"""Shared command-line inputs: the options most commands share, their checks and limits,
the one-line option errors (:class:`OptionError`, :func:`option_error`) and output paths.
The geometry options and the bearing they describe are in :mod:`._geometry`."""

import math
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import InputError
from ._app import console

#: Limits of the analysis options, in their units.
MAX_BALL_LOAD_N = 1e7
MAX_SPEED_RPM = 1e6
MAX_LOAD_N = 1e7
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON object instead of tables.")]
#: The options most commands share (each command gives its own default).
RingSpeedOpt = Annotated[
    float, typer.Option("--speed-rpm", help="Speed of the rotating ring [rpm].")
]
ShaftSpeedOpt = Annotated[
    float, typer.Option("--speed-rpm", help="Shaft (inner-ring) speed [rpm].")
]
RadialLoadOpt = Annotated[
    float, typer.Option("--radial-load-n", help="Radial load F_r on the shaft, downwards [N].")
]
AxialLoadOpt = Annotated[
    float, typer.Option("--axial-load-n", help="Axial load F_a on the inner ring [N].")
]
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
DesignationArg = Annotated[
    str | None,
    typer.Argument(
        help="Bearing designation or catalogue name; optional with explicit geometry.",
    ),
]


def speed_rad_s(speed_rpm: float, *, zero: bool = False) -> float:
    """Speed [rad/s] from --speed-rpm, which must lie in (0, MAX_SPEED_RPM] rpm ([0, ...]
    with ``zero``)."""
    in_range("--speed-rpm", speed_rpm, 0.0, MAX_SPEED_RPM, "a speed", low_open=not zero)
    return speed_rpm * math.pi / 30


def in_range(
    flag: str,
    value: float | None,
    low: float,
    high: float,
    what: str,
    *,
    low_open: bool = False,
    hint: str = "",
) -> float | None:
    """An option's value checked against [low, high] ((low, high] with ``low_open``), in the
    option's unit (its suffix); None (not given) passes."""
    if value is None:
        return None
    if not (math.isfinite(value) and (low < value if low_open else low <= value) and value <= high):
        from ..units import unit_of

        unit = unit_of(flag)
        symbol = f" {unit.symbol}" if unit is not None else ""
        interval = f"{'(' if low_open else '['}{low:g}, {high:g}]{symbol}"
        raise OptionError(flag, value, f"{what} in {interval}", hint)
    return float(value)


def load_n(flag: str, value: float | None, signed: bool = False) -> float | None:
    """A load option [N] in [0, MAX_LOAD_N] ([-MAX_LOAD_N, MAX_LOAD_N] when ``signed``);
    None (not given) passes."""
    return in_range(flag, value, -MAX_LOAD_N if signed else 0.0, MAX_LOAD_N, "a load")


def check_loads(radial: float, axial: float, unloaded: str | None = None) -> None:
    """--radial-load-n in [0, max], --axial-load-n signed; with ``unloaded`` (the reason
    a load is needed) at least one of them nonzero."""
    load_n("--radial-load-n", radial)
    load_n("--axial-load-n", axial, signed=True)
    if unloaded and radial == 0 and axial == 0:
        raise OptionError(
            "--radial-load-n", radial, "a load > 0 N (or an --axial-load-n)", unloaded
        )


def no_effect(flags, why: str) -> list[str]:
    """A warning naming the options given (``flags``: (flag, given) pairs) that have no
    effect ``why``; none when none was given."""
    given = [flag for flag, on in flags if on]
    return [f"{' and '.join(given)}: no effect {why}"] if given else []


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
    return repr(value)


class OptionError(InputError):
    """An :class:`InputError` worded for the command line: the option as typed, its value
    in the option's units."""

    def __init__(self, parameter: str, value, allowed: str, hint: str = "") -> None:
        super().__init__(parameter, value, allowed, hint)
        message = (
            f"{parameter} is not given: expected {allowed}"
            if value is None
            else f"{parameter} = {_show(value)} is not allowed: expected {allowed}"
        )
        self.args = (message + (f" ({hint})" if hint else ""),)


def _print_warnings(warnings: list[str]) -> None:
    for text in warnings:
        console.print(f"[yellow]warning:[/yellow] {escape(text)}")


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


def number_list(
    flag: str, text: str | None, allowed: str, *, counts: tuple = (), zero: bool = False
) -> list[float] | None:
    """A comma-separated option A,B,C as finite numbers, each > 0 (>= 0 with ``zero``) and
    as many as one of ``counts`` (any number without); None (not given) passes."""
    if text is None:
        return None
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    counted = bool(values) and (not counts or len(values) in counts)
    if not (counted and all(math.isfinite(v) and (v >= 0 if zero else v > 0) for v in values)):
        raise OptionError(flag, text, allowed)
    return values


def positive(flag: str, value, allowed: str, zero: bool = False):
    if value is not None and not (math.isfinite(value) and (value >= 0 if zero else value > 0)):
        raise OptionError(flag, value, allowed)
    return value


def check_path(flag: str, path: Path | None, suffixes: tuple[str, ...]) -> None:
    """Refuse an output path with an unknown suffix or in a missing directory, before
    any simulating."""
    if path is None:
        return
    if path.suffix.lower() not in suffixes:
        raise OptionError(flag, str(path), f"a file name ending in {', '.join(suffixes)}")
    if not path.parent.is_dir():
        raise OptionError(flag, str(path), "a path in an existing directory")


#: library parameter -> the option's quantity name where the two differ
_PARAMETER_OPTIONS = {"shaft_speed": "speed"}


def option_error(exc: InputError, options: dict) -> InputError:
    """A library error in the command line's terms: the option that holds the parameter.

    ``options`` maps a command's option names (``ring_mass_kg``, with the unit suffix of
    :data:`bearinglab.units.UNITS`) to the values typed. The option whose name, less its
    unit suffix, is the error's parameter is named, with the value as typed (or the
    error's SI value in the option's unit). Errors of other parameters are returned as
    they are."""
    from ..units import unit_of

    if isinstance(exc, OptionError):
        return exc
    parameter = _PARAMETER_OPTIONS.get(exc.parameter, exc.parameter)
    for name, typed in options.items():
        unit = unit_of(name)
        base = name[: -len(unit.suffix) - 1] if unit is not None else name
        if base != parameter:
            continue
        value = typed
        if value is None and isinstance(exc.value, (int, float)) and unit is not None:
            value = unit.from_si(exc.value)
        return OptionError("--" + name.replace("_", "-"), value, exc.allowed, exc.hint)
    return exc
