"""Checks of a long command's request made before any work starts (``study``, ``dataset``,
``benchmark``, ``trend``): each output path can be written (a probe file is created in
its folder and removed), a figure can be drawn (matplotlib imports), the scheduler
answers as a dask scheduler. Each failure is one :class:`OptionError` naming the option."""

from pathlib import Path

from ..errors import InputError
from ._inputs import OptionError, check_path


def output_file(
    flag: str, path: Path | None, suffixes: tuple[str, ...], *, figure: bool = False
) -> None:
    """Refuse an output file (``flag``'s value) with an unknown suffix, in a missing or
    unwritable folder, or a figure (``figure``) without matplotlib; None (not given)
    passes."""
    if path is None:
        return
    check_path(flag, path, suffixes)
    output_folder(flag, path.parent, shown=path)
    if figure:
        import importlib.util

        if importlib.util.find_spec("matplotlib") is None:
            raise OptionError(
                flag,
                str(path),
                "matplotlib installed to draw it (a dependency of bearinglab)",
                "pip install matplotlib",
            )


def output_folder(flag: str, folder: Path, shown: Path | None = None) -> None:
    """Refuse a folder (made if missing) where no file can be written; the error shows
    ``shown`` (the value typed) when given."""
    from ..study.cases import check_writable

    try:
        check_writable(flag, folder)
    except InputError as exc:
        raise OptionError(flag, str(shown or folder), exc.allowed, exc.hint) from None


def scheduler(value: str | None, *, environment: bool = True) -> None:
    """Refuse a scheduler address where no dask scheduler answers (within
    :data:`bearinglab.engine.CONNECT_TIMEOUT` seconds), before any work: the
    address given, else (``environment``) $DASK_SCHEDULER_ADDRESS."""
    from ..engine import ENV_ADDRESS, check_scheduler, scheduler_of

    where = scheduler_of(value) if environment else value
    if where is None or where in ("serial", "local"):
        return
    try:
        check_scheduler(str(where))
    except InputError as exc:
        flag = "--scheduler" if value is not None else f"${ENV_ADDRESS}"
        raise OptionError(flag, exc.value, exc.allowed, exc.hint) from None
