"""Writing result files without ever leaving a half-written one."""

from __future__ import annotations

import os
import uuid
from collections.abc import Callable
from pathlib import Path


def write_atomically(path: str | Path, write: Callable[[str], None]) -> Path:
    """Call ``write(tmp)`` on a temporary file beside ``path``, then rename it to ``path``.

    A failure (in ``write`` or the rename) or a Ctrl-C leaves no file behind (neither
    ``path`` half written nor the temporary file) and re-raises.

    Parameters
    ----------
    path : str or Path
        Destination; its directory must exist.
    write : callable
        Writes the content to the file name it is given.
    """
    path = Path(path)
    # the name is chosen before the file exists, so that a Ctrl-C at any moment after its
    # creation (even inside the call that creates it) finds it in the cleanup below
    tmp = path.with_name(f".{path.stem}-{uuid.uuid4().hex[:8]}{path.suffix}")
    try:
        os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))  # umask applies
        write(str(tmp))
        os.replace(tmp, path)
    finally:  # a failure or a Ctrl-C (KeyboardInterrupt) in write: no file left behind
        if os.path.exists(tmp):
            os.unlink(tmp)
    return path


def write_text_atomically(path: str | Path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` by :func:`write_atomically`.

    Parameters
    ----------
    path : str or Path
        Destination; its directory must exist.
    text : str
        The content.
    """
    return write_atomically(path, lambda tmp: Path(tmp).write_text(text, encoding="utf-8"))
